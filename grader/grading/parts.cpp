// The table of every kind's parts.
#include "grading/parts.h"

#include <map>

namespace raygrade {

const char* to_string(Comparison c) {
  switch (c) {
    case Comparison::kScalar: return "scalar";
    case Comparison::kPoint: return "point";
    case Comparison::kDirection: return "direction";
    case Comparison::kUnitDirection: return "unit direction";
    case Comparison::kHits: return "set of hits";
    case Comparison::kWeights: return "weights";
    case Comparison::kName: return "name";
    case Comparison::kFlag: return "flag";
    case Comparison::kNames: return "set of names";
    case Comparison::kFormula: return "formula";
    case Comparison::kTree: return "tree";
    case Comparison::kSteps: return "steps";
  }
  return "scalar";
}

namespace {

using C = Comparison;

const std::map<std::string, std::vector<PartSpec>, std::less<>>& table() {
  static const std::map<std::string, std::vector<PartSpec>, std::less<>> t = {
      {"intersect",
       {{"t", "every hit's t, in any order ([] when the ray misses)", 2, C::kHits},
        {"point", "every hit's point P = O + tD", 1, C::kPoint},
        {"normal", "the unit normal at every hit (any positive multiple)", 0, C::kDirection},
        {"barycentric", "a triangle hit's weights (w_a, w_b, w_c), or its u = w_b and v = w_c", 0,
         C::kWeights},
        {"steps", "the derivation's named steps", 0, C::kSteps}}},
      {"first-hit",
       {{"object", "the name of the object hit first (null when none is)", 2, C::kName},
        {"t", "the first hit's t", 1, C::kHits},
        {"point", "the first hit's point", 1, C::kPoint},
        {"normal", "the unit normal there", 0, C::kDirection}}},
      {"camera-ray",
       {{"ray", "the ray through the pixel: the eye and the direction (any positive multiple)", 1,
         C::kDirection},
        {"steps", "the derivation's named steps", 0, C::kSteps}}},
      {"reflect",
       {{"direction", "the reflected direction r (any positive multiple)", 1, C::kDirection},
        {"unit_direction", "r as a unit vector", 0, C::kUnitDirection}}},
      {"refract",
       {{"direction", "the refracted direction (null past the critical angle)", 1, C::kDirection},
        {"total_internal_reflection", "whether the light is totally reflected", 0, C::kFlag},
        {"angle_of_incidence", "θi in degrees", 0, C::kScalar},
        {"angle_of_refraction", "θt in degrees (none past the critical angle)", 0, C::kScalar},
        {"critical_angle", "asin(n2/n1) in degrees (only when n1 > n2)", 0, C::kScalar},
        {"reflected_direction", "the totally reflected direction (any positive multiple)", 0,
         C::kDirection}}},
      {"shade",
       {{"intensity", "the Phong intensity", 1, C::kScalar},
        {"ambient", "the ambient term k_a·I_a", 0, C::kScalar},
        {"diffuse", "the sum of the diffuse terms", 0, C::kScalar},
        {"specular", "the sum of the specular terms", 0, C::kScalar},
        {"terms", "which terms apply (ambient, diffuse, specular)", 0, C::kNames},
        {"lights", "per light: whether it reaches the point, N·L, R·V and its two terms", 0,
         C::kScalar},
        {"colour", "the material's colour at the point (a pattern's colour there), [r, g, b]", 0,
         C::kScalar}}},
      {"normal",
       {{"normal", "the outward unit normal at the point (any positive multiple)", 1,
         C::kDirection},
        {"object_normal", "a transformed object's normal in object space, before (A⁻¹)ᵀ", 0,
         C::kDirection}}},
      {"view-ray",
       {{"origin", "where the ray starts (the eye; the pixel itself when orthographic)", 1,
         C::kPoint},
        {"direction", "the ray's direction (any positive multiple)", 1, C::kDirection},
        {"unit_direction", "the direction as a unit vector", 0, C::kUnitDirection},
        {"u", "the camera's u (the image's right)", 0, C::kDirection},
        {"v", "the camera's v (the image's up)", 0, C::kDirection},
        {"w", "the camera's w (pointing back)", 0, C::kDirection},
        {"l", "the image plane's left edge", 0, C::kScalar},
        {"r", "right edge", 0, C::kScalar},
        {"b", "bottom edge", 0, C::kScalar},
        {"t", "top edge", 0, C::kScalar},
        {"pixel_width", "a pixel's width (r − l)/n_x", 0, C::kScalar},
        {"pixel_height", "a pixel's height (t − b)/n_y", 0, C::kScalar},
        {"u_s", "the pixel's position along u", 0, C::kScalar},
        {"v_s", "the pixel's position along v", 0, C::kScalar}}},
      {"fresnel",
       {{"reflectance", "the reflected share F (1 under total internal reflection)", 1, C::kScalar},
        {"transmittance", "the transmitted share 1 − F", 0, C::kScalar},
        {"total_internal_reflection", "whether the light is totally reflected", 0, C::kFlag},
        {"angle_of_incidence", "θi in degrees", 0, C::kScalar},
        {"angle_of_refraction", "θt in degrees (none past the critical angle)", 0, C::kScalar},
        {"r0", "Schlick: the reflectance at normal incidence", 0, C::kScalar},
        {"r_s", "exact: the s-polarized reflectance", 0, C::kScalar},
        {"r_p", "exact: the p-polarized reflectance", 0, C::kScalar}}},
      {"ray-tree",
       {{"hit", "ask \"hit\": the object the ray hits first and its t", 1, C::kHits},
        {"tree", "the hit points of the tree and their objects", 1, C::kTree},
        {"shadows", "which hit points are in shadow, and by what when named", 1, C::kFlag},
        {"terms", "which Phong terms apply at each hit point", 1, C::kNames},
        {"intensity", "ask \"intensity\": the intensity along the primary ray", 1, C::kScalar},
        {"media", "ask \"media\": n1 and n2 at every hit along the ray, in order", 1, C::kHits}}},
      {"derive", {{"<quantity>", "each quantity the problem names in find", 1, C::kFormula}}},
  };
  return t;
}

}  // namespace

const std::vector<PartSpec>& kind_parts(std::string_view kind) {
  static const std::vector<PartSpec> none;
  auto it = table().find(kind);
  return it == table().end() ? none : it->second;
}

const PartSpec* find_part(std::string_view kind, std::string_view name) {
  for (const auto& p : kind_parts(kind)) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

std::vector<std::pair<std::string, double>> default_points(std::string_view kind,
                                                           const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& n : names) {
    const PartSpec* p = find_part(kind, n);
    out.emplace_back(n, p ? p->points : 0);
  }
  return out;
}

}  // namespace raygrade
