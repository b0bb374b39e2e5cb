// Sphere: the reference intersection against values derived by hand.
#include "shapes/sphere.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// Seed 000, case 1: L = (2,0,0), t_ca = 2, d² = 0, t_hc = 1, so t = 1 and 3.
TEST(Sphere, SeedCase1HitsAtOneAndThree) {
  Sphere s({2, 0, 0}, 1);
  auto x = s.intersect(ray({0, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_DOUBLE_EQ(x.hits[0].t, 1);
  EXPECT_DOUBLE_EQ(x.hits[1].t, 3);
  EXPECT_EQ(x.hits[0].normal, Vec3d(-1, 0, 0));
  EXPECT_EQ(x.hits[1].point, Vec3d(3, 0, 0));
}

TEST(Sphere, BehindOriginIsMissed) {
  Sphere s({-2, 0, 0}, 1);
  EXPECT_TRUE(s.intersect(ray({0, 0, 0}, {1, 0, 0})).hits.empty());
}

// Origin inside: only the exit at t = 4 lies ahead; its normal still points outward.
TEST(Sphere, OriginInsideHitsOnceOnTheWayOut) {
  Sphere s({0, 0, 0}, 4);
  auto x = s.intersect(ray({0, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_DOUBLE_EQ(x.hits[0].t, 4);
  EXPECT_EQ(x.hits[0].normal, Vec3d(1, 0, 0));
}

// A ray along z at x = 1 touches the unit sphere at (1, 0, 5): one hit.
TEST(Sphere, TangentRayHitsOnce) {
  Sphere s({0, 0, 5}, 1);
  auto x = s.intersect(ray({1, 0, 0}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_DOUBLE_EQ(x.hits[0].t, 5);
}

TEST(Sphere, MissPassesBeside) {
  Sphere s({4, 4, 0}, 2);  // seed 000 case 5: distance from the ray is 4·√(2/3) ≈ 3.27 > 2
  EXPECT_TRUE(s.intersect(ray({0, 0, 0}, {1, 1, 1})).hits.empty());
}

// Direction (0,0,0.25): t is in units of the given vector, so the hits at z = 8 and 12 have
// t = 32 and 48.
TEST(Sphere, UnnormalizedDirectionKeepsItsScale) {
  Sphere s({0, 0, 10}, 2);
  auto x = s.intersect(ray({0, 0, 0}, {0, 0, 0.25}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_DOUBLE_EQ(x.hits[0].t, 32);
  EXPECT_DOUBLE_EQ(x.hits[1].t, 48);
}

// Seed 001: sphere 3 at (0,1,9), r = 2: (t − 9)² = 3, t = 9 − √3.
TEST(Sphere, Seed001SphereThree) {
  Sphere s({0, 1, 9}, 2);
  auto x = s.intersect(ray({0, 0, 0}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, 9 - std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(x.hits[1].t, 9 + std::sqrt(3.0), 1e-15);
}

// A sphere of radius 1 at distance 1e8: the naive discriminant (b² − 4ac with b² ≈ 4e16)
// loses every digit; the hit at t = 1e8 − 1 must survive.
TEST(Sphere, FarSphereKeepsItsDigits) {
  Sphere s({0, 0, 1e8}, 1);
  auto x = s.intersect(ray({0, 0, 0}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  // Within 4 ulps (an ulp of 1e8 is 1.49e-8); the naive formula reports a tangent at 1e8.
  EXPECT_NEAR(x.hits[0].t, 1e8 - 1, 4 * 1.49e-8);
  EXPECT_NEAR(x.hits[1].t, 1e8 + 1, 4 * 1.49e-8);
}

// An origin 1e-3 above a sphere of radius 1e9: the near hit along −z is at t = 1e-3.
TEST(Sphere, OriginJustAboveHugeSphere) {
  Sphere s({0, 0, 0}, 1e9);
  auto x = s.intersect(ray({0, 0, 1e9 + 1.0 / 1024}, {0, 0, -1}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_EQ(x.hits[0].t, 1.0 / 1024);
}

// sphere_nearest picks the nearest root at t ≥ 0 from the signs of b = f·d and c = f·f − r²
// alone. Unit sphere at the origin, rays along ±z, one case per sign pattern; t by hand.
TEST(Sphere, NearestRootBySigns) {
  struct Case {
    Vec3d origin, direction;
    bool hit;
    double t;
  };
  const Case cases[] = {
      {{0, 0, -5}, {0, 0, 1}, true, 4},      // outside, approaching (b < 0, c > 0): near root
      {{0, 0, -5}, {0, 0, 2}, true, 2},      // the same with |d| = 2: t halves
      {{0, 0, 5}, {0, 0, 1}, false, 0},      // outside, receding (b > 0, c > 0): both behind
      {{0, 0, 0.5}, {0, 0, 1}, true, 0.5},   // inside, b > 0: the far root, ahead
      {{0, 0, 0.5}, {0, 0, -1}, true, 1.5},  // inside, b < 0: the far root, ahead
      {{0, 0, 0}, {1, 0, 0}, true, 1},       // at the centre, b = 0
      {{0.5, 0, -5}, {0, 0, 1}, true, 5 - std::sqrt(0.75)},  // off-axis, outside
  };
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const Case& c = cases[i];
    double t = -1;
    bool hit = sphere_nearest(c.origin, c.direction, Vec3d{0, 0, 0}, 1.0, t);
    EXPECT_EQ(hit, c.hit) << "case " << i;
    if (hit && c.hit) {
      EXPECT_NEAR(t, c.t, 4e-16 * c.t) << "case " << i;
    }
  }
}

TEST(Sphere, SegmentEndsAtTMax) {
  Sphere s({0, 0, 10}, 2);
  auto x = s.intersect(ray({0, 0, 0}, {0, 0, 1}, 0, 10));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 8);
}

// The origin on the surface, moving out: from (1, 0, 0) along +x the unit sphere at the origin
// gives (1 + t)² = 1, t = 0 or −2. The closed interval [0, ∞) keeps t = 0; t_min = 1e-9 (a ray
// leaving a surface) drops it.
TEST(Sphere, OriginOnTheSurfaceHitsAtZeroUnlessTMinSkipsIt) {
  Sphere s({0, 0, 0}, 1);
  auto x = s.intersect(ray({1, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 0);
  EXPECT_TRUE(s.intersect(ray({1, 0, 0}, {1, 0, 0}, 1e-9)).hits.empty());
  // Moving in from the surface: t = 0 and t = 2, at (−1, 0, 0).
  auto in = s.intersect(ray({1, 0, 0}, {-1, 0, 0}));
  ASSERT_EQ(in.hits.size(), 2u);
  EXPECT_EQ(in.hits[1].t, 2);
}

// t_min cuts off the entry: from z = 0 the sphere of radius 2 at z = 10 is met at 8 and 12;
// with t_min = 9 only the exit remains.
TEST(Sphere, TMinSkipsTheEntry) {
  Sphere s({0, 0, 10}, 2);
  auto x = s.intersect(ray({0, 0, 0}, {0, 0, 1}, 9));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 12);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, 1));
}

// Seed 000 case 4, an oblique unnormalized ray: from the origin along (1, 1, 1), the sphere of
// radius 1 at (1, 1, 0.8): 3t² − 2(2.8)t + (1 + 1 + 0.64 − 1) = 0, i.e. 3t² − 5.6t + 1.64 = 0,
// t = (5.6 ∓ √(31.36 − 19.68))/6 = (5.6 ∓ √11.68)/6.
TEST(Sphere, SeedCaseFourObliqueRay) {
  Sphere s({1, 1, 0.8}, 1);
  auto x = s.intersect(ray({0, 0, 0}, {1, 1, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, (5.6 - std::sqrt(11.68)) / 6, 1e-15);
  EXPECT_NEAR(x.hits[1].t, (5.6 + std::sqrt(11.68)) / 6, 1e-15);
}

TEST(Sphere, ZeroRadiusIsRejected) {
  EXPECT_THROW(testing::shape(R"({"type":"sphere","center":[0,0,0],"radius":0})"), Error);
}

TEST(Sphere, TypoInKeyIsNamed) {
  try {
    testing::shape(R"({"type":"sphere","center":[0,0,0],"raduis":1})");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().path, "/raduis");
    EXPECT_NE(e.diagnostic().message.find("did you mean 'radius'"), std::string::npos);
  }
}

// The geometric derivation of seed 000 case 1 shows the seed's numbers.
TEST(Sphere, GeometricDerivationMatchesSeed) {
  Sphere s({2, 0, 0}, 1);
  Derivation d = s.derive(ray({0, 0, 0}, {1, 0, 0}), "geometric", nullptr);
  EXPECT_EQ(d.find("L")->value.vector, Vec3d(2, 0, 0));
  EXPECT_EQ(d.find("t_ca")->value.scalar, 2);
  EXPECT_EQ(d.find("d2")->value.scalar, 0);
  EXPECT_EQ(d.find("t_hc")->value.scalar, 1);
  EXPECT_EQ(d.find("t0")->value.scalar, 1);
  EXPECT_EQ(d.find("t1")->value.scalar, 3);
}

}  // namespace
}  // namespace raygrade
