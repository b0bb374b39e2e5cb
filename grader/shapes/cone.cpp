// Cone: reading, reference intersection, the quadratic derivation and the sketch.
#include "shapes/cone.h"

#include <cmath>

#include "math/robust.h"
#include "math/unit_vector.h"
#include "shapes/describe.h"
#include "shapes/round.h"

namespace raygrade {
namespace {

using DD = DoubleDouble;

// The side's quadratic, in double-double from the exact O − B: for whole-number data along a
// coordinate axis a, b and c are exact, so that a tangent's or the apex's double root is found
// as one (Δ = 0), not lost to rounding.
struct ConeQuadratic {
  DD a, half_b, c, fa, da;
};

ConeQuadratic cone_quadratic(const Vec3dd& f, const Vec3dd& d, const Vec3dd& axis, DD r, DD h) {
  DD fa = dot(f, axis), da = dot(d, axis);
  Vec3dd fp = f - fa * axis, dp = d - da * axis;
  DD w = h - fa, hh = h * h, rr = r * r;
  return {hh * dot(dp, dp) - rr * (da * da), hh * dot(fp, dp) + rr * (w * da),
          hh * dot(fp, fp) - rr * (w * w), fa, da};
}

}  // namespace

Cone::Cone(Vec3d base, Vec3d axis, double radius, double height, bool capped)
    : base_(base),
      axis_given_(axis),
      axis_(normalized(axis)),
      radius_(radius),
      height_(height),
      capped_(capped) {}

std::unique_ptr<Shape> Cone::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.insert(keys.end(), {"base", "axis", "radius", "height", "capped"});
  object.allow_only(keys);
  Vec3d axis = object.has("axis") ? object.at("axis").nonzero_vec3() : Vec3d{0, 0, 1};
  return std::make_unique<Cone>(
      object.at("base").vec3(), axis, object.at("radius").positive_number(),
      object.at("height").positive_number(), object.boolean_or("capped", false));
}

nlohmann::json Cone::to_json() const {
  nlohmann::json j = {{"type", "cone"},
                      {"base", {base_.x, base_.y, base_.z}},
                      {"axis", {axis_given_.x, axis_given_.y, axis_given_.z}},
                      {"radius", radius_},
                      {"height", height_}};
  if (capped_) j["capped"] = true;
  return j;
}

Shape::NormalRule Cone::normal_rule() const {
  return {"inward-normal",
          " A cone's side has the outward normal (h·ê + r·â)/√(h² + r²), ê the unit vector across "
          "the axis towards P; at the apex it is â; the base cap's is −â."};
}

std::string Cone::contained_line() const {
  return "The ray runs along a line of the cone's side through its apex (a = b = c = 0): it "
         "meets the side along a whole segment";
}

Intersection Cone::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  Vec3dd o(ray.origin), d(ray.direction), base(base_);
  Vec3dd axis = unit_dd(Vec3dd(axis_given_));
  Vec3dd f = o - base;
  DD r(radius_), h(height_);
  ConeQuadratic k = cone_quadratic(f, d, axis, r, h);
  double scale = length(ray.origin - base_) + length(ray.direction) + radius_ + height_;
  double seam = kSeamRelative * scale;
  // Compute the side's roots
  std::vector<DD> roots;
  if (k.a == DD(0)) {
    if (k.half_b == DD(0)) {
      if (k.c == DD(0) && k.da != DD(0)) {
        // The ray's line is a line of the side: contained where 0 ≤ s ≤ h within the interval.
        double t0 = static_cast<double>(-k.fa / k.da), t1 = static_cast<double>((h - k.fa) / k.da);
        if (t1 < t0) std::swap(t0, t1);
        out.contained = t0 <= ray.t_max && t1 >= ray.t_min;
        return out;
      }
    } else {
      roots.push_back(-k.c / (DD(2) * k.half_b));
    }
  } else {
    DD disc = k.half_b * k.half_b - k.a * k.c;
    if (disc == DD(0)) {
      roots.push_back(-k.half_b / k.a);
    } else if (DD(0) < disc) {
      DD q = -(k.half_b + sign_of(k.half_b) * sqrt(disc));
      roots.push_back(k.c / q);
      roots.push_back(q / k.a);
    }
  }
  for (const DD& t_dd : roots) {
    double t = static_cast<double>(t_dd);
    if (!ray.accepts(t)) continue;
    double s = static_cast<double>(k.fa + t_dd * k.da);
    if (s < -seam || s > height_ + seam) continue;
    Vec3dd v = f + t_dd * d;
    Vec3dd across = v - dot(v, axis) * axis;
    bool apex = s >= height_ - seam &&
                length(Vec3d(static_cast<double>(across.x), static_cast<double>(across.y),
                             static_cast<double>(across.z))) <= seam;
    Vec3d normal = apex ? unit_rounded(axis) : unit_rounded(unit_dd(across) * h + axis * r);
    out.hits.push_back(Hit{t, ray.at(t), normal, std::nullopt, apex ? "apex" : "side"});
  }
  // Compute the cap's hit
  if (capped_ && k.da != DD(0)) {
    double t = static_cast<double>(-k.fa / k.da);
    if (ray.accepts(t)) {
      Vec3d p = ray.at(t);
      Vec3d radial = (p - base_) - dot(p - base_, axis_) * axis_;
      if (length(radial) <= radius_ + seam) {
        out.hits.push_back(Hit{t, p, -axis_, std::nullopt, "base cap"});
      }
    }
  }
  finish_hits(out.hits, seam);
  return out;
}

