// The disk's generator: a disk across an axis, the hit at a lattice point of its plane (inside,
// on the rim, or outside for a miss) and the ray built backwards from it.
#include "generate/draft.h"
#include "generate/flats.h"
#include "shapes/disk.h"

namespace raygrade {

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
  Vec3d given = double(rng.sign() * rng.range(1, 2)) * map(n);
  nlohmann::ordered_json object = {{"type", kType},
                                   {"center", vector_json(map(c))},
                                   {"normal", vector_json(given)},
                                   {"radius", r}};
  return flat_draft(rng, o, map(c + offset), map(n), object,
                    fmt::format("the disk with center {}, normal {} and radius {}",
                                point_text(map(c)), direction_text(given), r));
}

}  // namespace raygrade
