// Box: the slab method against values derived by hand, with edges and zero components.
#include "shapes/box.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// min (0, 0, 0), max (1, 2, 3).
const Box kBox({0, 0, 0}, {1, 2, 3});

// From (−1, 1, 1) along +x: the x slab is t ∈ [1, 2]; y and z never change (d = 0) and lie
// inside their slabs. Enter at x = 0 (normal −x), leave at x = 1 (normal +x).
TEST(Box, ThroughHitsTwice) {
  auto x = kBox.intersect(ray({-1, 1, 1}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[0].point, Vec3d(0, 1, 1));
  EXPECT_EQ(x.hits[0].normal, Vec3d(-1, 0, 0));
  EXPECT_EQ(x.hits[1].t, 2);
  EXPECT_EQ(x.hits[1].normal, Vec3d(1, 0, 0));
}

// From (−1, −1, −1) along (1, 1.5, 2): x ∈ [1, 2], y ∈ [2/3, 2], z ∈ [1/2, 2]; enter at
// t = 1 through x = 0, leave at t = 2 where all three high ends meet (the corner (1, 2, 3)).
TEST(Box, ObliqueThroughACorner) {
  auto x = kBox.intersect(ray({-1, -1, -1}, {1, 1.5, 2}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[0].point, Vec3d(0, 0.5, 1));
  EXPECT_EQ(x.hits[1].t, 2);
  EXPECT_EQ(x.hits[1].point, Vec3d(1, 2, 3));
}

TEST(Box, MissBesideAndBehind) {
  EXPECT_TRUE(kBox.intersect(ray({-1, 3, 1}, {1, 0, 0})).hits.empty());
  EXPECT_TRUE(kBox.intersect(ray({2, 1, 1}, {1, 0, 0})).hits.empty());
}

// From the inside along −y: only the exit at y = 0, t = 1, normal −y.
TEST(Box, OriginInsideHitsOnTheWayOut) {
  auto x = kBox.intersect(ray({0.5, 1, 1.5}, {0, -1, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, -1, 0));
}

// Parallel to the x and z slabs: inside them it crosses the y slab at t = 1 and 3; outside
// the x slab it misses.
TEST(Box, ParallelToSlabs) {
  auto x = kBox.intersect(ray({0.5, -1, 1}, {0, 1, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[1].t, 3);
  EXPECT_TRUE(kBox.intersect(ray({2, -1, 1}, {0, 1, 0})).hits.empty());
}

// d_x = 0 with the origin on the slab plane x = 0 (the face): (0 − 0)/0 would be NaN; the
// closed box is touched along the face, from y = 0 (t = 1) to y = 2 (t = 3).
TEST(Box, SlidingAlongAFaceHitsWhereItEntersAndLeaves) {
  auto x = kBox.intersect(ray({0, -1, 1}, {0, 1, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[0].point, Vec3d(0, 0, 1));
  EXPECT_EQ(x.hits[1].t, 3);
  EXPECT_EQ(x.hits[1].point, Vec3d(0, 2, 1));
  // Along an edge (x = 0 and z = 3, both on slab planes with zero direction).
  EXPECT_EQ(kBox.intersect(ray({0, -1, 3}, {0, 1, 0})).hits.size(), 2u);
  // Just outside the face: a miss.
  EXPECT_TRUE(kBox.intersect(ray({-1e-12, -1, 1}, {0, 1, 0})).hits.empty());
}

// From (0, −1, 1) along (1, 1, 0) the line touches the box only along the edge x = 1, y = 0
// at t = 1: x ∈ [0, 1] and y ∈ [1, 3] share only t = 1. One hit, not two.
TEST(Box, GrazingAnEdgeHitsOnce) {
  auto x = kBox.intersect(ray({0, -1, 1}, {1, 1, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[0].point, Vec3d(1, 0, 1));
}

// The same kind of edge graze with inexact numbers: from (1.3, 0.1, 1) along (−0.3, −0.1, 0)
// the line touches the edge x = 1, y = 0 at t = 1; the x slab's end rounds to
// 0.30000000000000004/0.3 = 1.0000000000000002 while the y slab's is exactly 1. Closed: one
// hit, in both directions along the line.
TEST(Box, InexactEdgeGrazeHitsOnce) {
  auto x = kBox.intersect(ray({1.3, 0.1, 1}, {-0.3, -0.1, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_NEAR(x.hits[0].t, 1, 1e-15);
  auto back = kBox.intersect(ray({0.7, -0.1, 1}, {0.3, 0.1, 0}));
  ASSERT_EQ(back.hits.size(), 1u);
  EXPECT_NEAR(back.hits[0].t, 1, 1e-15);
}

// Through an edge into the box: from (−1, −1, 1) along (1, 1, 0) the edge x = 0, y = 0 is met
// at t = 1 (one hit there, not one per face), then the face x = 1 at t = 2.
TEST(Box, EnteringThroughAnEdgeIsListedOnce) {
  auto x = kBox.intersect(ray({-1, -1, 1}, {1, 1, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[1].t, 2);
  EXPECT_EQ(x.hits[1].normal, Vec3d(1, 0, 0));
}

// Along (0.25, 0, 0) from x = −1: x = 0 and 1 at t = 4 and 8.
TEST(Box, UnnormalizedDirectionKeepsItsScale) {
  auto x = kBox.intersect(ray({-1, 1, 1}, {0.25, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 4);
  EXPECT_EQ(x.hits[1].t, 8);
}

TEST(Box, IntervalIsClosed) {
  EXPECT_EQ(kBox.intersect(ray({-1, 1, 1}, {1, 0, 0}, 1, 2)).hits.size(), 2u);
  auto x = kBox.intersect(ray({-1, 1, 1}, {1, 0, 0}, 1.5, 5));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 2);
  EXPECT_TRUE(kBox.intersect(ray({-1, 1, 1}, {1, 0, 0}, 0, 0.5)).hits.empty());
}

// The template itself: no NaN for a zero component on a slab plane.
TEST(Box, SlabIntervalHasNoNaN) {
  auto s = slab_interval(Vec3d{0, -1, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 0}, Vec3d{1, 2, 3});
  EXPECT_TRUE(s.hit);
  EXPECT_EQ(s.t_enter, 1);
  EXPECT_EQ(s.t_exit, 3);
  EXPECT_EQ(s.enter_axis, 1);
}

TEST(Box, FlatBoxIsRejected) {
  EXPECT_THROW(testing::shape(R"({"type":"box","min":[0,0,0],"max":[1,0,1]})"), Error);
}

}  // namespace
}  // namespace raygrade