Derivation Cone::derive(const Ray& ray, std::string_view /*method*/,
                        const Overrides* overrides) const {
  Deriver d("quadratic",
            capped_ ? "Cone: the side's quadratic, the height test and the base cap"
                    : "Cone: the side's quadratic, then the height test",
            overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  E B = d.given("B", "B", base_, "the centre of the base circle");
  E r = d.given("r", "r", radius_, "the base's radius");
  E h = d.given("h", "h", height_, "the height: the apex is B + h·â");
  E u = d.given("u", "â", axis_, "the unit axis, from the base to the apex");
  // The side's quadratic
  d.step("f", "f", O - B, "from the base's centre to the origin");
  d.step("fa", "f_a", dot(d.sym("f"), u), "the origin's height above the base");
  double da = d.step("da", "D_a", dot(D, u), "the direction's part along the axis").scalar;
  d.step("f_perp", "f⊥", d.sym("f") - d.sym("fa") * u, "f across the axis");
  d.step("D_perp", "D⊥", D - d.sym("da") * u, "D across the axis");
  d.step("w", "w", h - d.sym("fa"), "the origin's depth below the apex");
  double a =
      d.step("a", "a",
             square(h) * dot(d.sym("D_perp"), d.sym("D_perp")) - square(r) * square(d.sym("da")),
             "from h²|f⊥ + tD⊥|² = r²(w − t D·â)²")
          .scalar;
  double b = d.step("b", "b",
                    2 * (square(h) * dot(d.sym("f_perp"), d.sym("D_perp")) +
                         square(r) * d.sym("w") * d.sym("da")))
                 .scalar;
  double c =
      d.step("c", "c",
             square(h) * dot(d.sym("f_perp"), d.sym("f_perp")) - square(r) * square(d.sym("w")))
          .scalar;
  std::vector<Candidate> candidates;
  auto side_candidate = [&](const std::string& n, const E& root) {
    double t = d.step("t" + n, "t_" + n, root).scalar;
    Value p = d.step("P" + n, "P_" + n, O + d.sym("t" + n) * D);
    double s = d.step("s" + n, "s_" + n, d.sym("fa") + d.sym("t" + n) * d.sym("da"),
                      "its height above the base: on the cone when 0 ≤ s ≤ h")
                   .scalar;
    std::string reason = s < 0         ? "it lies below the base (s < 0)"
                         : s > height_ ? "it lies on the other nappe, above the apex (s > h)"
                                       : range_reason(ray, t);
    candidates.push_back({t, p.vector, reason});
  };
  if (a == 0 && b == 0) {
    d.note(c == 0 ? "a = b = c = 0: the ray's line lies on the cone's side, through its apex."
                  : "a = b = 0 and c ≠ 0: the ray never meets the side.");
  } else if (a == 0) {
    d.note("a = 0: the ray is parallel to a line of the side, which it crosses once.");
    side_candidate("0", -d.sym("c") / d.sym("b"));
  } else {
    double disc =
        d.step("discriminant", "Δ", square(d.sym("b")) - 4 * d.sym("a") * d.sym("c")).scalar;
    if (disc < 0) {
      d.note("Δ < 0: the ray misses the side's double cone.");
    } else if (disc == 0) {
      d.note("Δ = 0: one root, a tangent or the apex.");
      side_candidate("0", -d.sym("b") / (2 * d.sym("a")));
    } else {
      side_candidate("0", (-d.sym("b") - sqrt(d.sym("discriminant"))) / (2 * d.sym("a")));
      side_candidate("1", (-d.sym("b") + sqrt(d.sym("discriminant"))) / (2 * d.sym("a")));
    }
  }
  // The base cap
  if (capped_ && da != 0) {
    double t = d.step("t_cap", "t_cap", -d.sym("fa") / d.sym("da"), "where s = 0").scalar;
    Value p = d.step("P_cap", "P_cap", O + d.sym("t_cap") * D);
    double rho2 = d.step("rho2_cap", "|P_cap − B|²", dot(d.sym("P_cap") - B, d.sym("P_cap") - B),
                         "inside the base circle when ≤ r²")
                      .scalar;
    candidates.push_back({t, p.vector,
                          rho2 > radius_ * radius_ * (1 + kSeamRelative)
                              ? "it lies outside the base circle (|P_cap − B|² > r²)"
                              : range_reason(ray, t)});
  }
  // A rim point is found by the side and the cap: each hit once.
  conclude_candidates(d, "cone", ray, each_hit_once(std::move(candidates)), capped_);
  return std::move(d).finish();
}

void Cone::sketch(Sketch& figure, const std::string& label) const {
  // The base circle as 48 points, and lines from it to the apex every eighth of a turn (a
  // side hit within the seam tolerance of the apex takes the apex's normal).
  Vec3d apex = base_ + height_ * axis_;
  constexpr int kRimPoints = 48;
  std::vector<Vec3d> rim = circle_points(base_, axis_, radius_, kRimPoints);
  for (int i = 0; i < kRimPoints; i += kRimPoints / 8) {
    figure.path({rim[i], apex}, false, Ink::kObject);
  }
  figure.path(std::move(rim), true, Ink::kObject, label);
}

nlohmann::ordered_json Cone::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "description": "the circle of radius at base and the apex at base + height·â (â the unit axis); open, or closed by its base cap",
  "required": ["base", "radius", "height"],
  "properties": {
    "base": {"$ref": "#/$defs/vec3"},
    "axis": {"$ref": "#/$defs/nonzero_vec3", "default": [0, 0, 1]},
    "radius": {"$ref": "#/$defs/positive"},
    "height": {"$ref": "#/$defs/positive"},
    "capped": {"type": "boolean", "default": false}
  },
  "examples": [
    {"type": "cone", "base": [0, 0, 0], "radius": 1, "height": 2},
    {"type": "cone", "base": [1, 0, 3], "axis": [0, 1, 0], "radius": 2, "height": 3, "capped": true}
  ]
}
)json");
}

}  // namespace raygrade
