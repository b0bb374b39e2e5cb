// Leaving a surface: a bound on the rounding error of a computed hit point, and the origin of a
// spawned ray moved off the surface by that bound, as pbrt-v4 does (Pharr, Jakob, Humphreys,
// Physically Based Rendering, 4th ed., sec. 6.8.6), instead of a fixed epsilon.
#pragma once

#include "math/vec3.h"
#include "shapes/ray.h"
#include "shapes/transform.h"

namespace raygrade {

// γ(n) = n·u / (1 − n·u), u = 2⁻⁵³: the bound on the relative error of n successive
// floating-point roundings (Higham, Accuracy and Stability of Numerical Algorithms, sec. 3.1).
constexpr double gamma_bound(int n) {
  constexpr double kUnitRoundoff = 1.1102230246251565e-16;  // 2⁻⁵³
  return n * kUnitRoundoff / (1 - n * kUnitRoundoff);
}

// Roundings behind a hit's t: the stable root formulas of the primitives (the quadratic's
// q = −(b + sign(b)√Δ) and c/q or q/a; a plane's (n·(q − o))/(n·d)) carry at most about six
// roundings; eight leaves a margin.
constexpr int kRootRoundings = 8;
// Roundings of the point itself: o + t·d is one product and one sum per coordinate.
constexpr int kPointRoundings = 2;
// Roundings of one affine transform of a point: three products, three sums (pbrt: γ3).
constexpr int kTransformRoundings = 3;

// The bound on each coordinate's error of p = o + t·d computed from a hit of `world` at t,
// including the error of t itself (|δt| ≤ γ(kRootRoundings)·|t|). When the object is
// transformed, the rounding of the ray taken into object space (and of the object-space t)
// is carried back to the world by |A|, as pbrt bounds transformed points.
Vec3d hit_point_error(const Ray& world, double t, const Transform* transform);

// The origin of a ray leaving `point` in `direction`: moved along the unit `normal` (to the
// side the new ray leaves on) by Σ|n_i|·error_i, the distance that clears the error box,
// then rounded one ulp further away from the surface in each coordinate.
Vec3d offset_ray_origin(const Vec3d& point, const Vec3d& error, const Vec3d& normal,
                        const Vec3d& direction);

// The distance of that offset along the normal (Σ|n_i|·error_i), for the worked solution.
double offset_distance(const Vec3d& error, const Vec3d& normal);

}  // namespace raygrade
