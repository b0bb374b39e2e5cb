// SoftFloat: binary floating point of any precision, correctly rounded (to nearest even, down
// or up), for builds without MPFR (WebAssembly; docs/web.md). The exact arithmetic on the
// significands is Boost.Multiprecision's cpp_int; this class only places the binary point and
// rounds once.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <cstdint>
#include <utility>

#include "math/rounding.h"

namespace raygrade {

// A value is zero, ±∞, NaN or m·2^e with m a natural number whose lowest bit is set (one
// representation per value). The operations take the precision of their result in bits, as
// MPFR's do from their destination, and round the exact result once, as MPFR does; the
// exponent is unbounded (no overflow or underflow before a conversion to double).
class SoftFloat {
 public:
  using Natural = boost::multiprecision::cpp_int;

  SoftFloat() = default;  // +0
  SoftFloat(double x, int precision, Rounding rounding = Rounding::kNearest);
  static SoftFloat nan();

  static SoftFloat add(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r);
  static SoftFloat sub(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r);
  static SoftFloat mul(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r);
  static SoftFloat div(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r);
  static SoftFloat sqrt(const SoftFloat& a, int precision, Rounding r);
  // a·b and a/b rounded down and up, both from one exact product (quotient and remainder), as
  // an interval's bounds take them: the same two values as mul (div) with kDown and kUp.
  static std::pair<SoftFloat, SoftFloat> mul_down_up(const SoftFloat& a, const SoftFloat& b,
                                                     int precision);
  static std::pair<SoftFloat, SoftFloat> div_down_up(const SoftFloat& a, const SoftFloat& b,
                                                     int precision);
  // −a and |a|, rounded to `precision`.
  static SoftFloat neg(const SoftFloat& a, int precision);
  static SoftFloat abs(const SoftFloat& a, int precision);

  // The nearest double below or above (kDown, kUp) or the nearest (kNearest), with
  // subnormals and overflow as IEEE 754 rounds them.
  double to_double(Rounding r) const;

  bool is_nan() const { return kind_ == Kind::kNaN; }
  bool is_finite() const { return kind_ == Kind::kZero || kind_ == Kind::kFinite; }

  // −1, 0 or 1; `unordered` when either is NaN (and then 0 is returned).
  static int compare(const SoftFloat& a, const SoftFloat& b, bool& unordered);

 private:
  enum class Kind : std::uint8_t { kZero, kFinite, kInf, kNaN };
  // An exact result before its rounding (soft_float.cpp).
  struct Unrounded;
  static Unrounded exact_product(const SoftFloat& a, const SoftFloat& b);
  static Unrounded exact_quotient(const SoftFloat& a, const SoftFloat& b, int precision);
  static SoftFloat rounded(Unrounded x, int precision, Rounding r);
  static std::pair<SoftFloat, SoftFloat> rounded_down_up(Unrounded x, int precision);
  // Rounds ±(m + a fraction, when `sticky`)·2^e to `precision` bits. With `sticky`, m must
  // hold at least precision + 2 bits.
  static SoftFloat round(bool negative, Natural m, std::int64_t e, bool sticky, int precision,
                         Rounding r);
  static SoftFloat special(Kind kind, bool negative);

  Kind kind_ = Kind::kZero;
  bool negative_ = false;
  Natural m_;  // odd when finite
  std::int64_t e_ = 0;
};

}  // namespace raygrade
