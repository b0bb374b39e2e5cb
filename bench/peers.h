// Peer intersectors measured beside the ladder on the same rays: GLM's intersectRaySphere,
// intersectRayTriangle and intersectRayPlane (in double) and a plain Möller–Trumbore.
#pragma once

#include <string>
#include <vector>

#include "accuracy/ladder.h"

namespace raygrade {

struct Peer {
  std::string name;
  Primitive primitive;
  NearestHit nearest;
};

const std::vector<Peer>& peers();

}  // namespace raygrade
