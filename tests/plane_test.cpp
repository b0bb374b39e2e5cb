// Plane: the reference intersection against values derived by hand.
#include "shapes/plane.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

Plane point_plane(Vec3d point, Vec3d normal) { return Plane(normal, point, std::nullopt); }
Plane d_plane(Vec3d normal, double d) { return Plane(normal, std::nullopt, d); }

// Seed 000, plane case 1: t = N·(P0 − O) / N·D = (−1·2) / (−1·1) = 2, at (2, 0, 0); the
// normal is the given one.
TEST(Plane, SeedCaseOneHitsAtTwo) {
  auto x = point_plane({2, 0, 0}, {-1, 0, 0}).intersect(ray({0, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 2);
  EXPECT_EQ(x.hits[0].point, Vec3d(2, 0, 0));
  EXPECT_EQ(x.hits[0].normal, Vec3d(-1, 0, 0));
  EXPECT_FALSE(x.contained);
}

// From (5, 0, 0) along +x the plane x = 2 lies behind: t = (−1·(2 − 5)) / (−1) = −3.
TEST(Plane, PlaneBehindIsMissed) {
  auto x = point_plane({2, 0, 0}, {-1, 0, 0}).intersect(ray({5, 0, 0}, {1, 0, 0}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_FALSE(x.contained);
}

// Parallel and off the plane: N·D = 0 and N·(O − P0) = 1 ≠ 0.
TEST(Plane, ParallelRayOffThePlaneMisses) {
  auto x = point_plane({0, 0, 0}, {0, 1, 0}).intersect(ray({0, 1, 0}, {1, 0, 0}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_FALSE(x.contained);
}

// Seed 000, plane case 2: N·D = 0 and N·(P0 − O) = 0: the ray lies in the plane.
TEST(Plane, RayInThePlaneIsContained) {
  auto x = point_plane({2, 0, 0}, {0, 1, 0}).intersect(ray({0, 0, 0}, {1, 0, 0}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_TRUE(x.contained);
}

// The d form: n = (0, 0, 2), d = −4 is the plane z = 2. From (1, 1, 2) along (3, −1, 0):
// n·D = 0 and n·O + d = 4 − 4 = 0, so the ray lies in it.
TEST(Plane, RayInTheDFormPlaneIsContained) {
  auto x = d_plane({0, 0, 2}, -4).intersect(ray({1, 1, 2}, {3, -1, 0}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_TRUE(x.contained);
  auto off = d_plane({0, 0, 2}, -4).intersect(ray({1, 1, 2.5}, {3, -1, 0}));
  EXPECT_FALSE(off.contained);
}

// A plane with inexact coefficients: n = (0.1, 0.2, 0.3), d = −1.4 passes through (1, 2, 3)
// (0.1 + 0.4 + 0.9 = 1.4). The ray from (1, 2, 3) along (3, 0, −1) has n·D = 0.3 − 0.3 = 0,
// so it lies in the plane, although n·O + d rounds to a few ulps rather than 0.
TEST(Plane, InexactDFormPlaneStillContainsTheRay) {
  auto x = d_plane({0.1, 0.2, 0.3}, -1.4).intersect(ray({1, 2, 3}, {3, 0, -1}));
  EXPECT_TRUE(x.contained);
}

// The d form: n = (0, 0, 1), d = −2 is z = 2; from (1, 1, 0) along +z, t = −(0 − 2)/1 = 2.
TEST(Plane, DFormHitsAtTwo) {
  auto x = d_plane({0, 0, 1}, -2).intersect(ray({1, 1, 0}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 2);
  EXPECT_EQ(x.hits[0].point, Vec3d(1, 1, 2));
}

// n = (2, 3, 6) (length 7) through (1, 1, 1): n·P0 = 11, n·D = 2 along +x, so t = 5.5 and the
// unit normal is (2, 3, 6)/7.
TEST(Plane, UnnormalizedNormalGivesUnitNormal) {
  auto x = point_plane({1, 1, 1}, {2, 3, 6}).intersect(ray({0, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 5.5);
  EXPECT_NEAR(x.hits[0].normal.x, 2.0 / 7, 1e-16);
  EXPECT_NEAR(x.hits[0].normal.y, 3.0 / 7, 1e-16);
  EXPECT_NEAR(x.hits[0].normal.z, 6.0 / 7, 1e-16);
}

// The direction as given: along (0.25, 0, 0) the plane x = 2 is at t = 8.
TEST(Plane, UnnormalizedDirectionKeepsItsScale) {
  auto x = point_plane({2, 0, 0}, {-1, 0, 0}).intersect(ray({0, 0, 0}, {0.25, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 8);
}

// No absolute epsilon: a direction of length 1e-10 still hits x = 2, at t = 2e10.
TEST(Plane, ShortDirectionIsNotTakenForParallel) {
  auto x = point_plane({2, 0, 0}, {-1, 0, 0}).intersect(ray({0, 0, 0}, {1e-10, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_NEAR(x.hits[0].t, 2e10, 2e10 * 1e-15);
}

// Nearly parallel is not parallel: n·D = 1e-12 relative, the plane y = 0 from y = −1 is at
// t = 1e12.
TEST(Plane, NearlyParallelRayHitsFarAway) {
  auto x = point_plane({0, 0, 0}, {0, 1, 0}).intersect(ray({0, -1, 0}, {1, 1e-12, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_NEAR(x.hits[0].t, 1e12, 1e12 * 1e-15);
}

// The origin on the plane: t = 0, which the closed interval [0, ∞) accepts.
TEST(Plane, OriginOnThePlaneHitsAtZero) {
  auto x = point_plane({2, 0, 0}, {1, 0, 0}).intersect(ray({2, 5, 5}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 0);
}

// The interval is closed at both ends: the hit at t = 2 counts for t_max = 2 and t_min = 2.
TEST(Plane, IntervalIsClosed) {
  Plane p = point_plane({2, 0, 0}, {-1, 0, 0});
  EXPECT_EQ(p.intersect(ray({0, 0, 0}, {1, 0, 0}, 0, 2)).hits.size(), 1u);
  EXPECT_EQ(p.intersect(ray({0, 0, 0}, {1, 0, 0}, 2, 5)).hits.size(), 1u);
  EXPECT_TRUE(p.intersect(ray({0, 0, 0}, {1, 0, 0}, 0, 1.5)).hits.empty());
  EXPECT_TRUE(p.intersect(ray({0, 0, 0}, {1, 0, 0}, 2.5, 5)).hits.empty());
}

TEST(Plane, BothPointAndDAreRejected) {
  EXPECT_THROW(testing::shape(R"({"type":"plane","point":[0,0,0],"normal":[0,0,1],"d":1})"), Error);
  EXPECT_THROW(testing::shape(R"({"type":"plane","normal":[0,0,1]})"), Error);
}

}  // namespace
}  // namespace raygrade
