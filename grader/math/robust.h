// Error-free transformations and compensated products used by the reference intersector.
#pragma once

#include <cmath>

#include "math/vec3.h"

namespace raygrade {

// a*b - c*d with one rounding, by Kahan's algorithm with FMA (Muller et al., Handbook of
// Floating-Point Arithmetic, 2nd ed., sec. 5.3). For number types without a native FMA the
// plain expression is used: they carry enough precision of their own.
template <typename T>
T difference_of_products(T a, T b, T c, T d) {
  if constexpr (std::is_floating_point_v<T>) {
    T cd = c * d;
    T err = std::fma(-c, d, cd);
    T dop = std::fma(a, b, -cd);
    return dop + err;
  } else {
    return a * b - c * d;
  }
}

// The cross product with every component computed by difference_of_products.
template <typename T>
Vec3<T> cross_accurate(const Vec3<T>& a, const Vec3<T>& b) {
  return {difference_of_products(a.y, b.z, a.z, b.y), difference_of_products(a.z, b.x, a.x, b.z),
          difference_of_products(a.x, b.y, a.y, b.x)};
}

// Sign of x as a number of the same type (+1 for zero, so that q below never vanishes
// for a nonzero discriminant).
template <typename T>
T sign_of(T x) {
  return x < T(0) ? T(-1) : T(1);
}

}  // namespace raygrade
