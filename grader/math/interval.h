// Interval<T>: interval arithmetic with outward rounding over double, DoubleDouble or Mpfr, for
// the certified mode. An order comparison the enclosures cannot decide is counted as undecided.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "math/double_double.h"
#include "math/mpfr_number.h"

namespace raygrade {

// Directed rounding, the customisation point of each number type: Rounded<T>::op(a, b, up)
// is a bound below (up = false) or above (up = true) the exact result.
template <typename T>
struct Rounded;

// double: the result rounded to nearest, moved one ulp outward only when the error-free
// transformation shows it inexact, and only on the side the error lies (an exact result stays
// a point, so exact tangents and exact zeros are decided). Near underflow the FMA residual may
// itself round to zero, so results below kUnderflowGuard are always moved outward.
template <>
struct Rounded<double> {
  static constexpr double kUnderflowGuard = 0x1p-960;
  static double away(double r, double residual, bool up, bool guard = true) {
    double inf = std::numeric_limits<double>::infinity();
    if (std::isinf(r)) return up ? r : (r > 0 ? std::numeric_limits<double>::max() : r);
    if (guard && std::abs(r) < kUnderflowGuard) return std::nextafter(r, up ? inf : -inf);
    if (up) return residual > 0 ? std::nextafter(r, inf) : r;
    return residual < 0 ? std::nextafter(r, -inf) : r;
  }
  // TwoSum is exact even among subnormals: no guard.
  static double add(double a, double b, bool up) {
    double s, e;
    two_sum(a, b, s, e);
    if (!std::isfinite(e)) e = up ? 1 : -1;
    return away(s, e, up, false);
  }
  static double mul(double a, double b, bool up) {
    double p = a * b;
    if (a == 0 || b == 0) return p;
    return away(p, std::fma(a, b, -p), up);
  }
  static double div(double a, double b, bool up) {
    double q = a / b;
    if (a == 0) return q;
    double r = std::fma(-q, b, a);  // a − q·b: the sign of the error times the sign of b
    return away(q, b > 0 ? r : -r, up);
  }
  static double sqrt(double a, bool up) {
    double s = std::sqrt(a);
    if (a == 0) return s;
    return away(s, std::fma(-s, s, a), up);
  }
};

// Mpfr: MPFR's own directed rounding modes.
template <>
struct Rounded<Mpfr> {
  static Rounding mode(bool up) { return up ? Rounding::kUp : Rounding::kDown; }
  static Mpfr add(const Mpfr& a, const Mpfr& b, bool up) { return Mpfr::add(a, b, mode(up)); }
  static Mpfr mul(const Mpfr& a, const Mpfr& b, bool up) { return Mpfr::mul(a, b, mode(up)); }
  static Mpfr div(const Mpfr& a, const Mpfr& b, bool up) { return Mpfr::div(a, b, mode(up)); }
  static Mpfr sqrt(const Mpfr& a, bool up) { return Mpfr::sqrt(a, mode(up)); }
  static std::pair<Mpfr, Mpfr> mul_bounds(const Mpfr& a, const Mpfr& b) {
    return Mpfr::mul_down_up(a, b);
  }
  static std::pair<Mpfr, Mpfr> div_bounds(const Mpfr& a, const Mpfr& b) {
    return Mpfr::div_down_up(a, b);
  }
};

// A bound below and above of a·b (a/b): from Rounded<T>'s mul_bounds (div_bounds) when it has
// one, which computes the exact result once for both (SoftFloat), else two roundings.
template <typename R, typename T>
std::pair<T, T> mul_bounds(const T& a, const T& b) {
  if constexpr (requires { R::mul_bounds(a, b); }) {
    return R::mul_bounds(a, b);
  } else {
    return {R::mul(a, b, false), R::mul(a, b, true)};
  }
}
template <typename R, typename T>
std::pair<T, T> div_bounds(const T& a, const T& b) {
  if constexpr (requires { R::div_bounds(a, b); }) {
    return R::div_bounds(a, b);
  } else {
    return {R::div(a, b, false), R::div(a, b, true)};
  }
}

// DoubleDouble operations err by at most 15u² = 15·2^-106 < 2^-102 relative (the division,
// Joldes et al. 2017) barring underflow; each of their at most 20 double operations may add
// 2^-1075 absolute near underflow. 2^-100 relative and 2^-1060 absolute cover both with room
// for the rounding of the widening itself. Products with a zero factor are exact.
template <>
struct Rounded<DoubleDouble> {
  static constexpr double kRelativeBound = 0x1p-100;
  static constexpr double kAbsoluteBound = 0x1p-1060;
  static DoubleDouble away(DoubleDouble x, bool up) {
    double big = std::numeric_limits<double>::max();
    if (!isfinite(x)) return up ? x : DoubleDouble(x.hi > 0 ? big : x.hi);
    DoubleDouble m(std::abs(x.hi) * kRelativeBound + kAbsoluteBound);
    return up ? x + m : x - m;
  }
  static DoubleDouble add(DoubleDouble a, DoubleDouble b, bool up) {
    if (b == DoubleDouble(0)) return a;
    if (a == DoubleDouble(0)) return b;
    return away(a + b, up);
  }
  static DoubleDouble mul(DoubleDouble a, DoubleDouble b, bool up) {
    if (a == DoubleDouble(0) || b == DoubleDouble(0)) return DoubleDouble(0);
    return away(a * b, up);
  }
  static DoubleDouble div(DoubleDouble a, DoubleDouble b, bool up) {
    if (a == DoubleDouble(0)) return a;
    return away(a / b, up);
  }
  static DoubleDouble sqrt(DoubleDouble a, bool up) {
    if (a == DoubleDouble(0)) return a;
    return away(raygrade::sqrt(a), up);
  }
};

// The number of order comparisons on this thread that the enclosures could not decide.
int& interval_undecided_count();

template <typename T>
struct Interval {
  using R = Rounded<T>;
  T lo{}, hi{};

