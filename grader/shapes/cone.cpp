// Cone: reading, reference intersection, the quadratic derivation and the sketch.
#include "shapes/cone.h"

#include <cmath>

#include "math/robust.h"
#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/solids.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"
#include "shapes/huge_coordinates.h"
#include "shapes/round.h"

namespace raygrade {
namespace {

using DD = DoubleDouble;

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

Intersection Cone::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  // The side's quadratic (cone_side, the study's template) in double-double from the exact
  // O − A: for whole-number data along a coordinate axis a, b, c and Δ' are exact, so that a
  // tangent's or the apex's double root is found as one (Δ' = 0), not lost to rounding. A
  // point's part is decided by its height in double-double, with a seam relative to the cone's
  // own size (not to a far origin's).
  double seam = kSeamRelative * (radius_ + height_);
  Vec3dd o(ray.origin), d(ray.direction), base(base_);
  DD r(radius_);
  Vec3dd apex = apex_ ? Vec3dd(*apex_) : base + DD(height_) * unit_dd(Vec3dd(axis_given_));
  Vec3dd v = apex - base, axis = unit_dd(v);
  DD h = apex_ ? sqrt(dot(v, v)) : DD(height_);
  ConeSide<DD> k = cone_side(o, d, apex, v, r);
  bool contained = false;
  Roots<DD> roots = cone_side_roots(k, contained);
  if (contained && k.alpha != DD(0)) {
    // The ray's line is a line of the side: contained where −v·v ≤ γ + tα ≤ 0 within the
    // interval.
    double t0 = static_cast<double>((-k.vv - k.gamma) / k.alpha),
           t1 = static_cast<double>(-k.gamma / k.alpha);
    if (t1 < t0) std::swap(t0, t1);
    out.contained = t0 <= ray.t_max && t1 >= ray.t_min;
    return out;
  }
  DD ts[2] = {roots.t0, roots.t1};
  for (int i = 0; i < roots.count; ++i) {
    double t = static_cast<double>(ts[i]);
    if (!ray.accepts(t)) continue;
    // The height above the base: h + (γ + tα)/h.
    double s = static_cast<double>(h + (k.gamma + ts[i] * k.alpha) / h);
    if (s < -seam || s > height_ + seam) continue;
    Vec3dd g = k.g + ts[i] * d;
    Vec3dd across = g - dot(g, axis) * axis;
    bool at_apex = s >= height_ - seam && static_cast<double>(sqrt(dot(across, across))) <= seam;
    Vec3d normal = at_apex ? unit_rounded(axis) : unit_rounded(unit_dd(across) * h + axis * r);
    out.hits.push_back(Hit{t, ray.at(t), normal, std::nullopt, at_apex ? "apex" : "side"});
  }
  // Compute the cap's hit: where γ + tα = −v·v, within the base circle.
  if (capped_ && k.alpha != DD(0)) {
    DD t_dd = (-k.vv - k.gamma) / k.alpha;
    double t = static_cast<double>(t_dd);
    if (ray.accepts(t)) {
      Vec3dd g = k.g + t_dd * d;
      Vec3dd radial = g - dot(g, axis) * axis;
      if (static_cast<double>(sqrt(dot(radial, radial))) <= radius_ + seam) {
        out.hits.push_back(Hit{t, ray.at(t), -axis_, std::nullopt, "base cap"});
      }
    }
  }
  finish_hits(out.hits, seam);
  return out;
}

// The accuracy study's cases of cones.

bool Cone::Ladder::case_of(const Cone& cone, std::vector<Vec3d>& points, double& radius) {
  if (cone.capped_) return false;
  if (cone.apex_) {
    points = {cone.base_, *cone.apex_};
    radius = cone.radius_;
    return true;
  }
  Vec3d apex = cone.base_ + cone.height_ * cone.axis_;
  // apex − B must be h·â exactly as intersect takes it (in double-double), and the case must
  // give back the same cone.
  Vec3dd v = Vec3dd(apex) - Vec3dd(cone.base_);
  Vec3dd hv = DD(cone.height_) * unit_dd(Vec3dd(cone.axis_given_));
  for (int i = 0; i < 3; ++i) {
    if (!(v[i] == hv[i])) return false;
  }
  std::unique_ptr<Shape> back = shape_of({cone.base_, apex}, cone.radius_);
  const auto& same = static_cast<const Cone&>(*back);
  if (!(same.base_ == cone.base_ && same.axis_ == cone.axis_ && same.height_ == cone.height_ &&
        same.radius_ == cone.radius_ && !same.capped_)) {
    return false;
  }
  points = {cone.base_, apex};
  radius = cone.radius_;
  return true;
}

void Cone::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius) {
  Vec3d base = rng.point(0.5);
  double height = rng.uniform(0.5, 1.5);
  points = {base, base + height * rng.unit_vector()};
  radius = rng.uniform(0.2, 0.8);
}

