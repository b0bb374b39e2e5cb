// Helpers the generators share: the ray, the expected hits and the statement of a draft.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sampling/lattice.h"
#include "sampling/outcome.h"

namespace raygrade {

// A hit as the construction knows it: its t and point, exact.
struct KnownHit {
  double t;
  Vec3d point;
};

// The outcome asked for, or a random one of those the generator can build.
Outcome choose_outcome(Prng& rng, std::optional<Outcome> asked, const std::vector<Outcome>& can);

// An intersect draft: the ray, the object, the hits, and a statement naming the object.
Draft intersect_draft(const Vec3d& origin, const Vec3d& direction, nlohmann::ordered_json object,
                      const std::string& object_text, const std::vector<KnownHit>& hits,
                      bool contained = false);

nlohmann::ordered_json known_hit_json(const KnownHit& h);

// "p(t) = (0, 0, 0) + t<1, 0, 0>".
std::string ray_text(const Vec3d& origin, const Vec3d& direction);

}  // namespace raygrade
