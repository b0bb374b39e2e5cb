// Generators of the primitives and kinds, one function each, listed in generator_table().
#pragma once

#include "generate/generate.h"

namespace raygrade {

// Boxes have no tangent case here (a ray grazing an edge is an edge case of the slabs).
inline const std::vector<Outcome> kBoxOutcomes = {Outcome::kHit, Outcome::kMiss, Outcome::kInside,
                                                  Outcome::kBehind};
// Flat objects: tangent means a ray through an edge (or, for a plane, lying in it).
inline const std::vector<Outcome> kFlatOutcomes = {Outcome::kHit, Outcome::kMiss, Outcome::kTangent,
                                                   Outcome::kBehind};

Draft make_sphere(Prng& rng, std::optional<Outcome> outcome);
Draft make_cylinder(Prng& rng, std::optional<Outcome> outcome);
Draft make_box(Prng& rng, std::optional<Outcome> outcome);
Draft make_plane(Prng& rng, std::optional<Outcome> outcome);
Draft make_triangle(Prng& rng, std::optional<Outcome> outcome);
Draft make_polygon(Prng& rng, std::optional<Outcome> outcome);
Draft make_first_hit(Prng& rng, std::optional<Outcome> outcome);
Draft make_camera_ray(Prng& rng, std::optional<Outcome> outcome);

}  // namespace raygrade
