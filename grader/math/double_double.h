// DoubleDouble: a number as the unevaluated sum hi + lo of two doubles (about 106 bits),
// by error-free transformations with FMA.
#pragma once

#include <cmath>

namespace raygrade {

// s + e = a + b exactly (Knuth's TwoSum; Muller et al., Handbook of Floating-Point
// Arithmetic, 2nd ed., sec. 4.3.2).
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

// s + e = a + b exactly, when |a| >= |b| or a = 0 (Dekker's FastTwoSum).
inline void fast_two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  e = b - (s - a);
}

// p + e = a·b exactly (barring underflow), by one FMA.
inline void two_prod(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

// The algorithms are those of Joldes, Muller and Popescu, "Tight and rigorous error bounds for
// basic building blocks of double-word arithmetic" (ACM TOMS 44(2), 2017): relative error at
// most 3u² for +, 7u² for ×, 15u² for ÷ (u = 2^-53; the remainder step of ÷ keeps that
// bound), barring underflow and overflow.
struct DoubleDouble {
  double hi = 0, lo = 0;

  constexpr DoubleDouble() = default;
  constexpr DoubleDouble(double x) : hi(x), lo(0) {}  // NOLINT: a double is exactly a DoubleDouble
  constexpr DoubleDouble(double h, double l) : hi(h), lo(l) {}

  explicit operator double() const { return hi + lo; }

  friend DoubleDouble operator+(DoubleDouble a, DoubleDouble b) {
    double sh, sl, th, tl;
    two_sum(a.hi, b.hi, sh, sl);
    two_sum(a.lo, b.lo, th, tl);
    double c = sl + th;
    double vh, vl;
    fast_two_sum(sh, c, vh, vl);
    double w = tl + vl;
    DoubleDouble r;
    fast_two_sum(vh, w, r.hi, r.lo);
    return r;
  }
  friend DoubleDouble operator-(DoubleDouble a) { return {-a.hi, -a.lo}; }
  friend DoubleDouble operator-(DoubleDouble a, DoubleDouble b) { return a + (-b); }
  friend DoubleDouble operator*(DoubleDouble a, DoubleDouble b) {
    double ch, cl;
    two_prod(a.hi, b.hi, ch, cl);
    double tl0 = a.lo * b.lo;
    double tl1 = std::fma(a.hi, b.lo, tl0);
    double cl2 = std::fma(a.lo, b.hi, tl1);
    double cl3 = cl + cl2;
    DoubleDouble r;
    fast_two_sum(ch, cl3, r.hi, r.lo);
    return r;
  }
  friend DoubleDouble operator/(DoubleDouble a, DoubleDouble b) {
    double th = 1.0 / b.hi;
    double rh = std::fma(-b.hi, th, 1.0);
    double rl = -b.lo * th;
    DoubleDouble e;
    fast_two_sum(rh, rl, e.hi, e.lo);
    DoubleDouble d = e * DoubleDouble(th);
    DoubleDouble m = d + DoubleDouble(th);  // 1/b
    // One remainder step from the quotient's leading double q₁: q₁ + (a − q₁·b)·(1/b). Without
    // it a·(1/b) kept the reciprocal's error, and −x/x came out as −1 ± 2^-106 for about half
    // of all x, which put a cone's apex (t = 1 there exactly) on the wrong nappe. When the true
    // quotient is q₁ and q₁·b is exact (q₁ = ±1, a power of two), the remainder is exactly 0
    // and the quotient comes back exactly. Otherwise what is left of the error is the rounding
    // of q₁·b (7u² of a) and of the final sum (3u²), with terms of order u³: within 15u².
    DoubleDouble q = a * m;
    double q1 = q.hi;
    DoubleDouble r = a - b * DoubleDouble(q1);
    return DoubleDouble(q1) + r * m;
  }
  DoubleDouble& operator+=(DoubleDouble b) { return *this = *this + b; }
  DoubleDouble& operator-=(DoubleDouble b) { return *this = *this - b; }
  DoubleDouble& operator*=(DoubleDouble b) { return *this = *this * b; }
  DoubleDouble& operator/=(DoubleDouble b) { return *this = *this / b; }

  // Comparisons of normalized pairs: hi decides, lo breaks ties.
  friend bool operator==(DoubleDouble a, DoubleDouble b) { return a.hi == b.hi && a.lo == b.lo; }
  friend bool operator<(DoubleDouble a, DoubleDouble b) {
    return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
  }
  friend bool operator>(DoubleDouble a, DoubleDouble b) { return b < a; }
  friend bool operator<=(DoubleDouble a, DoubleDouble b) { return !(b < a); }
  friend bool operator>=(DoubleDouble a, DoubleDouble b) { return !(a < b); }
};

inline DoubleDouble abs(DoubleDouble a) { return a.hi < 0 ? -a : a; }

// One Newton step from the double square root doubles its digits (Karp and Markstein).
inline DoubleDouble sqrt(DoubleDouble a) {
  if (a.hi <= 0) return DoubleDouble(std::sqrt(a.hi));
  double s = std::sqrt(a.hi);
  DoubleDouble ss = DoubleDouble(s) * DoubleDouble(s);
  DoubleDouble r = a - ss;
  double corr = r.hi / (2 * s);
  DoubleDouble out;
  fast_two_sum(s, corr, out.hi, out.lo);
  return out;
}

inline bool isfinite(DoubleDouble a) { return std::isfinite(a.hi) && std::isfinite(a.lo); }

// The exponent of the leading part, and a·2^k, exact barring underflow of either part: what
// the sphere's and the cylinder's rescaling of an extreme direction needs (math/robust.h).
inline int ilogb(DoubleDouble a) { return std::ilogb(a.hi); }
inline DoubleDouble ldexp(DoubleDouble a, int k) {
  DoubleDouble out;
  out.hi = std::ldexp(a.hi, k);
  out.lo = std::ldexp(a.lo, k);
  return out;
}

}  // namespace raygrade
