// Grading: seed answers graded as an instructor would, by values derived by hand.
#include "grading/grade.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace raygrade {
namespace {

using nlohmann::json;

const char* kSphere1 = R"({"id": "s1", "method": "geometric",
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})";

// Seed 000, sphere case 1: t = 1 and 3, P = (1,0,0) and (3,0,0); L = (2,0,0), t_ca = 2,
// d² = 0, t_hc = 1.
TEST(Grade, SeedSphereCase1IsRight) {
  Problem p = testing::problem(kSphere1);
  auto r = grade_answer(p, json::parse(R"({"hits": [{"t": 1, "point": [1, 0, 0]},
      {"t": 3, "point": [3, 0, 0]}], "steps": {"L": [2, 0, 0], "t_ca": 2, "d2": 0, "t_hc": 1}})"));
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
  EXPECT_DOUBLE_EQ(r.max_score, 3);  // t 2 + point 1 by default
  EXPECT_TRUE(r.mistakes.empty());
}

TEST(Grade, RootsMatchInEitherOrder) {
  Problem p = testing::problem(kSphere1);
  auto r = grade_answer(p, json::parse(R"({"hits": [{"t": "3"}, {"t": 1}]})"));
  ASSERT_FALSE(r.parts.empty());
  EXPECT_EQ(r.parts[0].name, "t");
  EXPECT_DOUBLE_EQ(r.parts[0].points, 2);
}

// Seed 000 plane case 1: the student's D = −2 (they took D = N·V0), t = 2 right.
TEST(Grade, SeedPlaneDSignSlipFlaggedWhileTIsRight) {
  Problem p = testing::problem(R"({"id": "p1", "method": "implicit",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "plane", "point": [2, 0, 0], "normal": [-1, 0, 0]}})");
  auto r = grade_answer(p, json::parse(R"({"hits": [{"t": 2, "point": [2, 0, 0]}],
      "steps": {"D": -2}})"));
  EXPECT_TRUE(r.has_mistake("plane-d-sign"));
  EXPECT_DOUBLE_EQ(r.score, 3);
}

}  // namespace
}  // namespace raygrade
