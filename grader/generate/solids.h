// Helpers the generators of solid primitives share: chords between lattice points, and
// integer vectors across a given one.
#pragma once

#include <vector>

#include "generate/lattice.h"
#include "generate/outcome.h"

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

// An integer vector perpendicular to `a`, reduced.
Vec3d perpendicular(Prng& rng, const Vec3d& a);

}  // namespace raygrade
