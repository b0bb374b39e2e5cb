// Shared pieces of the primitives with circles and axes (cylinder, disk, cone, capsule): the
// tolerances of their seams and axes, and a circle's outline for their sketches.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "math/vec3.h"

namespace raygrade {

// Relative size below which |â × D| counts as zero (the ray runs parallel to the axis): a few
// ulps (double epsilon 2.2e-16) of |D|. Without it, the rounding of a tilted unit axis leaves
// D − (D·â)â at 1e-16 instead of 0, and the side's quadratic reports roots near t = 1e16.
constexpr double kAxisParallelRelative = 8 * 2.220446049250313e-16;

// Tolerance of the seams, relative to the size of the figure: a point within this of a rim
// belongs to both parts it joins (each computes it with its own rounding), and two hits
// closer than this are one. Far below any exercise's precision, far above rounding.
constexpr double kSeamRelative = 64 * 2.220446049250313e-16;

// `count` points of the circle of `radius` around `center` in the plane with the unit normal
// `unit_normal`, a sketch's outline of a disk, a cap or a cone's base.
inline std::vector<Vec3d> circle_points(const Vec3d& center, const Vec3d& unit_normal,
                                        double radius, int count) {
  Vec3d helper = std::abs(unit_normal.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  Vec3d u = normalized(cross(unit_normal, helper));
  Vec3d v = cross(unit_normal, u);
  std::vector<Vec3d> points;
  for (int i = 0; i < count; ++i) {
    double angle = 2 * std::numbers::pi * i / count;
    points.push_back(center + radius * (std::cos(angle) * u + std::sin(angle) * v));
  }
  return points;
}

}  // namespace raygrade
