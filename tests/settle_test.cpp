// The solver's adaptive decision: the level a problem needed, and answers corrected where
// double could not decide.
#include "accuracy/settle.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace raygrade {
namespace {

std::string sphere_problem(const std::string& origin) {
  return fmt::format(
      R"({{"id": "p", "kind": "intersect", "ray": {{"origin": {}, "direction": [1, 0, 0]}},
          "object": {{"type": "sphere", "center": [0, 0, 0], "radius": 1}}}})",
      origin);
}

// Seed 000, case 1 (t = 1 and 3) needs no more than double.
TEST(Settle, OrdinaryProblemNeedsDouble) {
  Problem p = testing::problem(R"({"id": "p", "kind": "intersect",
      "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
      "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  EXPECT_EQ(p.task->level(), "double");
}

// An exact tangent: the discriminant is exactly 0 in interval arithmetic, so double decides.
TEST(Settle, ExactTangentIsDecidedInDouble) {
  Problem p = testing::problem(sphere_problem("[-5, 1, 0]"));
  EXPECT_EQ(p.task->level(), "double");
  EXPECT_EQ(p.task->answer()["hits"].size(), 1u);
}

// y = 1 − 2^-53, z = 2^-26 − 2^-79: Δ = 3·2^-106 − 2^-158 > 0, a hit near t = 5 that only
// MPFR can vouch for; z = 2^-26 gives Δ = −2^-106, a miss.
TEST(Settle, MpfrDecidesWhatDoubleDoubleCannot) {
  Problem hit =
      testing::problem(sphere_problem("[-5, 0.9999999999999999, 1.4901161193847655e-08]"));
  EXPECT_EQ(hit.task->level(), "mpfr");
  nlohmann::json a = hit.task->answer();
  ASSERT_GE(a["hits"].size(), 1u);
  EXPECT_NEAR(a["hits"][0]["t"].get<double>(), 5, 1e-6);
  Problem miss =
      testing::problem(sphere_problem("[-5, 0.9999999999999999, 1.4901161193847656e-08]"));
  EXPECT_EQ(miss.task->level(), "mpfr");
  EXPECT_EQ(miss.task->answer()["hits"].size(), 0u);
}

TEST(Settle, ProblemsOutsideTheStudyHaveNoLevel) {
  Problem p = testing::problem(R"({"id": "p", "kind": "intersect",
      "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0], "t_max": 10},
      "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  EXPECT_EQ(p.task->level(), std::nullopt);
}

}  // namespace
}  // namespace raygrade
