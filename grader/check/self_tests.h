// Self-tests of a problem: sample answers with the score (and named mistake) the grader must
// give them, like STACK's question tests and PrairieLearn's test().
#pragma once

#include <vector>

#include "core/error.h"
#include "problems/problem.h"

namespace raygrade {

// Runs every entry of the problem's `tests` through the grader and reports each one whose
// score or mistake differs from what it states, and each malformed entry.
std::vector<Diagnostic> run_self_tests(const Problem& p, const nlohmann::json& reference);

}  // namespace raygrade
