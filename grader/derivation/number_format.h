// How numbers appear to people: 1 rather than 1.000000, 7.27 at a chosen precision.
#pragma once

#include <optional>
#include <string>

#include "derivation/value.h"

namespace raygrade {

struct NumberFormat {
  // Significant digits shown for non-integers (7.268 at 4). A problem or a flag may set it.
  int significant = 4;
  // When set (>= 0), a fixed number of decimal places instead (7.27 at 2).
  int decimals = -1;
};

// A number as a person writes it: integers without a decimal point, no trailing zeros, no
// negative zero, scientific notation only for very large or very small magnitudes.
std::string format_number(double v, const NumberFormat& f = {});

// "(1, 0, 0)" with each component by format_number.
std::string format_vector(const Vec3d& v, const NumberFormat& f = {});

std::string format_value(const Value& v, const NumberFormat& f = {});

// A number of the form (p + s·√k) / q with small integers, as people write it when a square
// root or a fraction appears in an exercise: 9 − √3, (1 + √5)/2, 1/6, 2√2. `k` is square-free
// (1 when there is no root, so the number is the fraction p/q); q >= 1; gcd(p, s, q) = 1.
struct ExactForm {
  long long p = 0;
  long long s = 0;
  long long k = 1;
  long long q = 1;
};

// The exact form of `v` when one with small parts matches it to rounding and its decimal
// form would be rounded; nothing for integers, short decimals (0.5, 1.25) and numbers with
// no small exact form. Small means: q <= 12 for fractions; q in {1, 2, 3, 4, 6}, k <= 30 and
// |s| <= 12 for roots; |p| <= 10000.
std::optional<ExactForm> exact_form(double v);

// Whether `v` prints with a minus sign: false for −1.4e-14, which prints as 0.
bool prints_negative(double v, const NumberFormat& f = {});

// "9 − √3", "(1 + √5)/2", "1/6", "−2√2".
std::string exact_text(const ExactForm& e);

}  // namespace raygrade
