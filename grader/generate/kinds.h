// Generators of the kinds that are not one primitive: first-hit and camera-ray. The
// primitives' generators are in their own files (shapes/<name>.cpp).
#pragma once

#include "generate/generate.h"

namespace raygrade {

Draft make_first_hit(Prng& rng, std::optional<Outcome> outcome);
Draft make_camera_ray(Prng& rng, std::optional<Outcome> outcome);

}  // namespace raygrade
