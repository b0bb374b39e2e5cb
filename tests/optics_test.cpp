// Reflection, Snell's law and the Phong terms against values worked by hand.
#include "scenes/optics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raygrade {
namespace {

TEST(Optics, ReflectMirrorsAboutTheNormal) {
  Vec3d r = reflect({1, -1, 0}, {0, 1, 0});
  EXPECT_EQ(r, Vec3d(1, 1, 0));
  EXPECT_EQ(reflect({1, -1, 0}, {0, -1, 0}), Vec3d(1, 1, 0));  // either orientation
}

// 30° from air into glass (n = 1.5): sin θt = 0.5/1.5 = 1/3.
TEST(Optics, SnellIntoGlass) {
  double s = 0.5, c = std::sqrt(3.0) / 2;
  Refraction r = refract({s, -c, 0}, {0, 1, 0}, 1, 1.5);
  ASSERT_FALSE(r.total_internal_reflection);
  EXPECT_NEAR(r.direction.x, 1.0 / 3, 1e-15);
  EXPECT_NEAR(r.direction.y, -std::sqrt(8.0) / 3, 1e-15);
  EXPECT_NEAR(length(r.direction), 1, 1e-15);
}

// 45° from glass into air: sin θt would be 1.5·√2/2 ≈ 1.06 > 1.
TEST(Optics, TotalInternalReflectionBeyondTheCriticalAngle) {
  double h = std::sqrt(0.5);
  Refraction r = refract({h, -h, 0}, {0, 1, 0}, 1.5, 1);
  EXPECT_TRUE(r.total_internal_reflection);
  EXPECT_NEAR(r.k, 1 - 2.25 * 0.5, 1e-15);
  // asin(1/1.5) = 41.8103149°.
  EXPECT_NEAR(*critical_angle_degrees(1.5, 1), 41.8103148957786, 1e-10);
  EXPECT_FALSE(critical_angle_degrees(1, 1.5).has_value());
  // Just below the critical angle (40°) the ray still leaves.
  double a = 40 * 3.141592653589793 / 180;
  EXPECT_FALSE(
      refract({std::sin(a), -std::cos(a), 0}, {0, 1, 0}, 1.5, 1).total_internal_reflection);
}

// N = (0,1,0), L = (0.6, 0.8, 0), V = (−0.6, 0.8, 0): R = 2·0.8·N − L = (−0.6, 0.8, 0) = V,
// so R·V = 1; diffuse = 0.5·2·0.8 = 0.8, specular = 0.25·2·1^n = 0.5.
TEST(Optics, PhongTermsOfOneLight) {
  PhongLight p = phong_light({0, 1, 0}, {0.6, 0.8, 0}, {-0.6, 0.8, 0}, 2, 0.5, 0.25, 7);
  EXPECT_NEAR(p.n_dot_l, 0.8, 1e-15);
  EXPECT_NEAR(p.r_dot_v, 1, 1e-15);
  EXPECT_NEAR(p.diffuse, 0.8, 1e-15);
  EXPECT_NEAR(p.specular, 0.5, 1e-14);
  // A light below the surface gives nothing.
  PhongLight q = phong_light({0, 1, 0}, {0.6, -0.8, 0}, {-0.6, 0.8, 0}, 2, 0.5, 0.25, 7);
  EXPECT_EQ(q.diffuse, 0);
  EXPECT_EQ(q.specular, 0);
}

}  // namespace
}  // namespace raygrade
