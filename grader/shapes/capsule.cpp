// Capsule: reading, reference intersection, the side-and-ends derivation and the sketch.
#include "shapes/capsule.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/solids.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/cylinder.h"
#include "shapes/describe.h"
#include "shapes/huge_coordinates.h"
#include "shapes/round.h"
#include "shapes/sphere.h"

namespace raygrade {
Capsule::Capsule(Vec3d a, Vec3d b, double radius)
    : a_(a), b_(b), radius_(radius), height_(length(b - a)) {
  axis_ = (b - a) / height_;
}

std::unique_ptr<Shape> Capsule::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.insert(keys.end(), {"a", "b", "radius"});
  object.allow_only(keys);
  Vec3d a = object.at("a").vec3(), b = object.at("b").vec3();
  if (a == b) object.at("b").fail("b is a: the capsule would be a sphere", "degenerate");
  return std::make_unique<Capsule>(a, b, object.at("radius").positive_number());
}

nlohmann::json Capsule::to_json() const {
  return {{"type", "capsule"},
          {"a", {a_.x, a_.y, a_.z}},
          {"b", {b_.x, b_.y, b_.z}},
          {"radius", radius_}};
}

Intersection Capsule::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  // The roots, normals and heights along the axis in double-double, rounded once, as the
  // sphere's and the cylinder's: a point's part is then decided to far below the seam, which
  // is relative to the capsule's own size (not to a far origin's).
  double seam = kSeamRelative * (radius_ + height_);
  Vec3dd o(ray.origin), d(ray.direction), a(a_), b(b_);
  Vec3dd axis = unit_dd(b - a);
  DoubleDouble r(radius_);
  auto height_of = [&](const DoubleDouble& t) {
    return static_cast<double>(dot((o - a) + t * d, axis));
  };
  // The side
  if (length(cross(axis_, ray.direction)) > kAxisParallelRelative * length(ray.direction)) {
    Roots<DoubleDouble> roots = cylinder_side_roots(o, d, a, axis, r);
    DoubleDouble ts[2] = {roots.t0, roots.t1};
    for (int i = 0; i < roots.count; ++i) {
      double t = static_cast<double>(ts[i]);
      if (!ray.accepts(t)) continue;
      Vec3d p = ray.at(t);
      double s = height_of(ts[i]);
      if (s < -seam || s > height_ + seam) continue;
      Vec3dd v = (o - a) + ts[i] * d;
      out.hits.push_back(Hit{t, p, unit_rounded(v - dot(v, axis) * axis), std::nullopt, "side"});
    }
  }
  // The ends: each sphere where it lies beyond its end of the segment
  for (int end = 0; end < 2; ++end) {
    const Vec3dd& c = end == 0 ? a : b;
    Roots<DoubleDouble> roots = sphere_roots(o, d, c, r);
    DoubleDouble ts[2] = {roots.t0, roots.t1};
    for (int i = 0; i < roots.count; ++i) {
      double t = static_cast<double>(ts[i]);
      if (!ray.accepts(t)) continue;
      Vec3d p = ray.at(t);
      double s = height_of(ts[i]);
      if (end == 0 ? s > seam : s < height_ - seam) continue;
      out.hits.push_back(
          Hit{t, p, unit_rounded((o - c) + ts[i] * d), std::nullopt, end == 0 ? "end a" : "end b"});
    }
  }
  finish_hits(out.hits, seam);
  return out;
}

