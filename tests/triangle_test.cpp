// Triangle: the watertight reference intersection against values derived by hand.
#include "shapes/triangle.h"

#include <gtest/gtest.h>

#include <random>

#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// a = (0,0,0), b = (4,0,0), c = (0,4,0): n = (b − a) × (c − a) = (0, 0, 16), unit (0, 0, 1).
// A point (x, y, 0) has barycentric weights w_b = x/4, w_c = y/4, w_a = 1 − w_b − w_c.
const Triangle kTri({0, 0, 0}, {4, 0, 0}, {0, 4, 0});

void expect_bary(const Hit& h, double wa, double wb, double wc) {
  ASSERT_TRUE(h.barycentric);
  EXPECT_NEAR((*h.barycentric)[0], wa, 1e-15);
  EXPECT_NEAR((*h.barycentric)[1], wb, 1e-15);
  EXPECT_NEAR((*h.barycentric)[2], wc, 1e-15);
}

TEST(Triangle, HitInsideWithBarycentric) {
  auto x = kTri.intersect(ray({1, 1, 5}, {0, 0, -1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 5);
  EXPECT_EQ(x.hits[0].point, Vec3d(1, 1, 0));
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, 1));
  expect_bary(x.hits[0], 0.5, 0.25, 0.25);
}

// (3, 3) has x + y = 6 > 4: beyond edge bc.
TEST(Triangle, MissOutside) {
  EXPECT_TRUE(kTri.intersect(ray({3, 3, 5}, {0, 0, -1})).hits.empty());
}

// Closed: (2, 0) on edge ab and the vertex a both hit.
TEST(Triangle, EdgeAndVertexHit) {
  auto e = kTri.intersect(ray({2, 0, 5}, {0, 0, -1}));
  ASSERT_EQ(e.hits.size(), 1u);
  expect_bary(e.hits[0], 0.5, 0.5, 0);
  auto v = kTri.intersect(ray({0, 0, 5}, {0, 0, -1}));
  ASSERT_EQ(v.hits.size(), 1u);
  expect_bary(v.hits[0], 1, 0, 0);
}

// Oblique rays through points of edge bc (x + y = 4) with directions whose shear factors are
// not exact in binary: the closed triangle must still be hit.
TEST(Triangle, ObliqueRaysThroughAnEdgeHit) {
  const double ys[] = {0.3, 1.1, 2.0, 2.7, 3.9};
  const Vec3d ds[] = {{0.1, 0.3, -1}, {-0.7, 0.2, -0.9}, {0.33, -0.41, -1.7}, {1.3, 0.1, -0.3}};
  for (double y : ys) {
    for (const Vec3d& d : ds) {
      Vec3d p{4 - y, y, 0};
      auto x = kTri.intersect(ray(p - 3.0 * d, d));
      EXPECT_EQ(x.hits.size(), 1u) << "through " << fmt::format("{} along {}", p, d);
    }
  }
}

// Two triangles sharing the edge (0,0,0)–(1,1,0): a ray through a point of that edge hits at
// least one of them (watertightness), and with closed triangles both.
TEST(Triangle, SharedEdgeIsNeverMissedByBoth) {
  Triangle left({0, 0, 0}, {1, 1, 0}, {0, 1, 0}), right({0, 0, 0}, {1, 0, 0}, {1, 1, 0});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1);
  int both = 0;
  for (int i = 0; i < 2000; ++i) {
    double k = u(rng);
    Vec3d p{k, k, 0};
    Vec3d d{s(rng), s(rng), -0.5 - u(rng)};
    Ray r = ray(p - 2.0 * d, d);
    bool l = !left.intersect(r).hits.empty(), g = !right.intersect(r).hits.empty();
    ASSERT_TRUE(l || g) << fmt::format("{} along {}", r.origin, d);
    both += l && g;
  }
  EXPECT_EQ(both, 2000);
}

TEST(Triangle, BehindIsMissed) {
  EXPECT_TRUE(kTri.intersect(ray({1, 1, -5}, {0, 0, -1})).hits.empty());
}

