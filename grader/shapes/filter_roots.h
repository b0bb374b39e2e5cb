// The static filters of the quadric primitives (cylinder, cone, capsule): a quadratic computed in
// double with a forward error bound on each coefficient, its roots each enclosed, the sign of a
// linear quantity at an enclosed root (which part of the surface a root lies on), and the nearest
// of the roots a primitive keeps.
#pragma once

#include <algorithm>
#include <cmath>

#include "math/robust.h"
#include "shapes/filter_answer.h"

namespace raygrade {

// Added to every bound of these filters: it covers the absolute error of any product that
// underflows (at most 2^-1075, times at most 2^(48·6) for the factors it is multiplied by
// afterwards, the vectors and the radius the polynomials take being at most kFilterInputLimit).
constexpr double kFilterUnderflowSlack = 0x1p-700;
// The filters take vectors (the rounded differences, the direction, the axis) whose 1-norms, and
// a radius whose magnitude, are at most this, so that no product of up to eight of them
// overflows and the underflow slack above holds. A difference that overflows is infinite, and
// so is then its norm: the test fails for it too (and for NaN).
constexpr double kFilterInputLimit = 0x1p48;

// Are the 1-norms (and the radius) within kFilterInputLimit?
[[gnu::always_inline]] inline bool within_filter_limit(double n1, double n2, double n3, double r) {
  constexpr double limit = kFilterInputLimit;
  return (n1 <= limit) & (n2 <= limit) & (n3 <= limit) & (std::abs(r) <= limit);
}

// Magnitudes: a cross product x × y has terms whose magnitudes sum to at most ‖x‖₁‖y‖₁, so
// their squares sum to at most (‖x‖₁‖y‖₁)². The filters bound the magnitudes of cross products
// by these 1-norms, a little looser than component by component and a third of the cost, except
// where the two vectors are nearly parallel on ordinary rays (there the product cancels, and
// the 1-norms would overstate its error many times).

// A quadratic a·t² + 2b·t + c = 0 computed in double, with bounds on the absolute errors of a, b
// and c against their exact values, and its quarter discriminant b² − a·c = scale²·disc computed
// as disc, with a bound on disc's absolute error, and scale > 0 within 6u of the exact one.
struct BoundedQuadratic {
  double a = 0, b = 0, c = 0, disc = 0, scale = 1;
  double a_error = 0, b_error = 0, c_error = 0, disc_error = 0;
};

// The roots of a BoundedQuadratic: none, or two, each with an enclosure of an exact root (the
// two enclosures hold the two exact roots; their order is not relied on).
struct EnclosedRoots {
  int count = 0;
  FilterAnswer root[2];
};

// The relative errors enclose_roots allows, and the relative error of each root it encloses then
// (see there): τ, which nearly every ordinary ray meets, else 2^-20 (a grazing ray, a ray nearly
// parallel to a line of a cone), whose enclosure is wider but as certain.
constexpr double kRootTolerances[2] = {kFastPathTolerance<double>, 0x1p-20};
constexpr double root_error(double tolerance) {
  return 2.05 * tolerance + 16 * kUnitRoundoff<double>;
}

// The roots by the stable q = −(b + sign(b)·scale·√disc), t = c/q and q/a, when the signs of
// disc, a and c are certain (each farther from zero than its bound), and, for T the first of
// kRootTolerances that holds, disc's relative error is at most 2T and those of a, c and b
// (against |q|) at most T/2; false otherwise. Then, with scale within 6u: √disc is within
// 1.01T + u of the exact one (0.51 times disc's relative error, for one at most 1/64), the root
// R = scale·√disc within e_R = 1.01T + 8u, and q within T/2 + e_R + 2u: b and R are added with
// the same sign (|b|, R ≤ |q|), and where b's computed sign is not the exact one (|b| below its
// bound) q stands for the other q of the pair, −(b − sign(b)·R), whose quotients are the same
// two roots, within the same bound. c/q and q/a are then within root_error(T), enclosed by
// enclose_quotient (whose slack, 1.25 against 8/7, covers the second-order terms). The tests are
// products, not quotients: no division but the roots'. c ≠ 0 keeps both roots away from zero.
[[gnu::always_inline]] inline bool enclose_roots(const BoundedQuadratic& k, EnclosedRoots& out) {
  using std::abs;
  // The magnitudes named first: clang warns of a bitwise & on a call's result.
  double disc_m = abs(k.disc), a_m = abs(k.a), c_m = abs(k.c);
  if (!((disc_m > k.disc_error) & (a_m > k.a_error) & (c_m > k.c_error))) return false;
  out.count = 0;
  if (k.disc < 0) return true;
  double root = k.scale * std::sqrt(k.disc);
  double q = -(k.b + sign_of(k.b) * root);
  double q_m = abs(q);
  auto within = [&](double tolerance) {
    return (k.disc_error <= 2 * tolerance * k.disc) & (2 * k.a_error <= tolerance * a_m) &
           (2 * k.c_error <= tolerance * c_m) & (2 * k.b_error <= tolerance * q_m);
  };
  double error = root_error(kRootTolerances[0]);
  if (!within(kRootTolerances[0])) {
    if (!within(kRootTolerances[1])) return false;
    error = root_error(kRootTolerances[1]);
  }
  if (!enclose_quotient(k.c / q, error, 1, out.root[0]) ||
      !enclose_quotient(q / k.a, error, 1, out.root[1])) {
    return false;
  }
  out.count = 2;
  return true;
}

// The sign of an exact quantity x computed as `value` within `error`: 1 or −1 when certain, 0
// when not.
[[gnu::always_inline]] inline int certain_sign(double value, double error) {
  return value > error ? 1 : value < -error ? -1 : 0;
}

// The width of an enclosure around its t: the larger of t − t_lo and t_hi − t, rounded up.
[[gnu::always_inline]] inline double enclosure_width(const FilterAnswer& r) {
  return 1.001 * std::max(r.t - r.t_lo, r.t_hi - r.t);
}

// The nearest of the roots a primitive keeps at t ≥ 0, from enclosed roots each known to be
// kept or not: the exact nearest is the least of the kept exact roots, so it lies between the
// least of their lower ends and the least of their upper ends, whichever root it is.
struct NearestKept {
  FilterAnswer nearest;  // hit false until a root is kept

  // Keeps the enclosed root r, known to be kept by the primitive's tests, if it lies at t > 0;
  // false when its sign is not certain.
  [[gnu::always_inline]] bool keep(const FilterAnswer& r) {
    if (r.t_hi < 0) return true;
    if (!(r.t_lo > 0)) return false;
    if (!nearest.hit) {
      nearest = r;
      nearest.hit = true;
    } else {
      nearest.t = std::min(nearest.t, r.t);
      nearest.t_lo = std::min(nearest.t_lo, r.t_lo);
      nearest.t_hi = std::min(nearest.t_hi, r.t_hi);
    }
    return true;
  }
};

}  // namespace raygrade
