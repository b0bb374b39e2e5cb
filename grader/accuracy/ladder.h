// The precision ladder: every formulation and number type the accuracy study compares, each as
// a function from a case to its nearest hit rounded to double, and the error of a level
// against ground truth.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "accuracy/corpus.h"

namespace raygrade {

struct LadderLevel {
  std::string name;     // "naive double", "reference double-double", ...
  std::string summary;  // one line for the report
  std::function<std::optional<double>(const AccuracyCase&)> nearest;
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