TEST(Triangle, ParallelOffThePlaneMisses) {
  auto x = kTri.intersect(ray({1, 1, 5}, {1, 0, 0}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_FALSE(x.contained);
}

// In the plane z = 0: along y = 1 from x = −1 the ray crosses the triangle (contained); along
// y = 5 it never meets it; from (−1, 1) along −x it moves away from it.
TEST(Triangle, RayInThePlaneIsContainedOnlyWhenItMeetsTheTriangle) {
  EXPECT_TRUE(kTri.intersect(ray({-1, 1, 0}, {1, 0, 0})).contained);
  EXPECT_TRUE(kTri.intersect(ray({1, 1, 0}, {1, 0, 0})).contained);  // origin inside
  EXPECT_FALSE(kTri.intersect(ray({-1, 5, 0}, {1, 0, 0})).contained);
  EXPECT_FALSE(kTri.intersect(ray({-1, 1, 0}, {-1, 0, 0})).contained);
  // The segment stops before the triangle: t_max = 0.5 reaches x = −0.5 only.
  EXPECT_FALSE(kTri.intersect(ray({-1, 1, 0}, {1, 0, 0}, 0, 0.5)).contained);
  // Along the edge ab, and touching the vertex b only: both meet the closed triangle.
  EXPECT_TRUE(kTri.intersect(ray({-1, 0, 0}, {1, 0, 0})).contained);
  EXPECT_TRUE(kTri.intersect(ray({4, -1, 0}, {0, 1, 0})).contained);
  EXPECT_TRUE(kTri.intersect(ray({-1, 1, 0}, {1, 0, 0})).hits.empty());
}

// In a tilted plane with inexact coordinates: the plane through (1,0,0), (0,1,0), (0,0,1);
// the ray from (0.5, 0.5, 0) along (−0.1, −0.2, 0.3) stays in it (the components sum to 0)
// and passes through the triangle.
// In the tilted plane x + y + z = 1: the line (−0.9, 0.9, 1) + t(0.3, −0.3, 0) touches the
// triangle only at its vertex (0, 0, 1), at t = 3 (for t > 3, y < 0; for t < 3, x < 0), where
// 3·0.3 does not round to 0.9. It still meets the closed triangle; shifted off the vertex by
// 1e-9 along the plane, it misses.
TEST(Triangle, RayInATiltedPlaneTouchingAVertexIsContained) {
  Triangle t({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_TRUE(t.intersect(ray({-0.9, 0.9, 1}, {0.3, -0.3, 0})).contained);
  EXPECT_FALSE(t.intersect(ray({-0.9, 0.9 - 1e-9, 1 + 1e-9}, {0.3, -0.3, 0})).contained);
}

TEST(Triangle, RayInATiltedPlaneIsContained) {
  Triangle t({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_TRUE(t.intersect(ray({0.5, 0.5, 0}, {-0.1, -0.2, 0.3})).contained);
  EXPECT_FALSE(t.intersect(ray({2, -1, 0}, {0.1, 0.2, -0.3})).contained);
}

// Along (0, 0, −0.5) from z = 5 the plane is reached at t = 10.
TEST(Triangle, UnnormalizedDirectionKeepsItsScale) {
  auto x = kTri.intersect(ray({1, 1, 5}, {0, 0, -0.5}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 10);
}

// The plane x + y + z = 1 from the origin along (1, 2, 3): 6t = 1, t = 1/6, P = (1, 2, 3)/6;
// P = w_a(1,0,0) + w_b(0,1,0) + w_c(0,0,1), so the weights are P's coordinates.
TEST(Triangle, ObliqueHitAtOneSixth) {
  Triangle t({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  auto x = t.intersect(ray({0, 0, 0}, {1, 2, 3}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_NEAR(x.hits[0].t, 1.0 / 6, 1e-16);
  expect_bary(x.hits[0], 1.0 / 6, 2.0 / 6, 3.0 / 6);
  // The normal (1, 1, 1)/√3, correctly rounded: 1/√3 = 0.5773502691896257645..., within half
  // an ulp (5.55e-17). (1 / std::sqrt(3.0) rounds twice and lands an ulp above.)
  EXPECT_NEAR(x.hits[0].normal.x, 0.5773502691896257645, 5.6e-17);
}

// Reversing the vertex order reverses the normal: (c − a) × (b − a) = (0, 0, −16).
TEST(Triangle, NormalFollowsVertexOrder) {
  Triangle t({0, 0, 0}, {0, 4, 0}, {4, 0, 0});
  auto x = t.intersect(ray({1, 1, 5}, {0, 0, -1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, -1));
}

TEST(Triangle, IntervalIsClosed) {
  EXPECT_EQ(kTri.intersect(ray({1, 1, 5}, {0, 0, -1}, 0, 5)).hits.size(), 1u);
  EXPECT_TRUE(kTri.intersect(ray({1, 1, 5}, {0, 0, -1}, 0, 4.5)).hits.empty());
  EXPECT_TRUE(kTri.intersect(ray({1, 1, 5}, {0, 0, -1}, 5.5, 9)).hits.empty());
}

TEST(Triangle, DegenerateIsRejected) {
  EXPECT_THROW(testing::shape(R"({"type":"triangle","vertices":[[0,0,0],[1,1,1],[2,2,2]]})"),
               Error);
  EXPECT_NO_THROW(testing::shape(R"({"type":"triangle","vertices":[[0,0,0],[1,0,0],[0,1e-3,0]]})"));
}

}  // namespace
}  // namespace raygrade
