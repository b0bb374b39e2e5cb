// Cone: the reference intersection and reading, against values worked by hand.
#include "shapes/cone.h"

#include <gtest/gtest.h>

#include <cmath>

#include "shape_error.h"
#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// Base circle of radius 1 at the origin, apex at (0, 0, 2): at height s the radius is
// 1 − s/2. The side's outward normal at (x, 0, s) with x > 0 is (2, 0, 1)/√5.
Cone open_cone() { return Cone({0, 0, 0}, {0, 0, 1}, 1, 2, false); }
Cone capped_cone() { return Cone({0, 0, 0}, {0, 0, 1}, 1, 2, true); }

const double kR5 = 1 / std::sqrt(5.0);

void expect_hit(const Hit& h, double t, Vec3d point, Vec3d normal) {
  EXPECT_EQ(h.t, t);
  EXPECT_EQ(h.point, point);
  EXPECT_NEAR(h.normal.x, normal.x, 1e-15);
  EXPECT_NEAR(h.normal.y, normal.y, 1e-15);
  EXPECT_NEAR(h.normal.z, normal.z, 1e-15);
}

// Across at height 1 from (−5, 0, 1): a = 4, b = −40, c = 99, Δ = 1600 − 1584 = 16,
// t = (40 ∓ 4)/8 = 4.5 and 5.5, at x = ∓0.5 (the radius at s = 1).
TEST(Cone, RayAcrossTheSide) {
  auto x = open_cone().intersect(ray({-5, 0, 1}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_hit(x.hits[0], 4.5, {-0.5, 0, 1}, {-2 * kR5, 0, kR5});
  expect_hit(x.hits[1], 5.5, {0.5, 0, 1}, {2 * kR5, 0, kR5});
}

// Above the apex, at height 3: the same quadratic's roots lie on the other nappe (s = 3 > h):
// a miss.
TEST(Cone, OtherNappeIsNotTheCone) {
  EXPECT_TRUE(open_cone().intersect(ray({-5, 0, 3}, {1, 0, 0})).hits.empty());
}

// Tangent at height 1, 0.5 from the axis: a = 4, b = −40, c = 100, Δ = 0: t = 5 at (0.5, 0, 1).
TEST(Cone, TangentRayHitsOnce) {
  auto x = open_cone().intersect(ray({0.5, -5, 1}, {0, 1, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_hit(x.hits[0], 5, {0.5, 0, 1}, {2 * kR5, 0, kR5});
}

// Through the apex across the axis, from (−2, 0, 2): a = 4, b = −16, c = 16, Δ = 0: t = 2 at
// the apex, whose normal is the axis.
TEST(Cone, ApexHasTheAxisAsNormal) {
  auto x = open_cone().intersect(ray({-2, 0, 2}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_hit(x.hits[0], 2, {0, 0, 2}, {0, 0, 1});
}

// Along the axis from (0, 0, −5): D⊥ = 0, a = −1, b = 14, c = −49, Δ = 0: the apex at t = 7.
// With the cap, first the base at t = 5 (normal −â).
TEST(Cone, RayAlongTheAxisMeetsCapAndApex) {
  auto open = open_cone().intersect(ray({0, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(open.hits.size(), 1u);
  expect_hit(open.hits[0], 7, {0, 0, 2}, {0, 0, 1});
  auto capped = capped_cone().intersect(ray({0, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(capped.hits.size(), 2u);
  expect_hit(capped.hits[0], 5, {0, 0, 0}, {0, 0, -1});
  expect_hit(capped.hits[1], 7, {0, 0, 2}, {0, 0, 1});
}

// Parallel to the axis 0.5 from it: a = −1, b = 14, c = −48, Δ = 4: t = 6 (s = 1, kept) and
// t = 8 (s = 3, the other nappe). The cap adds t = 5 at (0.5, 0, 0).
TEST(Cone, RayParallelToTheAxis) {
  auto open = open_cone().intersect(ray({0.5, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(open.hits.size(), 1u);
  expect_hit(open.hits[0], 6, {0.5, 0, 1}, {2 * kR5, 0, kR5});
  auto capped = capped_cone().intersect(ray({0.5, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(capped.hits.size(), 2u);
  expect_hit(capped.hits[0], 5, {0.5, 0, 0}, {0, 0, -1});
}

// Through the rim from (−2, 0, −1) along (1, 0, 1): the side and the cap both meet (−1, 0, 0)
// at t = 1, listed once (with the side's normal); then the side again at t = 7/3 (a = 3,
// b = −10, c = 7, Δ = 16).
TEST(Cone, RimBetweenSideAndCapIsListedOnce) {
  auto x = capped_cone().intersect(ray({-2, 0, -1}, {1, 0, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_hit(x.hits[0], 1, {-1, 0, 0}, {-2 * kR5, 0, kR5});
  EXPECT_NEAR(x.hits[1].t, 7.0 / 3, 1e-15);
}

// From inside at (0, 0, 1) along +x: roots t = ±0.5, only t = 0.5 ahead.
TEST(Cone, RayFromInsideLeavesOnce) {
  auto x = open_cone().intersect(ray({0, 0, 1}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_hit(x.hits[0], 0.5, {0.5, 0, 1}, {2 * kR5, 0, kR5});
}

// From (5, 0, 1) along +x the cone lies behind: roots t = −5.5 and −4.5.
TEST(Cone, ConeBehindTheOriginMisses) {
  EXPECT_TRUE(open_cone().intersect(ray({5, 0, 1}, {1, 0, 0})).hits.empty());
}

// Along a line of the side, from (−1, 0, 0) towards the apex: a = b = c = 0, contained.
TEST(Cone, RayAlongALineOfTheSideIsContained) {
  auto x = open_cone().intersect(ray({-1, 0, 0}, {1, 0, 2}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_TRUE(x.contained);
}

// The default axis is +z, and the worked derivation carries a, b, c and Δ of the first case.
TEST(Cone, DerivationStepsCarryTheHandValues) {
  auto s = testing::shape(R"({"type": "cone", "base": [0, 0, 0], "radius": 1, "height": 2})");
  Derivation d = s->derive(ray({-5, 0, 1}, {1, 0, 0}), "", nullptr);
  ASSERT_NE(d.find("a"), nullptr);
  EXPECT_EQ(d.find("a")->value.scalar, 4);
  EXPECT_EQ(d.find("b")->value.scalar, -40);
  EXPECT_EQ(d.find("c")->value.scalar, 99);
  EXPECT_EQ(d.find("discriminant")->value.scalar, 16);
  EXPECT_EQ(d.find("t0")->value.scalar, 4.5);
  EXPECT_EQ(d.find("t1")->value.scalar, 5.5);
}

// Reading: a missing height and a zero radius are errors at their paths.
TEST(Cone, BadParametersAreErrorsAtTheirPaths) {
  EXPECT_EQ(
      testing::shape_error_path(R"({"type": "cone", "base": [0, 0, 0], "radius": 0, "height": 1})"),
      "/radius");
  EXPECT_EQ(testing::shape_error_path(
                R"({"type": "cone", "base": [0, 0, 0], "radius": 1, "height": -1})"),
            "/height");
}

}  // namespace
}  // namespace raygrade
