// What a generator builds: the outcomes of a generated ray, and the draft of a problem. Each
// primitive's generator (shapes/<name>.cpp) speaks these words.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "sampling/prng.h"

namespace raygrade {

// What the ray does: hits the object from outside, misses it, touches it (a tangent; for
// flat objects a ray through an edge or the rim, or lying in the plane), starts inside it, or
// has the object behind its origin.
enum class Outcome { kHit, kMiss, kTangent, kInside, kBehind };

// A problem as a generator builds it: everything but the id and title.
// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct Draft {
  nlohmann::ordered_json fields;  // kind, statement, ray, object(s) or camera, expected
};

}  // namespace raygrade