void Cone::Ladder::hard_cases(int round, SplitMix& /*shared*/, std::vector<AccuracyCase>& out) {
  if (round != kOwnStreamRound) return;
  SplitMix rng(20261126);
  auto add = [&](std::string id, std::string group, Vec3d o, Vec3d d, Vec3d base, Vec3d apex,
                 double r) {
    out.push_back(
        make_case(std::move(id), std::move(group), primitive_of<Cone>(), o, d, {base, apex}, r));
  };
  // A random cone: the base near the origin, the unit axis, the height and the radius.
  struct Random {
    Vec3d base, axis, apex, u, w;  // u across the axis, w across both
    double h = 0, r = 0;
  };
  auto cone = [&] {
    Random c;
    c.base = rng.point(1);
    c.axis = rng.unit_vector();
    c.h = rng.uniform(0.5, 3);
    c.r = rng.uniform(0.3, 1.5);
    c.apex = c.base + c.h * c.axis;
    c.u = perpendicular(c.axis, rng);
    c.w = cross(c.axis, c.u);
    return c;
  };
  // The ray from `distance` away, coming from the side of `outward`, aimed at `target`.
  auto ray_to = [&](Vec3d target, Vec3d outward, double distance) {
    Vec3d o = target + distance * normalized(rng.unit_vector() + 2.0 * outward);
    return std::pair{o, target - o};
  };
  // (Each draw is a statement of its own, so that the order of the draws is the same with every
  // compiler.)
  // Through the apex: aimed at it, or at 10^-k·h from it across the axis or along it.
  for (int i = 0; i < 8; ++i) {
    Random c = cone();
    double across = offset(rng, 6, 16), along = offset(rng, 6, 16);
    Vec3d target = i % 4 == 0 ? c.apex : c.apex + (c.h * across) * c.u + (c.h * along) * c.axis;
    auto [o, d] = ray_to(target, c.axis, 5);
    add(fmt::format("cone-apex-{}", i), "cone-apex", o, d, c.base, c.apex, c.r);
  }
  // Through the rim: aimed at B + r(1 + δ)u + δ'h·â, δ and δ' = ±10^-k.
  for (int i = 0; i < 8; ++i) {
    Random c = cone();
    double across = offset(rng, 6, 16), along = offset(rng, 6, 16);
    Vec3d target = c.base + (c.r * (1 + across)) * c.u + (c.h * along) * c.axis;
    auto [o, d] = ray_to(target, c.u, 5);
    add(fmt::format("cone-rim-{}", i), "cone-rim", o, d, c.base, c.apex, c.r);
  }
  // A point at (1 + δ) times the side's radius at height s, u across the axis: a ray through it
  // along w (and a little along the line of the side there) grazes the side.
  auto side_point = [&](Random& c, int k_lo, int k_hi) {
    double s = rng.uniform(0.2, 0.8) * c.h, delta = offset(rng, k_lo, k_hi);
    return c.base + s * c.axis + (c.r * (1 - s / c.h) * (1 + delta)) * c.u;
  };
  // Tangent to the side, from 5 away.
  for (int i = 0; i < 6; ++i) {
    Random c = cone();
    Vec3d target = side_point(c, 4, 15);
    Vec3d line = normalized(c.apex - (c.base + c.r * c.u));
    Vec3d d = c.w + rng.uniform(-0.3, 0.3) * line;
    add(fmt::format("cone-side-tangent-{}", i), "grazing", target - 5.0 * d, d, c.base, c.apex,
        c.r);
  }
  // Parallel to a line of the side (a = 0 up to the rounding of d): from a point inside, the
  // ray crosses the side once, far from the other root.
  for (int i = 0; i < 6; ++i) {
    Random c = cone();
    Vec3d rim = c.base + c.r * c.u;
    Vec3d d = c.apex - rim;
    // One draw per statement, in the order the stored hard cases were drawn in (the operands
    // of one expression are evaluated in an order the language leaves open).
    double back = rng.uniform(0, 0.3), aside = rng.uniform(-0.2, 0.2), up = rng.uniform(0.1, 0.6);
    Vec3d inside = c.base + (up * c.h) * c.axis + (aside * c.r) * c.w - (back * c.r) * c.u;
    add(fmt::format("cone-parallel-to-side-{}", i), "cone-parallel-to-side", inside - 3.0 * d, d,
        c.base, c.apex, c.r);
  }
  // Far cones: at 10^4 to 10^8, the ray aimed within 10^-1 to 10^-10 of the rim or the apex.
  for (int i = 0; i < 5; ++i) {
    Random c = cone();
    Vec3d target = i % 2 == 0 ? c.base + (c.r * (1 + offset(rng, 1, 10))) * c.u
                              : c.apex + (c.h * offset(rng, 1, 10)) * c.u;
    auto [o, d] = ray_to(target, i % 2 == 0 ? c.u : c.axis, std::pow(10.0, rng.uniform(4, 8)));
    add(fmt::format("far-cone-{}", i), "far-cone", o, d, c.base, c.apex, c.r);
  }
  // Grazing the side from 10^8 to 10^10 away across the axis.
  for (int i = 0; i < 4; ++i) {
    Random c = cone();
    Vec3d target = side_point(c, 3, 12);
    Vec3d o = target - std::pow(10.0, rng.uniform(8, 10)) * c.w;
    add(fmt::format("grazing-cone-{}", i), "grazing", o, target - o, c.base, c.apex, c.r);
  }
  // Huge coordinates: random cones shifted by 1e8.
  two_point_huge_coordinate_cases<Cone>(3, 0.3, rng, out);
  // Worked by hand: the cone B = (0, 0, 0), apex (0, 0, 1), r = 1 (the radius at height s is
  // 1 − s). From (−5, 0, 0.5) along +x the side at t = 4.5 in (−0.5, 0, 0.5); from (−2, 0, 1)
  // along +x the apex at t = 2; from (−5, 0, 0) along +x the rim at t = 4 in (−1, 0, 0); from
  // (0.5, −5, 0.5) along +y tangent at t = 5; from (0, 0, −0.5) along (1, 0, 1), parallel to the
  // line of the side from (−1, 0, 0) to the apex (a = 0), once at t = 0.75 in (0.75, 0, 0.25);
  // from (2, −5, 0.5) along +y a miss; from (0, 0, −5) along +z, through the open base, the apex
  // at t = 6.
  Vec3d base{0, 0, 0}, apex{0, 0, 1};
  add("cone-by-hand-0", "cone-rim", {-5, 0, 0.5}, {1, 0, 0}, base, apex, 1);
  add("cone-by-hand-1", "cone-apex", {-2, 0, 1}, {1, 0, 0}, base, apex, 1);
  add("cone-by-hand-2", "cone-rim", {-5, 0, 0}, {1, 0, 0}, base, apex, 1);
  add("cone-by-hand-3", "grazing", {0.5, -5, 0.5}, {0, 1, 0}, base, apex, 1);
  add("cone-by-hand-4", "cone-parallel-to-side", {0, 0, -0.5}, {1, 0, 1}, base, apex, 1);
  add("cone-by-hand-5", "cone-rim", {2, -5, 0.5}, {0, 1, 0}, base, apex, 1);
  add("cone-by-hand-6", "cone-apex", {0, 0, -5}, {0, 0, 1}, base, apex, 1);
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
