// Helpers the generators of solid primitives share: chords between lattice points, and
// integer vectors across a given one.
#pragma once

#include <vector>

#include "sampling/draft.h"
#include "sampling/lattice.h"
#include "sampling/outcome.h"

namespace raygrade {

// Every outcome: what a closed round solid (sphere, cylinder, capsule) can be asked for.
inline const std::vector<Outcome> kSolidOutcomes = {
    Outcome::kHit, Outcome::kMiss, Outcome::kTangent, Outcome::kInside, Outcome::kBehind};

// Two different points of a lattice set, as offsets a and b; the chord from a to b is
// g·d with d the reduced direction. With `min_steps` 2 the chord has an integer point inside.
struct Chord {
  Vec3d a, b, d;
  int steps = 1;  // g
};
Chord random_chord(Prng& rng, const std::vector<Vec3d>& points, int min_steps);

// The ray along the chord from p0 to p1 (`steps` steps of d) for the outcome `o`: from s steps
// before p0 for kHit (both hits), from a random one of the steps between them for kInside (the
// exit only), from s steps past p1 for kBehind (none).
void chord_ray(Prng& rng, Outcome o, const Vec3d& p0, const Vec3d& p1, const Vec3d& d, int steps,
               int s, Vec3d& origin, std::vector<KnownHit>& hits);

// An integer vector perpendicular to `a`, reduced.
Vec3d perpendicular(Prng& rng, const Vec3d& a);

}  // namespace raygrade
