// Mpfr: an MPFR number at the precision of the current MpfrPrecision scope, with the
// operators the intersection templates use (ground truth and the top of the precision ladder).
// Built with RAYGRADE_SOFT_MPFR (WebAssembly, where there is no MPFR), the same class computes
// with SoftFloat instead, rounding every operation the way MPFR does (docs/web.md).
#pragma once

#include <utility>

#include "math/rounding.h"

#if RAYGRADE_SOFT_MPFR
#include "math/soft_float.h"
#else
#include <mpfr.h>
#endif

namespace raygrade {

// The precision, in bits, of Mpfr numbers created on this thread. 256 bits by default: far
// beyond the 106 of DoubleDouble, so its rounding never shows in a double result.
int mpfr_precision();

// Sets the precision of Mpfr numbers created on this thread while it lives.
class MpfrPrecision {
 public:
  explicit MpfrPrecision(int bits);
  ~MpfrPrecision();
  MpfrPrecision(const MpfrPrecision&) = delete;
  MpfrPrecision& operator=(const MpfrPrecision&) = delete;

 private:
  int saved_;
};

#if RAYGRADE_SOFT_MPFR

// Every operation rounds its exact result once to the current precision, as MPFR rounds to
// the precision of a destination created in the same scope.
class Mpfr {
 public:
  Mpfr() = default;
  Mpfr(double x) : v_(x, mpfr_precision()) {}  // NOLINT

  explicit operator double() const { return v_.to_double(Rounding::kNearest); }
  double to_double(Rounding r) const { return v_.to_double(r); }

  static Mpfr add(const Mpfr& a, const Mpfr& b, Rounding r) {
    return Mpfr(SoftFloat::add(a.v_, b.v_, mpfr_precision(), r));
  }
  static Mpfr mul(const Mpfr& a, const Mpfr& b, Rounding r) {
    return Mpfr(SoftFloat::mul(a.v_, b.v_, mpfr_precision(), r));
  }
  static Mpfr div(const Mpfr& a, const Mpfr& b, Rounding r) {
    return Mpfr(SoftFloat::div(a.v_, b.v_, mpfr_precision(), r));
  }
  static Mpfr sqrt(const Mpfr& a, Rounding r) {
    return Mpfr(SoftFloat::sqrt(a.v_, mpfr_precision(), r));
  }
  // a·b and a/b rounded down and up (an interval's bounds) from one exact product (quotient).
  static std::pair<Mpfr, Mpfr> mul_down_up(const Mpfr& a, const Mpfr& b) {
    auto [down, up] = SoftFloat::mul_down_up(a.v_, b.v_, mpfr_precision());
    return {Mpfr(std::move(down)), Mpfr(std::move(up))};
  }
  static std::pair<Mpfr, Mpfr> div_down_up(const Mpfr& a, const Mpfr& b) {
    auto [down, up] = SoftFloat::div_down_up(a.v_, b.v_, mpfr_precision());
    return {Mpfr(std::move(down)), Mpfr(std::move(up))};
  }

  friend Mpfr operator+(const Mpfr& a, const Mpfr& b) { return add(a, b, Rounding::kNearest); }
  friend Mpfr operator-(const Mpfr& a, const Mpfr& b) {
    return Mpfr(SoftFloat::sub(a.v_, b.v_, mpfr_precision(), Rounding::kNearest));
  }
  friend Mpfr operator*(const Mpfr& a, const Mpfr& b) { return mul(a, b, Rounding::kNearest); }
  friend Mpfr operator/(const Mpfr& a, const Mpfr& b) { return div(a, b, Rounding::kNearest); }
  friend Mpfr operator-(const Mpfr& a) { return Mpfr(SoftFloat::neg(a.v_, mpfr_precision())); }
  Mpfr& operator+=(const Mpfr& b) { return *this = *this + b; }
  Mpfr& operator-=(const Mpfr& b) { return *this = *this - b; }
  Mpfr& operator*=(const Mpfr& b) { return *this = *this * b; }

  friend bool operator==(const Mpfr& a, const Mpfr& b) { return order(a, b) == 0; }
  friend bool operator<(const Mpfr& a, const Mpfr& b) { return order(a, b) == -1; }
  friend bool operator>(const Mpfr& a, const Mpfr& b) { return order(a, b) == 1; }
  friend bool operator<=(const Mpfr& a, const Mpfr& b) { return order(a, b) <= 0; }
  friend bool operator>=(const Mpfr& a, const Mpfr& b) {
    int o = order(a, b);
    return o == 0 || o == 1;
  }

  friend Mpfr sqrt(const Mpfr& a) { return sqrt(a, Rounding::kNearest); }
  friend Mpfr abs(const Mpfr& a) { return Mpfr(SoftFloat::abs(a.v_, mpfr_precision())); }
  friend bool isfinite(const Mpfr& a) { return a.v_.is_finite(); }

