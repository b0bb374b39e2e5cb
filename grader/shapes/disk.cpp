// Disk: reading, reference intersection, the plane-then-distance derivation and the sketch.
#include "shapes/disk.h"

#include <cmath>

#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/flats.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"
#include "shapes/flat.h"
#include "shapes/plane.h"
#include "shapes/round.h"
#include "shapes/sphere.h"

namespace raygrade {

// A point whose squared distance from the centre exceeds r² by no more than this fraction of r²
// is on the rim: the rounding of P = O + tD and of the squares, a few ulps each, so that a ray
// worked by hand through the rim (|P − C| = r exactly) hits.
// (disk_inside, shapes/disk.h).
constexpr double kRimRelative = 16 * 2.220446049250313e-16;

std::unique_ptr<Shape> Disk::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.insert(keys.end(), {"center", "normal", "radius"});
  object.allow_only(keys);
  return std::make_unique<Disk>(object.at("center").vec3(), object.at("normal").nonzero_vec3(),
                                object.at("radius").positive_number());
}

nlohmann::json Disk::to_json() const {
  return {{"type", "disk"},
          {"center", {center_.x, center_.y, center_.z}},
          {"normal", {normal_.x, normal_.y, normal_.z}},
          {"radius", radius_}};
}

bool Disk::inside(const Vec3d& point) const { return disk_inside(point, center_, radius_); }

Intersection Disk::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  if (parallel_to_plane(normal_, ray.direction)) {
    // In the plane, the ray meets the disk along a segment when its line passes within r of
    // the centre inside the ray's interval: the circle's roots, as a sphere's.
    if (in_plane(normal_, center_, ray.origin)) {
      Roots<double> roots = sphere_roots(ray.origin, ray.direction, center_, radius_);
      double last = roots.count == 2 ? roots.t1 : roots.t0;
      out.contained = roots.count > 0 && roots.t0 <= ray.t_max && last >= ray.t_min;
    }
    return out;
  }
  std::optional<double> t = plane_t(ray.origin, ray.direction, normal_, center_);
  if (!t || !ray.accepts(*t)) return out;
  Vec3d p = ray.at(*t);
  if (!inside(p)) return out;
  Hit h;
  h.t = *t;
  h.point = p;
  h.normal = unit_rounded(Vec3dd(normal_));
  out.hits.push_back(h);
  return out;
}

Derivation Disk::derive(const Ray& ray, std::string_view /*method*/,
                        const Overrides* overrides) const {
  Deriver d("plane-then-distance", "Disk: the plane, then the distance from the centre", overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  E C = d.given("C", "C", center_, "the disk's centre");
  E N = d.given("N", "N", normal_, "the disk's normal");
  E r = d.given("r", "r", radius_, "the disk's radius");
  // The plane
  double den = d.step("denominator", dot(N, D), dot(N, D)).scalar;
  if (den == 0) {
    double s = d.step("numerator", dot(N, C - O), dot(N, C - O)).scalar;
    d.note("N·D = 0: the ray is parallel to the disk's plane.");
    d.conclude(s == 0 ? "The ray lies in the disk's plane: where it crosses the disk it meets it "
                        "along a segment, not at a point."
                      : "The ray is parallel to the disk's plane and off it: no hit.");
    return std::move(d).finish();
  }
  d.step("numerator", dot(N, C - O), dot(N, C - O));
  double t = d.step("t", "t", d.sym("numerator") / d.sym("denominator"),
                    "where the ray meets the plane N·(P − C) = 0")
                 .scalar;
  Value p = d.step("P", "P", O + d.sym("t") * D, "the point where the ray meets the plane");
  // The distance from the centre
  double dist2 = d.step("dist2", "|P − C|²", dot(d.sym("P") - C, d.sym("P") - C),
                        "the squared distance of P from the centre")
                     .scalar;
  double r2 = d.step("r2", "r²", square(r)).scalar;
  bool in = dist2 <= r2 * (1 + kRimRelative);
  std::string reason =
      in ? range_reason(ray, t)
         : "the plane point P lies outside the disk (|P − C|² > r²: farther than r from C)";
  conclude_candidates(d, "disk", ray, {{t, p.vector, reason}}, false);
  return std::move(d).finish();
}

void Disk::sketch(Sketch& figure, const std::string& label) const {
  // The rim as a polygon of 48 points: edge-on it is a segment, face-on a circle.
  figure.path(circle_points(center_, normal_ / length(normal_), radius_, 48), true, Ink::kObject,
              label);
}

nlohmann::ordered_json Disk::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "description": "the closed disk of radius r around center in the plane through it with the given normal: the rim hits",
  "required": ["center", "normal", "radius"],
  "properties": {
    "center": {"$ref": "#/$defs/vec3"},
    "normal": {"$ref": "#/$defs/nonzero_vec3"},
    "radius": {"$ref": "#/$defs/positive"}
  },
  "examples": [
    {"type": "disk", "center": [0, 0, 5], "normal": [0, 0, -1], "radius": 2},
    {"type": "disk", "center": [1, 2, 0], "normal": [0, 1, 1], "radius": 0.5}
  ]
}
)json");
}

