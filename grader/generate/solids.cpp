// Helpers the generators of solid primitives share.
#include "generate/solids.h"

namespace raygrade {

Chord random_chord(Prng& rng, const std::vector<Vec3d>& points, int min_steps) {
  while (true) {
    Chord c{rng.pick(points), rng.pick(points), {}, 1};
    if (c.a == c.b) continue;
    c.steps = static_cast<int>(component_gcd(c.b - c.a));
    if (c.steps < min_steps) continue;
    c.d = reduced(c.b - c.a);
    return c;
  }
}

Vec3d perpendicular(Prng& rng, const Vec3d& a) {
  while (true) {
    Vec3d p = cross(a, random_direction(rng, a));
    if (length_squared(p) > 0) return reduced(p);
  }
}

}  // namespace raygrade
