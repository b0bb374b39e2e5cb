// Error-free transformations and compensated products used by the reference intersector.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>

#include "math/vec3.h"

namespace raygrade {

// The customisation point of the compensated formulas: number types for which FMA and
// TwoSum give error-free transformations (the built-in floating types). Other number types
// (DoubleDouble, Mpfr, Interval) carry enough precision or rigour of their own and take the
// plain expression.
template <typename T>
inline constexpr bool kErrorFree = std::is_floating_point_v<T>;

// The unit roundoff u of a floating type (2^-53 for double): every correctly rounded operation
// has a relative error of at most u.
template <typename T>
inline constexpr T kUnitRoundoff = std::numeric_limits<T>::epsilon() / 2;

// The fast paths of the reference formulas run in plain arithmetic and keep their result when an
// a-posteriori bound on its rounding error, computed from magnitudes the formula has at hand, is
// at most kFastPathTolerance of each quantity the answer depends on (Shewchuk's filtered
// predicates; pbrt-v4's error bounds). The sign of every such quantity is then certain, so no
// decision differs from exact arithmetic on the same inputs. In double the tolerance is 2^-34
// (about 6e-11), so t is within a few times that relative to the exact t: finer than the 1e-9
// a conformance check asks, and within a few ulps times t's condition number (the hard-case
// tests check both). For float it is 32u. Otherwise the compensated formulas run. The bounds are
// derived in docs/precision.md.
template <typename T>
inline constexpr T kFastPathTolerance = std::max(T(32) * kUnitRoundoff<T>, T(0x1p-34));

// The triangle's fast path runs in plain arithmetic when its barycentric denominator does not
// cancel by more than this factor: a result at least 1/16 of the magnitudes it is computed from
// has lost at most 4 bits to rounding, so the plain result is within a few tens of ulps.
constexpr double kNoCancellation = 1.0 / 16;

// The fast paths run only on inputs whose squared magnitudes lie in [1/kFastPathRange,
// kFastPathRange]: the products of up to four such magnitudes in their error bounds then neither
// overflow nor underflow by more than the bounds' own slack. 2^(max_exponent/4 − 2): 2^254 for
// double.
template <typename T>
inline constexpr T kFastPathRange = [] {
  T x = 1;
  for (int i = 0; i < std::numeric_limits<T>::max_exponent / 4 - 2; ++i) x *= 2;
  return x;
}();

// Is x a squared magnitude the fast paths' bounds can take (see kFastPathRange)?
template <typename T>
bool in_fast_path_range(T x) {
  return x >= T(1) / kFastPathRange<T> && x <= kFastPathRange<T>;
}

// a*b - c*d with one rounding, by Kahan's algorithm with FMA (Muller et al., Handbook of
// Floating-Point Arithmetic, 2nd ed., sec. 5.3). For number types without a native FMA the
// plain expression is used: they carry enough precision of their own.
template <typename T>
T difference_of_products(T a, T b, T c, T d) {
  if constexpr (kErrorFree<T>) {
    T cd = c * d;
    T err = std::fma(-c, d, cd);
    T dop = std::fma(a, b, -cd);
    return dop + err;
  } else {
    return a * b - c * d;
  }
}

// The dot product and the cross product with fused multiply-adds where the type has them in
// hardware (float and double): fewer operations and roundings than the plain ones, and within
// the same error bounds (each fused step rounds once where the plain one rounds twice). The
// results are the same on every machine: std::fma rounds once whether or not the processor
// fuses it.
template <typename T>
inline constexpr bool kFusedArithmetic = std::is_same_v<T, float> || std::is_same_v<T, double>;

template <typename T>
[[gnu::always_inline]] inline T dot_fused(const Vec3<T>& u, const Vec3<T>& v) {
  if constexpr (kFusedArithmetic<T>) {
    return std::fma(u.x, v.x, std::fma(u.y, v.y, u.z * v.z));
  } else {
    return dot(u, v);
  }
}

template <typename T>
[[gnu::always_inline]] inline Vec3<T> cross_fused(const Vec3<T>& a, const Vec3<T>& b) {
  if constexpr (kFusedArithmetic<T>) {
    return {std::fma(a.y, b.z, -(a.z * b.y)), std::fma(a.z, b.x, -(a.x * b.z)),
            std::fma(a.x, b.y, -(a.y * b.x))};
  } else {
    return cross(a, b);
  }
}

// The cross product with every component computed by difference_of_products.
template <typename T>
Vec3<T> cross_accurate(const Vec3<T>& a, const Vec3<T>& b) {
  return {difference_of_products(a.y, b.z, a.z, b.y), difference_of_products(a.z, b.x, a.x, b.z),
          difference_of_products(a.x, b.y, a.y, b.x)};
}

// a·b + c·d + e·f (a dot product) with the products split exactly by FMA and summed with
// their errors (Ogita, Rump and Oishi's Dot2): as if computed in twice the precision.
template <typename T>
T dot_accurate(const Vec3<T>& u, const Vec3<T>& v) {
  if constexpr (kErrorFree<T>) {
    T sum = 0, err = 0;
    for (int i = 0; i < 3; ++i) {
      T p = u[i] * v[i];
      T pe = std::fma(u[i], v[i], -p);
      T s = sum + p;
      T bb = s - sum;
      err += ((sum - (s - bb)) + (p - bb)) + pe;
      sum = s;
    }
    return sum + err;
  } else {
    return dot(u, v);
  }
}

// o − c as an unevaluated sum hi + lo (exact for floating types, by Knuth's TwoSum).
template <typename T>
void difference_exact(const Vec3<T>& o, const Vec3<T>& c, Vec3<T>& hi, Vec3<T>& lo) {
  for (int i = 0; i < 3; ++i) {
    T s = o[i] - c[i];
    if constexpr (kErrorFree<T>) {
      T bb = s - o[i];
      lo[i] = (o[i] - (s - bb)) + (-c[i] - bb);
    } else {
      lo[i] = T(0);
    }
    hi[i] = s;
  }
}

// The exponent k (ilogb) of v's largest component, so that v·2^-k has it in [1, 2); 0 when it is
// zero or not finite.
template <typename T>
int scale_exponent(const Vec3<T>& v) {
  using std::abs, std::ilogb, std::isfinite;
  T m = std::max({abs(v.x), abs(v.y), abs(v.z)});
  if (!(m > T(0)) || !isfinite(m)) return 0;
  return ilogb(m);
}

// v·2^k, exact barring underflow.
template <typename T>
Vec3<T> scaled_by_power_of_two(const Vec3<T>& v, int k) {
  using std::ldexp;
  return {ldexp(v.x, k), ldexp(v.y, k), ldexp(v.z, k)};
}

// Number types whose values scale by a power of two exactly (barring underflow): the floating
// types, and double-double (math/double_double.h), whose exponent range is double's.
template <typename T>
concept ScalesByPowersOfTwo = kErrorFree<T> || requires(const T& x) {
  { ilogb(x) } -> std::same_as<int>;
  { ldexp(x, 0) } -> std::same_as<T>;
};

// |v|, also where |v|² overflows or underflows (a direction of 1e-170): then computed for v
// scaled by a power of two, exactly, and scaled back. Where |v|² is a normal number, the plain
// √(v·v).
inline double length_at_any_scale(const Vec3<double>& v) {
  double squared = length_squared(v);
  if (squared >= std::numeric_limits<double>::min() && std::isfinite(squared))
    return std::sqrt(squared);
  int k = scale_exponent(v);
  return std::ldexp(length(scaled_by_power_of_two(v, -k)), k);
}

// The compensated paths of the sphere and the cylinder scale a direction whose largest
// component is beyond 2^±kRescaleExponent into [1, 2) by a power of two, and the roots back, in
// every number type that ScalesByPowersOfTwo (double-double too, whose exponent range is
// double's):
// the squares and products of up to four magnitudes in their formulas then neither overflow nor
// underflow, at any direction scale where a double holds t.
constexpr int kRescaleExponent = 64;

// The roots of a quadratic for the direction d·2^-k, scaled back to the direction d (t·2^-k).
template <typename Roots>
Roots roots_scaled_back(Roots r, int k) {
  using std::ldexp;
  r.t0 = ldexp(r.t0, -k);
  r.t1 = ldexp(r.t1, -k);
  return r;
}

// Sign of x as a number of the same type (+1 for zero, so that q below never vanishes
// for a nonzero discriminant).
template <typename T>
T sign_of(T x) {
  return x < T(0) ? T(-1) : T(1);
}

}  // namespace raygrade
