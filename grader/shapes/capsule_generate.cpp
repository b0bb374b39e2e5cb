// The capsule's generator: a capsule along an axis, the answer built first from lattice points
// of its side (on circles of its radius) and of its ends (on spheres of its radius), and the ray
// backwards from it.
#include "generate/draft.h"
#include "generate/solids.h"
#include "shapes/capsule.h"

namespace raygrade {
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
