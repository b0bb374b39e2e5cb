// Cylinder: infinite, finite and capped, against values derived by hand.
#include "shapes/cylinder.h"

#include <gtest/gtest.h>

#include <random>

#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// The unit cylinder around the z axis: x² + y² = 1.
const Cylinder kInfinite({0, 0, 0}, {0, 0, 1}, 1, std::nullopt, false);
// The same, from z = 0 to z = 2, with and without caps.
const Cylinder kCapped({0, 0, 0}, {0, 0, 1}, 1, 2.0, true);
const Cylinder kOpen({0, 0, 0}, {0, 0, 1}, 1, 2.0, false);

// From (−3, 0, 0.5) along +x: (t − 3)² = 1, t = 2 and 4, at x = −1 and 1.
TEST(Cylinder, ThroughHitsTwiceWithOutwardNormals) {
  auto x = kInfinite.intersect(ray({-3, 0, 0.5}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 2);
  EXPECT_EQ(x.hits[1].t, 4);
  EXPECT_EQ(x.hits[0].normal, Vec3d(-1, 0, 0));
  EXPECT_EQ(x.hits[1].normal, Vec3d(1, 0, 0));
}

TEST(Cylinder, MissPassesBeside) {
  EXPECT_TRUE(kInfinite.intersect(ray({-3, 2, 0}, {1, 0, 0})).hits.empty());
}

// y = 1 touches the cylinder at (0, 1, 0): (t − 3)² + 1 = 1, a double root t = 3.
TEST(Cylinder, TangentHitsOnce) {
  auto x = kInfinite.intersect(ray({-3, 1, 0}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 3);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 1, 0));
}