  Interval() = default;
  Interval(double x) : lo(x), hi(x) {}  // NOLINT: a double is an exact point interval
  Interval(T l, T h) : lo(std::move(l)), hi(std::move(h)) {}

  // The midpoint, rounded: the value to report.
  T mid() const { return (lo + hi) * T(0.5); }
  bool is_point() const { return lo == hi; }
  bool contains(const T& x) const { return lo <= x && x <= hi; }

  static Interval entire() {
    double inf = std::numeric_limits<double>::infinity();
    return {T(-inf), T(inf)};
  }

  friend Interval operator+(const Interval& a, const Interval& b) {
    return {R::add(a.lo, b.lo, false), R::add(a.hi, b.hi, true)};
  }
  friend Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return {R::add(a.lo, -b.hi, false), R::add(a.hi, -b.lo, true)};
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    const T* x[4][2] = {{&a.lo, &b.lo}, {&a.lo, &b.hi}, {&a.hi, &b.lo}, {&a.hi, &b.hi}};
    auto [low, high] = mul_bounds<R>(a.lo, b.lo);
    if (a.is_point() && b.is_point()) return {std::move(low), std::move(high)};
    for (int i = 1; i < 4; ++i) {
      auto [l, h] = mul_bounds<R>(*x[i][0], *x[i][1]);
      if (l < low) low = std::move(l);
      if (h > high) high = std::move(h);
    }
    return {std::move(low), std::move(high)};
  }
  friend Interval operator/(const Interval& a, const Interval& b) {
    if (b.lo <= T(0) && b.hi >= T(0)) return entire();
    Interval out = entire();
    bool first = true;
    for (const T* p : {&a.lo, &a.hi}) {
      for (const T* q : {&b.lo, &b.hi}) {
        auto [l, h] = div_bounds<R>(*p, *q);
        if (first || l < out.lo) out.lo = std::move(l);
        if (first || h > out.hi) out.hi = std::move(h);
        first = false;
      }
    }
    return out;
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }
  Interval& operator*=(const Interval& b) { return *this = *this * b; }

  // Order: certain when the enclosures are apart; otherwise undecided (counted), answered by
  // the midpoints so that the computation can go on.
  friend bool operator<(const Interval& a, const Interval& b) {
    if (a.hi < b.lo) return true;
    if (a.lo >= b.hi) return false;
    ++interval_undecided_count();
    return a.mid() < b.mid();
  }
  friend bool operator>(const Interval& a, const Interval& b) { return b < a; }
  friend bool operator<=(const Interval& a, const Interval& b) {
    if (a.hi <= b.lo) return true;
    if (a.lo > b.hi) return false;
    ++interval_undecided_count();
    return a.mid() <= b.mid();
  }
  friend bool operator>=(const Interval& a, const Interval& b) { return b <= a; }
  // Equality is identity of the enclosures (two equal points): the templates use it only to
  // spot exact zeros, and a wide interval then goes on to the order tests, which count it.
  friend bool operator==(const Interval& a, const Interval& b) {
    return a.is_point() && b.is_point() && a.lo == b.lo;
  }

  friend Interval sqrt(const Interval& a) {
    T low = a.lo < T(0) ? T(0) : a.lo;
    return {R::sqrt(low, false), R::sqrt(a.hi, true)};
  }
  friend Interval abs(const Interval& a) {
    if (a.lo >= T(0)) return a;
    if (a.hi <= T(0)) return -a;
    T m = -a.lo > a.hi ? -a.lo : a.hi;
    return {T(0), m};
  }
};

// The sign used to pick a root formula is a choice, not a decision: either sign gives the
// same roots in exact arithmetic, so it is taken from the midpoint and not counted.
template <typename T>
Interval<T> sign_of(const Interval<T>& x) {
  return x.mid() < T(0) ? Interval<T>(-1.0) : Interval<T>(1.0);
}

}  // namespace raygrade
