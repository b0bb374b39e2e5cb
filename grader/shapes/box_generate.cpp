// The box's generator: builds the answer first (hits at lattice points, at integer t) and the ray
// backwards from it.
#include "generate/draft.h"
#include "generate/solids.h"
#include "shapes/box.h"

namespace raygrade {
namespace {

// Boxes have no tangent case here (a ray grazing an edge is an edge case of the slabs).
const std::vector<Outcome> kBoxOutcomes = {Outcome::kHit, Outcome::kMiss, Outcome::kInside,
                                           Outcome::kBehind};

}  // namespace

const std::vector<Outcome>& Box::outcomes() { return kBoxOutcomes; }

Draft Box::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kBoxOutcomes);
  AxisMap map = random_axis_map(rng);
  Vec3d lo = random_point(rng, 3);
  Vec3d size{double(rng.range(2, 5)), double(rng.range(2, 5)), double(rng.range(2, 5))};
  Vec3d hi = lo + size;
  // Enter through the face x = lo.x and leave through x = hi.x, away from every edge.
  auto inner = [&](int axis) { return double(rng.range(1, static_cast<int>(size[axis]) - 1)); };
  Vec3d p0, p1, full;
  int steps = 1;
  do {
    p0 = {lo.x, lo.y + inner(1), lo.z + inner(2)};
    p1 = {hi.x, lo.y + inner(1), lo.z + inner(2)};
    full = p1 - p0;
    steps = static_cast<int>(component_gcd(full));
  } while (o == Outcome::kInside && steps < 2);
  Vec3d d = reduced(full);
  int s = rng.range(1, 3);
  Vec3d origin;
  std::vector<KnownHit> hits;
  if (o != Outcome::kMiss) {
    chord_ray(rng, o, p0, p1, d, steps, s, origin, hits);
  } else {
    // The same line moved past the box's top in y: clear of it by at least one unit.
    origin = p0 - s * d + Vec3d{0, size.y + std::abs(p1.y - p0.y) + 1, 0};
  }
  Vec3d a = map(lo), b = map(hi);
  Vec3d mn{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  Vec3d mx{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  nlohmann::ordered_json object = {
      {"type", "box"}, {"min", vector_json(mn)}, {"max", vector_json(mx)}};
  for (auto& h : hits) h.point = map(h.point);
  return intersect_draft(
      map(origin), map(d), object,
      fmt::format("the axis-aligned box from {} to {}", point_text(mn), point_text(mx)), hits);
}

}  // namespace raygrade