 private:
  explicit Mpfr(SoftFloat v) : v_(std::move(v)) {}
  // −1, 0 or 1; 2 when either is NaN (every comparison is then false, as MPFR's).
  static int order(const Mpfr& a, const Mpfr& b) {
    bool unordered = false;
    int c = SoftFloat::compare(a.v_, b.v_, unordered);
    return unordered ? 2 : c;
  }
  SoftFloat v_;
};

#else

class Mpfr {
 public:
  Mpfr() { mpfr_init2(v_, mpfr_precision()), mpfr_set_zero(v_, 1); }
  Mpfr(double x) { mpfr_init2(v_, mpfr_precision()), mpfr_set_d(v_, x, MPFR_RNDN); }  // NOLINT
  Mpfr(const Mpfr& o) { mpfr_init2(v_, mpfr_get_prec(o.v_)), mpfr_set(v_, o.v_, MPFR_RNDN); }
  Mpfr(Mpfr&& o) noexcept {
    mpfr_init2(v_, mpfr_get_prec(o.v_));
    mpfr_swap(v_, o.v_);
  }
  Mpfr& operator=(const Mpfr& o) {
    if (this != &o) {
      mpfr_set_prec(v_, mpfr_get_prec(o.v_));
      mpfr_set(v_, o.v_, MPFR_RNDN);
    }
    return *this;
  }
  Mpfr& operator=(Mpfr&& o) noexcept {
    mpfr_swap(v_, o.v_);
    return *this;
  }
  ~Mpfr() { mpfr_clear(v_); }

  explicit operator double() const { return mpfr_get_d(v_, MPFR_RNDN); }
  double to_double(Rounding r) const { return mpfr_get_d(v_, mode(r)); }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }

  static Mpfr add(const Mpfr& a, const Mpfr& b, Rounding r) { return apply(mpfr_add, a, b, r); }
  static Mpfr mul(const Mpfr& a, const Mpfr& b, Rounding r) { return apply(mpfr_mul, a, b, r); }
  static Mpfr div(const Mpfr& a, const Mpfr& b, Rounding r) { return apply(mpfr_div, a, b, r); }
  static Mpfr sqrt(const Mpfr& a, Rounding r) {
    Mpfr s;
    mpfr_sqrt(s.v_, a.v_, mode(r));
    return s;
  }
  // a·b and a/b rounded down and up (an interval's bounds): two MPFR operations.
  static std::pair<Mpfr, Mpfr> mul_down_up(const Mpfr& a, const Mpfr& b) {
    return {mul(a, b, Rounding::kDown), mul(a, b, Rounding::kUp)};
  }
  static std::pair<Mpfr, Mpfr> div_down_up(const Mpfr& a, const Mpfr& b) {
    return {div(a, b, Rounding::kDown), div(a, b, Rounding::kUp)};
  }

  friend Mpfr operator+(const Mpfr& a, const Mpfr& b) { return apply(mpfr_add, a, b); }
  friend Mpfr operator-(const Mpfr& a, const Mpfr& b) { return apply(mpfr_sub, a, b); }
  friend Mpfr operator*(const Mpfr& a, const Mpfr& b) { return apply(mpfr_mul, a, b); }
  friend Mpfr operator/(const Mpfr& a, const Mpfr& b) { return apply(mpfr_div, a, b); }
  friend Mpfr operator-(const Mpfr& a) {
    Mpfr r;
    mpfr_neg(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  Mpfr& operator+=(const Mpfr& b) { return *this = *this + b; }
  Mpfr& operator-=(const Mpfr& b) { return *this = *this - b; }
  Mpfr& operator*=(const Mpfr& b) { return *this = *this * b; }

  friend bool operator==(const Mpfr& a, const Mpfr& b) { return mpfr_equal_p(a.v_, b.v_); }
  friend bool operator<(const Mpfr& a, const Mpfr& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator>(const Mpfr& a, const Mpfr& b) { return mpfr_greater_p(a.v_, b.v_); }
  friend bool operator<=(const Mpfr& a, const Mpfr& b) { return mpfr_lessequal_p(a.v_, b.v_); }
  friend bool operator>=(const Mpfr& a, const Mpfr& b) { return mpfr_greaterequal_p(a.v_, b.v_); }

  friend Mpfr sqrt(const Mpfr& a) {
    Mpfr r;
    mpfr_sqrt(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend Mpfr abs(const Mpfr& a) {
    Mpfr r;
    mpfr_abs(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend bool isfinite(const Mpfr& a) { return mpfr_number_p(a.v_); }

 private:
  static mpfr_rnd_t mode(Rounding r) {
    return r == Rounding::kUp ? MPFR_RNDU : r == Rounding::kDown ? MPFR_RNDD : MPFR_RNDN;
  }
  template <typename F>
  static Mpfr apply(F f, const Mpfr& a, const Mpfr& b, Rounding rounding = Rounding::kNearest) {
    Mpfr r;
    f(r.v_, a.v_, b.v_, mode(rounding));
    return r;
  }
  mpfr_t v_;
};

#endif

}  // namespace raygrade
