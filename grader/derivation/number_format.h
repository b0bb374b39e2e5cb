// How numbers appear to people: 1 rather than 1.000000, 7.27 at a chosen precision.
#pragma once

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

}  // namespace raygrade
