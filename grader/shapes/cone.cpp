// Cone: reading, reference intersection, the quadratic derivation and the sketch.
#include "shapes/cone.h"

#include <cmath>

#include "generate/draft.h"
#include "generate/solids.h"
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

// The cone's normal at a point: (h·ê + r·â)/√(h² + r²) on the side, ê across the axis towards
// P; at the apex, where ê is undefined, â; −â on the base cap. On the rim the side's normal, as
// the cone's hits there have (docs/problem-format.md).

SurfacePoint Cone::nearest_surface(const Vec3d& p, double tie) const {
  Vec3d e = unit_across(p, base_, axis_);
  Vec3d apex = base_ + height_ * axis_;
  Vec3d on_side = nearest_on_segment(p, base_ + radius_ * e, apex);
  SurfacePoint side{on_side, height_ * e + radius_ * axis_, "side", ""};
  if (length(on_side - apex) <= tie) side = SurfacePoint{apex, axis_, "apex", ""};
  if (!capped_) return side;
  Vec3d q = p - base_;
  Vec3d radial = q - dot(q, axis_) * axis_;
  Vec3d on_cap = base_ + (length(radial) <= radius_ ? radial : radius_ * e);
  // The cap only where it is nearer than the side by more than `tie`: the rim is the side's.
  if (length(on_cap - p) + tie < length(side.nearest - p)) {
    return SurfacePoint{on_cap, -axis_, "base cap", ""};
  }
  return side;
}

void Cone::derive_normal(Deriver& d, const E& P, const SurfacePoint& s,
                         const NormalNames& n) const {
  E B = d.given("B", "B", base_, "the centre of the base");
  E a = d.given("a_hat", "â", axis_, "the unit axis");
  if (s.part == "side") {
    E h = d.given("h", "h", height_, "the height");
    E r = d.given("r", "r", radius_, "the radius of the base");
    d.step("q", "q", P - B);
    d.step("s", "s", dot(d.sym("q"), a), "the height of P along the axis");
    d.step("radial", "q_⊥", d.sym("q") - d.sym("s") * a, "the part of q across the axis");
    d.step("e_hat", "ê", d.sym("radial") / norm(d.sym("radial")),
           "the unit vector across the axis towards P");
    d.step("m", "m", h * d.sym("e_hat") + r * a,
           "h·ê + r·â: across the slanted side, pointing out");
    d.step(n.name, n.display, d.sym("m") / norm(d.sym("m")),
           "the outward unit normal of the side: (h·ê + r·â)/√(h² + r²)");
  } else if (s.part == "apex") {
    d.step(n.name, n.display, a,
           "P is the apex, where ê is undefined: by the cone's convention the normal is â");
  } else {
    d.step(n.name, n.display, -a, "P is on the base cap: the normal is −â, pointing out");
  }
}

// The cone's generator: a cone along an axis whose radius at every whole height is whole, so
// that its side holds lattice points; the answer is built first from those points (and the
// cap's) and the ray backwards from it.

namespace {

// A point of the cone's surface as the construction knows it: its offset from the base centre
// across the axis, its height above the base, and whether it is on the cap.
struct ConePoint {
  Vec3d across;
  int height = 0;
  bool cap = false;
  Vec3d at(const Vec3d& base) const { return base + across + Vec3d{0, 0, double(height)}; }
};

}  // namespace

// Every outcome; the ray starts inside a capped cone only (the open one encloses nothing).
const std::vector<Outcome>& Cone::outcomes() { return kSolidOutcomes; }

Draft Cone::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kSolidOutcomes);
  AxisMap map = random_axis_map(rng);
  // radius : height is 1 : 1, 2 : 1 or 1 : 2, so the radius at height s, r (h − s) / h, is
  // whole wherever the side's lattice points are taken.
  static const std::vector<std::pair<int, int>> kRatios = {{1, 1}, {2, 1}, {1, 2}};
  auto [rn, hn] = rng.pick(kRatios);
  int k = rng.range(2, 5);
  int r = rn * k, h = hn * k;
  Vec3d base = random_point(rng, 3);
  bool capped = o == Outcome::kInside || rng.below(2);
  // Built around the z axis, then turned by `map`. The side's points strictly between the cap
  // and the apex, and (when capped) the cap's points strictly inside its rim.
  std::vector<ConePoint> side, pool;
  for (int s = 1; s < h; ++s) {
    if ((rn * (h - s)) % hn != 0) continue;
    for (const auto& p : lattice_circle(rn * (h - s) / hn)) side.push_back({p, s, false});
  }
  pool = side;
  if (capped) {
    for (int x = -r + 1; x < r; ++x) {
      for (int y = -r + 1; y < r; ++y) {
        if (x * x + y * y < r * r) pool.push_back({Vec3d{double(x), double(y), 0}, 0, true});
      }
    }
  }
  Vec3d up{0, 0, 1};
  int s = rng.range(1, 3);
  Vec3d origin, d;
  std::vector<KnownHit> hits;
  if (o == Outcome::kTangent || o == Outcome::kMiss) {
    // Across the axis, tangent to the circle of the cone at that height: the line keeps its
    // height and touches the side at one point (a double root).
    ConePoint p = rng.pick(side);
    d = reduced(Vec3d{-p.across.y, p.across.x, 0});
    origin = p.at(base) - s * d;
    if (o == Outcome::kMiss)
      origin = origin + p.across;  // twice as far from the axis as the side at that height
    else
      hits.push_back({double(s), p.at(base)});
  } else {
    // A chord between two points of the surface: the cone with its cap is convex, so the line
    // meets its surface there and nowhere else, unless both lie on one line of the surface (one
    // generator of the side, or both on the cap).
    ConePoint a, b;
    int steps = 1;
    while (true) {
      a = rng.pick(pool);
      b = rng.pick(pool);
      if (a.cap && b.cap) continue;
      bool same_generator = !a.cap && !b.cap && length_squared(cross(a.across, b.across)) == 0 &&
                            dot(a.across, b.across) > 0;
      if (same_generator || (a.across == b.across && a.height == b.height)) continue;
      steps = static_cast<int>(component_gcd(b.at(base) - a.at(base)));
      if (o == Outcome::kInside && steps < 2) continue;
      break;
    }
    d = reduced(b.at(base) - a.at(base));
    Vec3d p0 = a.at(base), p1 = b.at(base);
    chord_ray(rng, o, p0, p1, d, steps, s, origin, hits);
  }
  nlohmann::ordered_json object = {{"type", kType}, {"base", vector_json(map(base))}};
  if (map(up) != Vec3d{0, 0, 1}) object["axis"] = vector_json(map(up));
  object["radius"] = r;
  object["height"] = h;
  if (capped) object["capped"] = true;
  std::string text = fmt::format(
      "the {} cone whose base circle of radius {} is centred at {}, with its apex at {}",
      capped ? "closed (with its base cap)" : "open", r, point_text(map(base)),
      point_text(map(base + double(h) * up)));
  for (auto& hit : hits) hit.point = map(hit.point);
  return intersect_draft(map(origin), map(d), object, text, hits);
}

}  // namespace raygrade
