// Peer intersectors measured beside the ladder on the same rays: GLM's intersectRaySphere,
// intersectRayTriangle and intersectRayPlane (in double) and a plain Möller–Trumbore.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "accuracy/accuracy_case.h"

namespace raygrade {

struct Peer {
  std::string name;
  Primitive primitive;
  std::function<std::optional<double>(const AccuracyCase&)> nearest;
};

const std::vector<Peer>& peers();

}  // namespace raygrade