// The accuracy study's cases of disks.

void Disk::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius) {
  Vec3d c = rng.point(0.5);
  points = {c, rng.unit_vector()};
  radius = rng.uniform(0.3, 1.2);
}

void Disk::Ladder::hard_cases(int round, SplitMix& /*shared*/, std::vector<AccuracyCase>& out) {
  if (round != kOwnStreamRound) return;
  SplitMix rng(20261124);
  auto add = [&](std::string id, std::string group, Vec3d o, Vec3d d, Vec3d c, Vec3d n, double r) {
    out.push_back(
        make_case(std::move(id), std::move(group), primitive_of<Disk>(), o, d, {c, n}, r));
  };
  // A ray through the rim: aimed at C + r(1 + δ)·u, u in the plane, δ = ±10^-k.
  auto rim_ray = [&](Vec3d c, Vec3d n, double r, double distance, double delta) {
    Vec3d u = perpendicular(normalized(n), rng);
    Vec3d target = c + (r * (1 + delta)) * u;
    Vec3d o = target + distance * normalized(rng.unit_vector() + normalized(n));
    return std::pair{o, target - o};
  };
  for (int i = 0; i < 12; ++i) {
    Vec3d c = rng.point(1);
    double length = rng.uniform(0.5, 3);
    Vec3d n = rng.unit_vector() * length;
    double r = rng.uniform(0.5, 2);
    auto [o, d] = rim_ray(c, n, r, 5, offset(rng, 6, 16));
    add(fmt::format("disk-rim-{}", i), "disk-rim", o, d, c, n, r);
  }
  // Far disks: at 1e4 to 1e8, the ray aimed just inside or outside the rim.
  for (int i = 0; i < 10; ++i) {
    Vec3d c = rng.point(1), n = rng.unit_vector();
    double r = 1;
    double delta = offset(rng, 1, 10), distance = std::pow(10.0, rng.uniform(4, 8));
    auto [o, d] = rim_ray(c, n, r, distance, delta);
    add(fmt::format("far-disk-{}", i), "far-disk", o, d, c, n, r);
  }
  // Grazing: from 10^8 to 10^11 away along the plane and 0.5 to 2 off it (an angle of 10^-8 to
  // 10^-11), crossing the plane near the rim.
  for (int i = 0; i < 10; ++i) {
    Vec3d c = rng.point(1), n = normalized(rng.unit_vector());
    double r = rng.uniform(0.5, 2);
    Vec3d u = perpendicular(n, rng), along = perpendicular(n, rng);
    Vec3d target = c + (r * (1 + offset(rng, 3, 12))) * u;
    double far = std::pow(10.0, rng.uniform(8, 11)), h = rng.uniform(0.5, 2);
    Vec3d o = target - far * along + h * n;
    add(fmt::format("grazing-disk-{}", i), "grazing", o, target - o, c, n, r);
  }
  // Huge coordinates: random disks shifted by 1e8.
  for (int i = 0; i < 6; ++i) {
    Vec3d shift = 1e8 * rng.unit_vector();
    Vec3d c = rng.point(0.5), n = rng.unit_vector();
    double r = rng.uniform(0.3, 1.2);
    Vec3d o = 4.0 * rng.unit_vector(), target = rng.point(1);
    add(fmt::format("huge-coordinates-disk-{}", i), "huge-coordinates", o + shift, target - o,
        c + shift, n, r);
  }
  // Worked by hand: the disk of radius 5 around the origin in z = 0. From (3, 4, 7) along −z the
  // ray meets the plane at t = 7 in (3, 4, 0), on the rim (3² + 4² = 25): a hit. From (3, 4.5, 7),
  // |P|² = 29.25 > 25: a miss. From (0, 0, −2) along +z, t = 2 from behind. From (1, 1, 2) along
  // +z the plane is behind (t = −2): a miss.
  add("disk-by-hand-0", "disk-rim", {3, 4, 7}, {0, 0, -1}, {0, 0, 0}, {0, 0, 1}, 5);
  add("disk-by-hand-1", "disk-rim", {3, 4.5, 7}, {0, 0, -1}, {0, 0, 0}, {0, 0, 1}, 5);
  add("disk-by-hand-2", "disk-rim", {0, 0, -2}, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}, 5);
  add("disk-by-hand-3", "disk-rim", {1, 1, 2}, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}, 5);
}

