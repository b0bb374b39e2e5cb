// Helpers the generators of flat primitives share: a plane's integer lattice, and the ray
// built backwards from a point of it.
#pragma once

#include <string>
#include <vector>

#include "sampling/lattice.h"
#include "sampling/outcome.h"

namespace raygrade {

// Flat objects: tangent means a ray through an edge or the rim (or, for a plane, lying in it).
inline const std::vector<Outcome> kFlatOutcomes = {Outcome::kHit, Outcome::kMiss, Outcome::kTangent,
                                                   Outcome::kBehind};

// Two integer vectors spanning a plane, and a corner: the plane's 2D lattice.
struct Frame {
  Vec3d corner, e1, e2;
  Vec3d at(double x, double y) const { return corner + x * e1 + y * e2; }
  Vec3d normal() const { return cross(e1, e2); }
};
Frame random_frame(Prng& rng);

// The ray for a flat object: through `p` for a hit or an edge, with `p` behind it for
// kBehind; for a miss the caller passes a point of the plane outside the object.
Draft flat_draft(Prng& rng, Outcome o, const Vec3d& p, const Vec3d& normal,
                 const nlohmann::ordered_json& object, const std::string& text);

// "(0, 0, 0), (4, 0, 0), (0, 3, 0)" and the JSON list of the same vertices.
std::string vertices_text(const std::vector<Vec3d>& v);
nlohmann::ordered_json vertices_json(const std::vector<Vec3d>& v);

}  // namespace raygrade
