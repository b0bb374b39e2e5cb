// The precision ladder: every formulation and number type the accuracy study compares, each as
// a function from a case to its nearest hit rounded to double, and the error of a level
// against ground truth.
#pragma once

#include <array>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "accuracy/corpus.h"

namespace raygrade {

// A formulation's nearest hit (t ≥ 0) on a case, rounded to double: true with it in `t`, false
// for a miss. A plain function that hands t back through a reference: GCC 12 returns a
// std::optional<double> through memory, a store-forwarding stall that a timing would count as
// part of the formula.
using NearestHit = bool (*)(const AccuracyCase& c, double& t);

// One such function per primitive of the study (LadderPrimitives), indexed by Primitive: timing
// one primitive's cases then runs a compact function with that primitive's formula alone, for
// every level alike. nullptr where a peer does not serve the primitive.
using PerPrimitive = std::array<NearestHit, kPrimitiveCount>;

struct LadderLevel {
  std::string name;     // "naive double", "reference double-double", ...
  std::string summary;  // one line for the report
  PerPrimitive on{};

  // The nearest hit of a case; std::nullopt for a miss, or where the level does not serve the
  // case's primitive.
  std::optional<double> nearest(const AccuracyCase& c) const;
};

// naive float, naive double, reference float, reference double, reference long double,
// reference double-double, reference MPFR (kMpfrBits), certified double (the interval
// enclosure's midpoint) and adaptive.
const std::vector<LadderLevel>& ladder_levels();

// The error of one level on a set of cases with known truth. Relative errors in t are taken
// where both the level and the truth hit (absolute below |t| = 1); cases whose truth lies on a
// boundary are not judged.
struct LevelError {
  int judged = 0;
  int wrong_decisions = 0;  // hit where the truth misses, or the reverse
  double median_relative = 0, max_relative = 0;
};
LevelError level_error(const LadderLevel& level, const std::vector<TruthCase>& cases);

// Relative error of t against the truth, absolute below magnitude 1.
double relative_error(double t, double truth);

}  // namespace raygrade