Derivation Capsule::derive(const Ray& ray, std::string_view /*method*/,
                           const Overrides* overrides) const {
  Deriver d("side-and-ends", "Capsule: the side's quadratic, then the end spheres", overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  E A = d.given("A", "A", a_, "one end of the segment");
  E B = d.given("B", "B", b_, "the other end");
  E r = d.given("r", "r", radius_, "the radius");
  d.step("h", "h", norm(B - A), "the length of the segment");
  d.step("u", "û", (B - A) / d.sym("h"), "the unit axis from A to B");
  E u = d.sym("u");
  std::vector<Candidate> candidates;
  // The side: the infinite cylinder around the axis, kept where 0 ≤ s ≤ h
  d.step("f", "f", O - A, "from A to the origin");
  d.step("f_perp", "f⊥", d.sym("f") - dot(d.sym("f"), u) * u, "f across the axis");
  d.step("D_perp", "D⊥", D - dot(D, u) * u, "D across the axis");
  double qa = d.step("a", "a", dot(d.sym("D_perp"), d.sym("D_perp"))).scalar;
  d.step("b", "b", 2 * dot(d.sym("f_perp"), d.sym("D_perp")));
  d.step("c", "c", dot(d.sym("f_perp"), d.sym("f_perp")) - square(r));
  if (qa == 0) {
    d.note("a = 0: the ray runs parallel to the axis and never crosses the side.");
  } else {
    double disc =
        d.step("discriminant", "Δ", square(d.sym("b")) - 4 * d.sym("a") * d.sym("c")).scalar;
    if (disc < 0) {
      d.note("Δ < 0: the ray misses the side's cylinder.");
    } else {
      for (int i = 0; i < 2; ++i) {
        std::string n = std::to_string(i);
        E root = (-d.sym("b") + (i == 0 ? -1 : 1) * sqrt(d.sym("discriminant"))) / (2 * d.sym("a"));
        double t = d.step("t_side" + n, "t_side" + n, root).scalar;
        Value p = d.step("P_side" + n, "P_side" + n, O + d.sym("t_side" + n) * D);
        double s = d.step("s_side" + n, "s_side" + n, dot(d.sym("P_side" + n) - A, u),
                          "its height along the axis: the side when 0 ≤ s ≤ h")
                       .scalar;
        std::string reason = s < 0 || s > height_
                                 ? "it lies on the side's cylinder beyond the segment (s outside "
                                   "[0, h]): an end covers it"
                                 : range_reason(ray, t);
        candidates.push_back({t, p.vector, reason});
      }
    }
  }
  // The ends: the spheres around A and B, kept beyond their end (s ≤ 0 at A, s ≥ h at B)
  d.step("a_end", "a_e", dot(D, D), "a of both end spheres: D·D");
  for (int end = 0; end < 2; ++end) {
    std::string e = end == 0 ? "A" : "B";
    E C = end == 0 ? A : B;
    d.step("f_" + e, "f_" + e, O - C, "from " + e + " to the origin");
    d.step("b_" + e, "b_" + e, 2 * dot(D, d.sym("f_" + e)));
    d.step("c_" + e, "c_" + e, dot(d.sym("f_" + e), d.sym("f_" + e)) - square(r));
    double disc = d.step("disc_" + e, "Δ_" + e,
                         square(d.sym("b_" + e)) - 4 * d.sym("a_end") * d.sym("c_" + e))
                      .scalar;
    if (disc < 0) {
      d.note(fmt::format("Δ_{} < 0: the ray misses the sphere around {}.", e, e));
      continue;
    }
    for (int i = 0; i < 2; ++i) {
      std::string n = e + std::to_string(i);
      E root =
          (-d.sym("b_" + e) + (i == 0 ? -1 : 1) * sqrt(d.sym("disc_" + e))) / (2 * d.sym("a_end"));
      double t = d.step("t_" + n, "t_" + n, root).scalar;
      Value p = d.step("P_" + n, "P_" + n, O + d.sym("t_" + n) * D);
      double s = d.step("s_" + n, "s_" + n, dot(d.sym("P_" + n) - A, u)).scalar;
      bool beyond = end == 0 ? s <= 0 : s >= height_;
      std::string reason =
          beyond ? range_reason(ray, t)
                 : fmt::format(
                       "it lies on the sphere around {} inside the segment's span ({}): "
                       "the side covers it",
                       e, end == 0 ? "s > 0" : "s < h");
      candidates.push_back({t, p.vector, reason});
    }
  }
  // A rim point is found twice (side and end) and a tangent twice over: each hit once.
  conclude_candidates(d, "capsule", ray, each_hit_once(std::move(candidates)), true);
  return std::move(d).finish();
}

void Capsule::sketch(Sketch& figure, const std::string& label) const {
  figure.cylinder(a_, axis_, radius_, height_, Ink::kObject, label);
  figure.circle(a_, radius_, Ink::kObject);
  figure.circle(b_, radius_, Ink::kObject);
}

nlohmann::ordered_json Capsule::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "description": "the points within radius of the segment from a to b: a cylinder with two hemispherical ends",
  "required": ["a", "b", "radius"],
  "properties": {
    "a": {"$ref": "#/$defs/vec3"},
    "b": {"$ref": "#/$defs/vec3"},
    "radius": {"$ref": "#/$defs/positive"}
  },
  "examples": [
    {"type": "capsule", "a": [0, 0, 0], "b": [0, 0, 4], "radius": 1},
    {"type": "capsule", "a": [-1, 2, 3], "b": [2, 2, 3], "radius": 0.5}
  ]
}
)json");
}