// From the axis along (1, 1, 1): (t² + t²) = 1, t = 1/√2, on the way out.
TEST(Cylinder, OriginInsideHitsOnTheWayOut) {
  auto x = kInfinite.intersect(ray({0, 0, 0}, {1, 1, 1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_NEAR(x.hits[0].t, std::sqrt(0.5), 2e-16);
  EXPECT_NEAR(x.hits[0].normal.x, std::sqrt(0.5), 2e-16);
  EXPECT_EQ(x.hits[0].normal.z, 0);
}

TEST(Cylinder, BehindIsMissed) {
  EXPECT_TRUE(kInfinite.intersect(ray({3, 0, 0}, {1, 0, 0})).hits.empty());
}

// Along (0.5, 0, 0): t is in units of the given vector, so x = −1 and 1 come at t = 4 and 8.
TEST(Cylinder, UnnormalizedDirectionKeepsItsScale) {
  auto x = kInfinite.intersect(ray({-3, 0, 0}, {0.5, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 4);
  EXPECT_EQ(x.hits[1].t, 8);
}

// Parallel to the axis, inside or outside: the infinite side is never crossed.
TEST(Cylinder, ParallelToTheAxisMissesTheInfiniteSide) {
  EXPECT_TRUE(kInfinite.intersect(ray({0.5, 0, -3}, {0, 0, 1})).hits.empty());
  EXPECT_TRUE(kInfinite.intersect(ray({2, 0, -3}, {0, 0, 1})).hits.empty());
}

// A tilted axis (1, 1, 0), whose unit vector is inexact: a ray parallel to it, inside, at
// distance √0.5 from the axis, must not report the huge spurious roots that the rounding of
// D − (D·A)A produces.
TEST(Cylinder, ParallelToATiltedAxisHasNoSpuriousHits) {
  Cylinder c({0, 0, 0}, {1, 1, 0}, 1, std::nullopt, false);
  EXPECT_TRUE(c.intersect(ray({0.5, -0.5, 0}, {1, 1, 0})).hits.empty());
  EXPECT_TRUE(c.intersect(ray({0.5, -0.5, 0}, {3, 3, 0})).hits.empty());
  Cylinder tilted({1, 2, 3}, {0.3, 0.4, 1.2}, 0.5, std::nullopt, false);
  EXPECT_TRUE(tilted.intersect(ray({1.1, 2, 3}, {0.3, 0.4, 1.2})).hits.empty());
}

// A ray lying on the side, parallel to the axis: it meets the infinite cylinder along a whole
// line (contained, no hits); the finite open one from rim to rim, at z = 0 and z = 2.
TEST(Cylinder, RayOnTheSideAlongTheAxis) {
  auto inf = kInfinite.intersect(ray({1, 0, -3}, {0, 0, 1}));
  EXPECT_TRUE(inf.hits.empty());
  EXPECT_TRUE(inf.contained);
  auto open = kOpen.intersect(ray({1, 0, -3}, {0, 0, 1}));
  ASSERT_EQ(open.hits.size(), 2u);
  EXPECT_EQ(open.hits[0].t, 3);
  EXPECT_EQ(open.hits[1].t, 5);
  EXPECT_EQ(open.hits[0].normal, Vec3d(1, 0, 0));
  auto capped = kCapped.intersect(ray({1, 0, -3}, {0, 0, 1}));
  ASSERT_EQ(capped.hits.size(), 2u);
  EXPECT_EQ(capped.hits[0].t, 3);
  EXPECT_EQ(capped.hits[1].t, 5);
}

// Along the axis of the capped cylinder: the bottom cap at t = 3 (normal −z), the top at 5.
// cylinder_side_nearest picks the nearest root at t ≥ 0 from the signs of b = f⊥·d⊥ and
// c = |f⊥|² − r², as the sphere does. Unit cylinder along z through the origin; t by hand.
TEST(Cylinder, NearestRootBySigns) {
  struct Case {
    Vec3d origin, direction;
    bool hit;
    double t;
  };
  const Case cases[] = {
      {{-5, 0, 0}, {1, 0, 0}, true, 4},      // outside, approaching: near root
      {{-5, 0, 2}, {1, 0, 1}, true, 4},      // the same with a component along the axis
      {{5, 0, 0}, {1, 0, 0}, false, 0},      // outside, receding: both roots behind
      {{0.5, 0, 3}, {1, 0, 0}, true, 0.5},   // inside, b > 0: the far root, ahead
      {{0.5, 0, 3}, {-1, 0, 0}, true, 1.5},  // inside, b < 0: the far root, ahead
      {{0, 0, 7}, {0, 2, 0}, true, 0.5},     // on the axis, b = 0, |d| = 2
      {{0, 0, 0}, {0, 0, 1}, false, 0},      // along the axis: no side hit
  };
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const Case& c = cases[i];
    double t = -1;
    bool hit = cylinder_side_nearest(c.origin, c.direction, Vec3d{0, 0, 0}, Vec3d{0, 0, 1}, 1.0, t);
    EXPECT_EQ(hit, c.hit) << "case " << i;
    if (hit && c.hit) {
      EXPECT_NEAR(t, c.t, 4e-16 * c.t) << "case " << i;
    }
  }
}

TEST(Cylinder, CapsAlongTheAxis) {
  auto x = kCapped.intersect(ray({0, 0, -3}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 3);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, -1));
  EXPECT_EQ(x.hits[1].t, 5);
  EXPECT_EQ(x.hits[1].normal, Vec3d(0, 0, 1));
  EXPECT_TRUE(kOpen.intersect(ray({0, 0, -3}, {0, 0, 1})).hits.empty());
}

// Finite height: from (−3, 0, 3) along +x the side is met at z = 3, above the top (z = 2).
TEST(Cylinder, FiniteHeightRejectsSideHitsAbove) {
  EXPECT_TRUE(kOpen.intersect(ray({-3, 0, 3}, {1, 0, 0})).hits.empty());
  EXPECT_EQ(kOpen.intersect(ray({-3, 0, 2}, {1, 0, 0})).hits.size(), 2u);  // on the top rim
}

// Through the top rim at (0.6, 0.8, 2) (inexact in binary) from (1.1, 1.1, 3) along
// (−0.5, −0.3, −1): the rim at t = 1 is listed once, then the bottom cap at t = 3, at
// (−0.4, 0.2, 0), inside its disc.
TEST(Cylinder, RimHitIsListedOnce) {
  auto x = kCapped.intersect(ray({1.1, 1.1, 3}, {-0.5, -0.3, -1}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, 1, 1e-15);
  EXPECT_NEAR(x.hits[1].t, 3, 1e-15);
  EXPECT_EQ(x.hits[1].normal, Vec3d(0, 0, -1));
  auto open = kOpen.intersect(ray({1.1, 1.1, 3}, {-0.5, -0.3, -1}));
  ASSERT_EQ(open.hits.size(), 1u);  // the rim, then out through the open bottom
  EXPECT_NEAR(open.hits[0].t, 1, 1e-15);
}

// Rays through random points of the top rim towards random points inside the cylinder enter
// at the rim and leave elsewhere: exactly two hits, the first at the rim point.
TEST(Cylinder, RaysThroughTheRimEnterOnceAndLeaveOnce) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0, 6.283185307179586), u(0, 1);
  for (int i = 0; i < 1000; ++i) {
    double a = angle(rng);
    Vec3d rim{std::cos(a), std::sin(a), 2};
    double ra = 0.8 * std::sqrt(u(rng)), b = angle(rng);
    Vec3d inside{ra * std::cos(b), ra * std::sin(b), 0.2 + 1.6 * u(rng)};
    Vec3d d = inside - rim;
    auto x = kCapped.intersect(ray(rim - d, d));
    ASSERT_EQ(x.hits.size(), 2u) << fmt::format("through {} along {}", rim, d);
    EXPECT_NEAR(x.hits[0].t, 1, 1e-9);
  }
}

// A tilted finite cylinder: base (1, 2, 3), axis (2, 0, 0) (unit (1, 0, 0)), radius 0.5,
// height 4. From (3, 2, 6) along −z: (z − 3)² = 0.25, z = 3.5 and 2.5, t = 2.5 and 3.5.
TEST(Cylinder, AxisIsNormalizedHeightAlongTheUnitAxis) {
  Cylinder c({1, 2, 3}, {2, 0, 0}, 0.5, 4.0, false);
  auto x = c.intersect(ray({3, 2, 6}, {0, 0, -1}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 2.5);
  EXPECT_EQ(x.hits[1].t, 3.5);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, 1));
  EXPECT_TRUE(c.intersect(ray({5.5, 2, 6}, {0, 0, -1})).hits.empty());  // beyond height 4
}

TEST(Cylinder, IntervalIsClosed) {
  auto x = kInfinite.intersect(ray({-3, 0, 0}, {1, 0, 0}, 2, 3));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 2);
  EXPECT_EQ(kInfinite.intersect(ray({-3, 0, 0}, {1, 0, 0}, 0, 4)).hits.size(), 2u);
}

TEST(Cylinder, CapsNeedAHeight) {
  EXPECT_THROW(testing::shape(R"({"type":"cylinder","base":[0,0,0],"radius":1,"capped":true})"),
               Error);
}

}  // namespace
}  // namespace raygrade
