// The certified and adaptive answers: the reference nearest hit computed in interval
// arithmetic, so that it is known whether the hit-or-miss decision is certain, and recomputed
// up the ladder (double, double-double, MPFR) until it is; MPFR ground truth.
#pragma once

#include <concepts>
#include <optional>
#include <string_view>
#include <vector>

#include "shapes/accuracy_case.h"
#include "shapes/filter_answer.h"

namespace raygrade {

// The levels of the adaptive answer, in the order they are tried.
enum class Level { kDouble, kDoubleDouble, kMpfr, kExactBoundary };
std::string_view level_name(Level level);

// The reference nearest hit in interval arithmetic: `decided` when every comparison it made
// (discriminant sign, edge signs, t ≥ 0, which root is first) was certain; `hit` and the
// enclosure [t_lo, t_hi] of the true t (rounded outward to doubles) are then rigorous.
struct Certified {
  bool decided = false;
  bool hit = false;
  double t_lo = 0, t_hi = 0;
  double t = 0;  // the enclosure's midpoint, rounded
};

// The static filter of the case's primitive (its Ladder::filter, where it has one): in plain
// double with a forward error bound on every quantity the decision rests on (docs/precision.md),
// the exact decision and an enclosure of t around the reference double's own t where the bounds
// allow, std::nullopt otherwise. `bound_scale` multiplies every bound: 1, but in the test that
// shows a smaller bound is caught.
std::optional<FilterAnswer> filtered_double(const AccuracyCase& c, double bound_scale = 1);
// Has the primitive a static filter?
bool has_filter(Primitive primitive);
// The same, at compile time: the primitive's Ladder has a static filter.
template <typename P>
concept HasStaticFilter = requires(const Vec3d& v, const std::vector<Vec3d>& p, double r,
                                   FilterAnswer& answer) {
  { P::Ladder::filter(v, v, p, r, answer, 1.0) } -> std::same_as<bool>;
};

// The certified answers. In double the static filter answers first; interval arithmetic runs
// where it cannot decide.
Certified certified_double(const AccuracyCase& c);
Certified certified_double_double(const AccuracyCase& c);
Certified certified_mpfr(const AccuracyCase& c, int bits);

// The adaptive answer (Shewchuk's plan): the certified double answer (the static filter's, or
// interval arithmetic's in double) when it decides, else
// double-double, else MPFR at kMpfrBits, then kMpfrBoundaryBits; when even that cannot decide,
// the true input lies on the boundary itself (a ray exactly tangent, through an edge, at
// t = 0) and the level is kExactBoundary, with the decision of the last level.
struct Adaptive {
  Level level = Level::kDouble;
  bool hit = false;
  double t = 0;
  double t_lo = 0, t_hi = 0;
};
Adaptive adaptive_nearest(const AccuracyCase& c);

// The order of two cases' nearest hits, both of which hit: `sign` −1 when a's t is smaller, 1
// when b's is, 0 for an exact tie; `level` is the first level of the ladder whose certified
// enclosures of the two t values are disjoint (computed and compared at that level's own
// precision, not rounded to double). Enclosures that still overlap at kMpfrBoundaryBits are an
// exact tie, at kExactBoundary, by the same argument as for a decision on a boundary.
struct Order {
  int sign = 0;
  Level level = Level::kDouble;
};
Order order_nearest(const AccuracyCase& a, const AccuracyCase& b);

// MPFR precisions of the ladder's top: 256 bits decides all but inputs within about 2^-200 of
// the boundary; 4096 bits exceeds the exponent range of double products of the inputs (their
// exact values need at most 2·2098 + 106 bits), so a case it cannot decide is, for the
// polynomial tests (discriminants, edge functions), exactly on the boundary.
constexpr int kMpfrBits = 256;
constexpr int kMpfrBoundaryBits = 4096;

// Ground truth: the certified MPFR answer; `boundary` when even kMpfrBoundaryBits cannot
// decide. `condition` is the relative condition number of t with respect to relative
// perturbations of every input coordinate (∞ at a tangent), by differences at MPFR precision.
// `hits` holds every hit at t ≥ 0 (both of a sphere's, a cylinder's or a box's), each t and unit
// normal computed at kTruthBits and rounded once; the normal is zero for boxes, whose faces'
// normals are exact (and ambiguous at an edge). Empty for a miss and on a boundary.
struct TruthHit {
  double t = 0;
  Vec3d normal;
};
struct Truth {
  bool hit = false;
  double t = 0;
  bool boundary = false;
  double condition = 0;
  std::vector<TruthHit> hits;
};
Truth compute_truth(const AccuracyCase& c, bool with_condition = true);

// Every hit at t ≥ 0 of the case at kTruthBits, as Truth::hits holds them.
std::vector<TruthHit> truth_hits(const AccuracyCase& c);

}  // namespace raygrade
