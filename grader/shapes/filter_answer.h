// FilterAnswer: what a primitive's static filter (its Ladder::filter) decides in double, with an
// enclosure of t, and the enclosure of a quotient whose parts have known relative errors.
#pragma once

#include <cmath>

namespace raygrade {

// A decision a static filter has shown to be the exact one (a forward error bound lies below
// every quantity it rests on), and for a hit the rounded t with an interval that holds the
// exact t.
struct FilterAnswer {
  bool hit = false;  // the nearest hit at t ≥ 0 exists
  double t = 0, t_lo = 0, t_hi = 0;
};

// The largest relative error of a quotient's numerator or denominator, summed, for which
// enclose_quotient gives an enclosure: 1/8 keeps 1/(1 − e) below 8/7.
constexpr double kQuotientErrorLimit = 1.0 / 8;
// Below this magnitude a quotient is not enclosed: its width, a small multiple of |t|, would
// come near the subnormals, where relative bounds fail. 2^-900.
constexpr double kQuotientFloor = 0x1p-900;

// enclose_quotient where the caller has shown e ≤ kQuotientErrorLimit (the plane's filter shows
// e ≤ kFastPathTolerance without dividing): the same enclosure, without the test of e, so that
// a decision need not wait for e's division. False when t is too small or not finite.
inline bool enclose_quotient_within_limit(double t, double e, int roundings, FilterAnswer& out) {
  constexpr double u = 0x1p-53;
  if (!(std::abs(t) >= kQuotientFloor && std::isfinite(t))) return false;
  double width = std::abs(t) * (1.25 * e + (roundings + 2) * u);
  out.t = t;
  out.t_lo = t - width;
  out.t_hi = t + width;
  return true;
}

// Sets out.t = t and [t_lo, t_hi] around it, where t is the quotient N/D of computed values whose
// exact values are N(1 + α), D(1 + β) with |α| + |β| ≤ e, rounded `roundings` times after the
// division. The exact quotient is within (8/7)·e·|N/D| of N/D for e ≤ 1/8 (1.25e is used), and
// within u per rounding of t; two ulps more cover the rounding of the bounds themselves. False
// (nothing enclosed) when e is too large or t too small or not finite.
inline bool enclose_quotient(double t, double e, int roundings, FilterAnswer& out) {
  return e <= kQuotientErrorLimit && enclose_quotient_within_limit(t, e, roundings, out);
}

}  // namespace raygrade
