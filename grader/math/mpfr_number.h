// Mpfr: an MPFR number at the precision of the current MpfrPrecision scope, with the
// operators the intersection templates use (ground truth and the top of the precision ladder).
#pragma once

#include <mpfr.h>

#include <utility>

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
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }

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
  template <typename F>
  static Mpfr apply(F f, const Mpfr& a, const Mpfr& b) {
    Mpfr r;
    f(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  mpfr_t v_;
};

}  // namespace raygrade