// The accuracy study's cases of capsules.

void Capsule::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius) {
  Vec3d a = rng.point(0.5);
  double length = rng.uniform(0.5, 1.5);
  points = {a, a + length * rng.unit_vector()};
  radius = rng.uniform(0.2, 0.8);
}

void Capsule::Ladder::hard_cases(int round, SplitMix& /*shared*/, std::vector<AccuracyCase>& out) {
  if (round != kOwnStreamRound) return;
  SplitMix rng(20261125);
  auto add = [&](std::string id, std::string group, Vec3d o, Vec3d d, Vec3d a, Vec3d b, double r) {
    out.push_back(
        make_case(std::move(id), std::move(group), primitive_of<Capsule>(), o, d, {a, b}, r));
  };
  // A random capsule: a near the origin, b at 0.5 to 3 from it.
  auto capsule = [&](double& r) {
    Vec3d a = rng.point(1);
    r = rng.uniform(0.3, 1.5);
    double length = rng.uniform(0.5, 3);
    return std::pair{a, a + length * rng.unit_vector()};
  };
  // The ray from `distance` away, coming from the side of `outward`, aimed at `target`.
  auto ray_to = [&](Vec3d target, Vec3d outward, double distance) {
    Vec3d o = target + distance * normalized(rng.unit_vector() + 2.0 * outward);
    return std::pair{o, target - o};
  };
  // Through a rim: aimed at e + r(1 + δ)u + δ' r â, u across the axis, δ and δ' = ±10^-k.
  // (Each draw is a statement of its own, so that the order of the draws is the same with every
  // compiler.)
  for (int i = 0; i < 10; ++i) {
    double r = 0;
    auto [a, b] = capsule(r);
    Vec3d axis = normalized(b - a), u = perpendicular(axis, rng);
    double across = offset(rng, 6, 16), along = offset(rng, 6, 16);
    Vec3d target = (i % 2 == 0 ? a : b) + (r * (1 + across)) * u + (r * along) * axis;
    auto [o, d] = ray_to(target, u, 5);
    add(fmt::format("capsule-rim-{}", i), "capsule-rim", o, d, a, b, r);
  }
  // A point at r(1 + δ) from the axis, inside the segment's span, u across the axis, and w
  // across both: a ray through it along w (and a little along the axis) grazes the side.
  struct SidePoint {
    Vec3d a, b, axis, w, target;
    double r = 0;
  };
  auto side_point = [&](int k_lo, int k_hi) {
    SidePoint p;
    std::tie(p.a, p.b) = capsule(p.r);
    p.axis = normalized(p.b - p.a);
    Vec3d u = perpendicular(p.axis, rng);
    p.w = cross(p.axis, u);
    double height = rng.uniform(0.2, 0.8), delta = offset(rng, k_lo, k_hi);
    p.target = p.a + height * (p.b - p.a) + (p.r * (1 + delta)) * u;
    return p;
  };
  // Tangent to the side, from 5 away.
  for (int i = 0; i < 5; ++i) {
    SidePoint p = side_point(4, 15);
    Vec3d d = p.w + rng.uniform(-0.3, 0.3) * p.axis;
    add(fmt::format("capsule-side-tangent-{}", i), "grazing", p.target - 5.0 * d, d, p.a, p.b, p.r);
  }
  // Tangent to an end: a line at r(1 + δ) from a or b, touching the sphere beyond its end.
  for (int i = 0; i < 5; ++i) {
    double r = 0;
    auto [a, b] = capsule(r);
    Vec3d axis = normalized(b - a), u = perpendicular(axis, rng);
    bool at_a = i % 2 == 0;
    Vec3d e = at_a ? a : b, beyond = at_a ? -1.0 * axis : axis;
    Vec3d v = normalized(beyond + rng.uniform(0, 1.5) * u);
    Vec3d d = perpendicular(v, rng);
    Vec3d target = e + (r * (1 + offset(rng, 4, 15))) * v;
    add(fmt::format("capsule-end-tangent-{}", i), "grazing", target - 5.0 * d, d, a, b, r);
  }
  // Far capsules: at 1e4 to 1e8, the ray aimed within 1e-1 to 1e-10 of a rim.
  for (int i = 0; i < 5; ++i) {
    double r = 1;
    Vec3d a = rng.point(1);
    double length = rng.uniform(0.5, 3);
    Vec3d b = a + length * rng.unit_vector();
    Vec3d axis = normalized(b - a), u = perpendicular(axis, rng);
    Vec3d target = (i % 2 == 0 ? a : b) + (1 + offset(rng, 1, 10)) * u;
    auto [o, d] = ray_to(target, u, std::pow(10.0, rng.uniform(4, 8)));
    add(fmt::format("far-capsule-{}", i), "far-capsule", o, d, a, b, r);
  }
  // Grazing the side from 10^8 to 10^10 away across the axis.
  for (int i = 0; i < 4; ++i) {
    SidePoint p = side_point(3, 12);
    Vec3d o = p.target - std::pow(10.0, rng.uniform(8, 10)) * p.w;
    add(fmt::format("grazing-capsule-{}", i), "grazing", o, p.target - o, p.a, p.b, p.r);
  }
  // Huge coordinates: random capsules shifted by 1e8.
  two_point_huge_coordinate_cases<Capsule>(3, 0.5, rng, out);
  // Worked by hand: the capsule a = (0, 0, 0), b = (0, 0, 4), r = 1. From (−5, 0, 2) along +x
  // the side at t = 4 in (−1, 0, 2); from (0, 0, 10) along −z the end b at t = 5 in (0, 0, 5);
  // from (−5, 0, 0) along +x the rim at a, t = 4 in (−1, 0, 0); from (0.6, 0, −5) along +z the
  // end a at z = −0.8 (0.6² + 0.8² = 1), t = 4.2; from (2, −5, 2) along +y a miss (2 from the
  // axis); from (0, 0, 2) along +x, inside, the side at t = 1; from (0, 0, 10) along +z, the
  // capsule behind: a miss.
  Vec3d a{0, 0, 0}, b{0, 0, 4};
  add("capsule-by-hand-0", "capsule-rim", {-5, 0, 2}, {1, 0, 0}, a, b, 1);
  add("capsule-by-hand-1", "capsule-rim", {0, 0, 10}, {0, 0, -1}, a, b, 1);
  add("capsule-by-hand-2", "capsule-rim", {-5, 0, 0}, {1, 0, 0}, a, b, 1);
  add("capsule-by-hand-3", "capsule-rim", {0.6, 0, -5}, {0, 0, 1}, a, b, 1);
  add("capsule-by-hand-4", "capsule-rim", {2, -5, 2}, {0, 1, 0}, a, b, 1);
  add("capsule-by-hand-5", "capsule-rim", {0, 0, 2}, {1, 0, 0}, a, b, 1);
  add("capsule-by-hand-6", "capsule-rim", {0, 0, 10}, {0, 0, 1}, a, b, 1);
}

