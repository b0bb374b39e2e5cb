// The optics of one surface point: the mirror direction, Snell's law with total internal
// reflection, and the Phong terms of one light.
#pragma once

#include <numbers>
#include <optional>

#include "math/vec3.h"

namespace raygrade {

// A vector typed as unit length is taken as unit when |n| is within this of 1: decimals such
// as (0.6, 0.8, 0) are off by an ulp or two, far below; anything not meant as unit, far above.
constexpr double kUnitLengthTolerance = 1e-12;

// r = d − 2(d·n)n for a unit normal n (either orientation gives the same r).
Vec3d reflect(const Vec3d& d, const Vec3d& n);

struct Refraction {
  double eta = 1;    // η = n1/n2
  double cos_i = 1;  // cos θi = −d̂·n, n facing the incoming ray
  double k = 1;      // 1 − η²(1 − cos²θi) = cos²θt; negative: total internal reflection
  bool total_internal_reflection = false;
  Vec3d direction{};  // t = η·d̂ + (η·cos θi − √k)·n, unit; zero under total reflection
};

// Snell's law n1 sin θi = n2 sin θt in vector form, for a unit direction `d` and a unit normal
// `n` that faces the incoming ray (d·n < 0).
Refraction refract(const Vec3d& d, const Vec3d& n, double n1, double n2);

// The critical angle asin(n2/n1) in degrees, when light goes into a lower index (n1 > n2).
std::optional<double> critical_angle_degrees(double n1, double n2);

// The Phong terms of one light at a point: diffuse k_d·I_p·(N·L), specular k_s·I_p·(R·V)^n with
// R = 2(N·L)N − L; both 0 when N·L ≤ 0. N, L and V are unit vectors.
struct PhongLight {
  double n_dot_l = 0;
  Vec3d r{};
  double r_dot_v = 0;
  double diffuse = 0;
  double specular = 0;
};
PhongLight phong_light(const Vec3d& n, const Vec3d& l, const Vec3d& v, double intensity, double k_d,
                       double k_s, double shininess);

// An angle in radians, in degrees.
inline double degrees(double radians) { return radians * 180 / std::numbers::pi; }

}  // namespace raygrade