// The disk's normal at a point: the given one, normalized, the same over the disk and its rim
// (the disk is flat: its rim is no edge between two parts).

SurfacePoint Disk::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d u = normalized(normal_);
  Vec3d q = p - dot(p - center_, u) * u;
  Vec3d off = q - center_;
  double rho = length(off);
  if (rho > radius_) q = center_ + (radius_ / rho) * off;  // beyond the rim: the rim's point
  return SurfacePoint{q, normal_, "", ""};
}

void Disk::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                         const NormalNames& n) const {
  E given = d.given("n", "n", normal_, "the disk's normal as given");
  d.step(n.name, n.display, given / norm(given),
         "the same at every point of the disk, its rim included");
}

// The disk's generator: a disk across an axis, the hit at a lattice point of its plane (inside,
// on the rim, or outside for a miss) and the ray built backwards from it.

// The tangent outcome of a disk is a ray through its rim (the disk is closed: the rim hits).
const std::vector<Outcome>& Disk::outcomes() { return kFlatOutcomes; }

Draft Disk::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kFlatOutcomes);
  AxisMap map = random_axis_map(rng);
  int r = rng.pick(std::vector<int>{2, 3, 5, 10});
  Vec3d c = random_point(rng, 4);
  // Built across the z axis, then turned by `map`.
  Vec3d n{0, 0, 1};
  Vec3d offset;  // from the centre to the point the ray passes through, in the disk's plane
  if (o == Outcome::kTangent) {
    offset = rng.pick(lattice_circle(r));
  } else if (o == Outcome::kMiss) {
    offset = 2 * rng.pick(lattice_circle(r));  // twice the radius from the centre
  } else {
    // A lattice point strictly inside: |offset| < r.
    do {
      offset = {double(rng.range(-r + 1, r - 1)), double(rng.range(-r + 1, r - 1)), 0};
    } while (length_squared(offset) >= double(r * r));
  }
  // A normal of length 1 or 2 as given, either way across the disk.
  int sign = rng.sign();
  Vec3d given = double(sign * rng.range(1, 2)) * map(n);
  nlohmann::ordered_json object = {{"type", kType},
                                   {"center", vector_json(map(c))},
                                   {"normal", vector_json(given)},
                                   {"radius", r}};
  return flat_draft(rng, o, map(c + offset), map(n), object,
                    fmt::format("the disk with center {}, normal {} and radius {}",
                                point_text(map(c)), direction_text(given), r));
}

}  // namespace raygrade