// The capsule's normal at a point: from the nearest point F of the segment ab to P. The side
// and the ends meet smoothly, so the rims have this normal too.

SurfacePoint Capsule::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d f = nearest_on_segment(p, a_, b_);
  Vec3d out = length(p - f) > 0 ? p - f : radius_ * unit_across(p, a_, axis_);
  double u = dot(p - a_, axis_) / height_;
  std::string part = u <= 0 ? "end at a" : u >= 1 ? "end at b" : "side";
  return SurfacePoint{f + radius_ * normalized(out), out, part, ""};
}

void Capsule::derive_normal(Deriver& d, const E& P, const SurfacePoint& s,
                            const NormalNames& n) const {
  E A = d.given("A", "a", a_, "one end of the segment");
  E B = d.given("B", "b", b_, "the other end");
  if (s.part == "side") {
    d.step("ab", "b − a", B - A);
    d.step("u", "u", dot(P - A, d.sym("ab")) / dot(d.sym("ab"), d.sym("ab")),
           "how far along ab the point nearest to P lies (between 0 and 1: on the side)");
    d.step("F", "F", A + d.sym("u") * d.sym("ab"), "the point of the segment nearest to P");
  } else {
    d.step("F", "F", s.part == "end at a" ? A : B,
           fmt::format("P is beyond that end of the segment (on the {}): the nearest point of "
                       "the segment is the end itself",
                       s.part));
  }
  d.step("PF", n.point + " − F", P - d.sym("F"), "from the segment to the point");
  d.step(n.name, n.display, d.sym("PF") / norm(d.sym("PF")), "the outward unit normal");
}

