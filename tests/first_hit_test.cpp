// first-hit: the nearest object along a ray, with ties and objects out of the interval.
#include <gtest/gtest.h>

#include "kinds/intersect.h"
#include "test_util.h"

namespace raygrade {
namespace {

Problem first_hit_problem(const std::string& ray, const std::string& objects) {
  return testing::problem(R"({"id": "p", "kind": "first-hit", "ray": )" + ray + R"(, "objects": )" +
                          objects + "}");
}

// Seed 001: spheres at (0,0,10), (0,3,8), (0,1,9), radius 2, ray from the origin along +z.
// Sphere 1: (t − 10)² = 4, t = 8; sphere 2: 9 + (t − 8)² = 4 has no root; sphere 3:
// 1 + (t − 9)² = 4, t = 9 − √3 ≈ 7.27. Sphere 3 is hit first.
TEST(FirstHit, SeedOneSphereThreeIsFirst) {
  Problem p = first_hit_problem(
      R"({"origin": [0, 0, 0], "direction": [0, 0, 1]})",
      R"([{"name": "sphere 1", "type": "sphere", "center": [0, 0, 10], "radius": 2},
      {"name": "sphere 2", "type": "sphere", "center": [0, 3, 8], "radius": 2},
      {"name": "sphere 3", "type": "sphere", "center": [0, 1, 9], "radius": 2}])");
  auto a = p.task->answer();
  EXPECT_EQ(a["object"], "sphere 3");
  ASSERT_EQ(a["hits"].size(), 1u);
  EXPECT_NEAR(a["hits"][0]["t"].get<double>(), 9 - std::sqrt(3.0), 1e-15);
  EXPECT_FALSE(a.contains("tie"));
}

// Two objects met at the same t = 4: a plane z = 4 and a sphere touching it from above
// (center (0, 0, 5), radius 1). The tie is flagged; the first in the list is named.
TEST(FirstHit, TieNamesTheFirstAndSaysSo) {
  Problem p = first_hit_problem(
      R"({"origin": [0, 0, 0], "direction": [0, 0, 1]})",
      R"([{"name": "floor", "type": "plane", "point": [0, 0, 4], "normal": [0, 0, -1]},
      {"name": "ball", "type": "sphere", "center": [0, 0, 5], "radius": 1}])");
  auto a = p.task->answer();
  EXPECT_EQ(a["object"], "floor");
  EXPECT_EQ(a["tie"], true);
  EXPECT_EQ(a["hits"][0]["t"], 4.0);
}

// A tie computed by two different formulas, equal up to rounding: the plane x + y + z = 0.3
// (d form) and a triangle in it, met from the origin along (0.1, 0.1, 0.1) at t = 1.
TEST(FirstHit, TieUpToRoundingIsATie) {
  Problem p = first_hit_problem(
      R"({"origin": [0, 0, 0], "direction": [0.1, 0.1, 0.1]})",
      R"([{"name": "tri", "type": "triangle", "vertices": [[0.3, 0, 0], [0, 0.3, 0], [0, 0, 0.3]]},
      {"name": "plane", "type": "plane", "normal": [1, 1, 1], "d": -0.3}])");
  auto a = p.task->answer();
  EXPECT_EQ(a["object"], "tri");
  EXPECT_EQ(a["tie"], true);
}

// A plane x = 1 and a sphere of centre (1 + 2^-7, 0, 0) and radius 2^-7 − 2^-60 (both exact
// doubles), met from the origin along +x: the plane at t = 1, the sphere at t = c − r =
// 1 + 2^-60, which is distinct but rounds to 1 in double. Double sees a tie and would name the
// sphere, listed first; double-double orders them: the plane is first, and there is no tie.
TEST(FirstHit, OrderDoubleCannotResolveIsSettledHigher) {
  Problem p = first_hit_problem(R"({"origin": [0, 0, 0], "direction": [1, 0, 0]})",
                                R"([{"name": "ball", "type": "sphere", "center": [1.0078125, 0, 0],
           "radius": 0.0078124999999999991326382620115964},
          {"name": "wall", "type": "plane", "point": [1, 0, 0], "normal": [-1, 0, 0]}])");
  ASSERT_EQ(0x1p-7 - 0x1p-60, 0.0078124999999999991326382620115964);
  auto a = p.task->answer();
  EXPECT_EQ(a["object"], "wall");
  EXPECT_FALSE(a.contains("tie"));
  EXPECT_EQ(a["hits"][0]["t"], 1.0);
  EXPECT_EQ(p.task->level(), "double-double");
}

// A plane x = 1 and a sphere of centre (2, 0, 0) and radius 1, met from the origin along
// (3, 0, 0): both at t = 1/3 exactly, which no binary precision represents, so no level's
// enclosures separate them: an exact tie, reported at the top of the ladder.
TEST(FirstHit, ExactTieIsReportedAsATie) {
  Problem p =
      first_hit_problem(R"({"origin": [0, 0, 0], "direction": [3, 0, 0]})",
                        R"([{"name": "ball", "type": "sphere", "center": [2, 0, 0], "radius": 1},
          {"name": "wall", "type": "plane", "point": [1, 0, 0], "normal": [-1, 0, 0]}])");
  auto a = p.task->answer();
  EXPECT_EQ(a["object"], "ball");
  EXPECT_EQ(a["tie"], true);
  EXPECT_NEAR(a["hits"][0]["t"].get<double>(), 1.0 / 3, 1e-16);
  EXPECT_EQ(p.task->level(), "exact-boundary");
}

// Objects far apart in t are ordered in double.
TEST(FirstHit, DistinctObjectsAreOrderedInDouble) {
  Problem p = first_hit_problem(
      R"({"origin": [0, 0, 0], "direction": [0, 0, 1]})",
      R"([{"name": "sphere 1", "type": "sphere", "center": [0, 0, 10], "radius": 2},
      {"name": "sphere 3", "type": "sphere", "center": [0, 1, 9], "radius": 2}])");
  EXPECT_EQ(p.task->answer()["object"], "sphere 3");
  EXPECT_EQ(p.task->level(), "double");
}

// A nearer object behind the origin does not count; t_max cuts off a farther one.
TEST(FirstHit, OnlyHitsInTheIntervalCount) {
  std::string objects = R"([{"name": "behind", "type": "sphere", "center": [0, 0, -5], "radius": 1},
      {"name": "near", "type": "sphere", "center": [0, 0, 5], "radius": 1},
      {"name": "far", "type": "sphere", "center": [0, 0, 9], "radius": 1}])";
  auto a =
      first_hit_problem(R"({"origin": [0, 0, 0], "direction": [0, 0, 1]})", objects).task->answer();
  EXPECT_EQ(a["object"], "near");
  EXPECT_EQ(a["hits"][0]["t"], 4.0);
  auto none =
      first_hit_problem(R"({"origin": [0, 0, 0], "direction": [0, 0, 1], "t_max": 3.5})", objects)
          .task->answer();
  EXPECT_TRUE(none["object"].is_null());
  EXPECT_TRUE(none["hits"].empty());
}

TEST(FirstHit, DuplicateNamesAreRejected) {
  EXPECT_THROW(
      first_hit_problem(R"({"origin": [0, 0, 0], "direction": [0, 0, 1]})",
                        R"([{"name": "a", "type": "sphere", "center": [0, 0, 5], "radius": 1},
      {"name": "a", "type": "sphere", "center": [0, 0, 9], "radius": 1}])"),
      Error);
}

}  // namespace
}  // namespace raygrade
