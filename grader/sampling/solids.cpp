// Helpers the generators of solid primitives share.
#include "sampling/solids.h"

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

void chord_ray(Prng& rng, Outcome o, const Vec3d& p0, const Vec3d& p1, const Vec3d& d, int steps,
               int s, Vec3d& origin, std::vector<KnownHit>& hits) {
  if (o == Outcome::kHit) {
    origin = p0 - s * d;
    hits = {{double(s), p0}, {double(s + steps), p1}};
  } else if (o == Outcome::kInside) {
    int k = rng.range(1, steps - 1);
    origin = p0 + k * d;
    hits = {{double(steps - k), p1}};
  } else {
    origin = p1 + s * d;
  }
}

Vec3d perpendicular(Prng& rng, const Vec3d& a) {
  while (true) {
    Vec3d p = cross(a, random_direction(rng, a));
    if (length_squared(p) > 0) return reduced(p);
  }
}

}  // namespace raygrade