// The capsule's generator: a capsule along an axis, the answer built first from lattice points
// of its side (on circles of its radius) and of its ends (on spheres of its radius), and the ray
// backwards from it.

namespace {

// A point of the capsule's surface as the construction knows it: its offset from the axis
// point `foot` (a + z·â), and whether it is on the side (whose lines along the axis are the
// only lines the surface holds).
struct CapsulePoint {
  Vec3d offset;
  int foot = 0;  // the height of the axis point it is measured from
  bool side = false;
  Vec3d at(const Vec3d& a) const { return a + offset + Vec3d{0, 0, double(foot)}; }
};

}  // namespace

const std::vector<Outcome>& Capsule::outcomes() { return kSolidOutcomes; }

Draft Capsule::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kSolidOutcomes);
  AxisMap map = random_axis_map(rng);
  int r = rng.pick(std::vector<int>{2, 3, 5, 6, 7});
  int length = rng.range(2, 6);
  Vec3d a = random_point(rng, 3);
  Vec3d up{0, 0, 1};
  // Built along the z axis from a to a + length·z, then turned by `map`. The side's points
  // strictly between the rims, and the ends' strictly beyond them (never on a rim).
  std::vector<CapsulePoint> points;
  for (int z = 1; z < length; ++z) {
    for (const auto& p : lattice_circle(r)) points.push_back({p, z, true});
  }
  for (const auto& v : lattice_sphere(r)) {
    if (v.z < 0) points.push_back({v, 0, false});
    if (v.z > 0) points.push_back({v, length, false});
  }
  int s = rng.range(1, 3);
  Vec3d origin, d;
  std::vector<KnownHit> hits;
  if (o == Outcome::kTangent || o == Outcome::kMiss) {
    // Tangent at P: across the outward normal there (the offset), so the line touches the
    // convex capsule at P alone; moved out by the offset, it passes 2r from the axis point and
    // misses.
    CapsulePoint p = rng.pick(points);
    d = p.side ? reduced(Vec3d{-p.offset.y, p.offset.x, 0}) : perpendicular(rng, p.offset);
    origin = p.at(a) - s * d;
    if (o == Outcome::kMiss)
      origin = origin + p.offset;
    else
      hits.push_back({double(s), p.at(a)});
  } else {
    // A chord between two points of the surface: the capsule is convex, so the line meets its
    // surface there and nowhere else, unless both lie on one line of the side.
    CapsulePoint p, q;
    int steps = 1;
    while (true) {
      p = rng.pick(points);
      q = rng.pick(points);
      if (p.at(a) == q.at(a) || (p.side && q.side && p.offset == q.offset)) continue;
      steps = static_cast<int>(component_gcd(q.at(a) - p.at(a)));
      if (o == Outcome::kInside && steps < 2) continue;
      break;
    }
    d = reduced(q.at(a) - p.at(a));
    Vec3d p0 = p.at(a), p1 = q.at(a);
    chord_ray(rng, o, p0, p1, d, steps, s, origin, hits);
  }
  Vec3d b = a + double(length) * up;
  nlohmann::ordered_json object = {
      {"type", kType}, {"a", vector_json(map(a))}, {"b", vector_json(map(b))}, {"radius", r}};
  for (auto& hit : hits) hit.point = map(hit.point);
  return intersect_draft(map(origin), map(d), object,
                         fmt::format("the capsule of radius {} around the segment from {} to {}", r,
                                     point_text(map(a)), point_text(map(b))),
                         hits);
}

}  // namespace raygrade
