// The levels of the precision ladder and their error against ground truth.
#include "accuracy/ladder.h"

#include <algorithm>
#include <cmath>

#include "accuracy/formulations.h"
#include "math/interval.h"

namespace raygrade {
namespace {

template <typename T>
std::optional<double> rounded(const std::optional<T>& t) {
  if (!t) return std::nullopt;
  return static_cast<double>(*t);
}

}  // namespace

const std::vector<LadderLevel>& ladder_levels() {
  static const std::vector<LadderLevel> levels = {
      {"naive float", "b² − 4ac and (−b ± √Δ)/2a, plane then edge tests, plain slabs; float",
       [](const AccuracyCase& c) { return rounded(naive_nearest<float>(c)); }},
      {"naive double", "the same textbook formulas in double",
       [](const AccuracyCase& c) { return naive_nearest<double>(c); }},
      {"reference float", "the solver's stable formulations in float",
       [](const AccuracyCase& c) { return rounded(reference_nearest<float>(c)); }},
      {"reference double", "the solver's stable formulations in double (what solve runs)",
       [](const AccuracyCase& c) { return reference_nearest<double>(c); }},
      {"reference long double", "the same in x87 long double (64-bit significand)",
       [](const AccuracyCase& c) { return rounded(reference_nearest<long double>(c)); }},
      {"reference double-double", "the same in double-double (about 106 bits)",
       [](const AccuracyCase& c) { return rounded(reference_nearest<DoubleDouble>(c)); }},
      {"reference MPFR", "the same in MPFR at 256 bits",
       [](const AccuracyCase& c) {
         MpfrPrecision bits(kMpfrBits);
         return rounded(reference_nearest<Mpfr>(c));
       }},
      {"certified double", "interval arithmetic in double with outward rounding",
       [](const AccuracyCase& c) -> std::optional<double> {
         Certified x = certified_double(c);
         if (!x.hit) return std::nullopt;
         return x.t;
       }},
      {"adaptive", "certified double, then double-double, then MPFR, until decided",
       [](const AccuracyCase& c) -> std::optional<double> {
         Adaptive a = adaptive_nearest(c);
         if (!a.hit) return std::nullopt;
         return a.t;
       }},
  };
  return levels;
}

double relative_error(double t, double truth) {
  return std::abs(t - truth) / std::max(1.0, std::abs(truth));
}

LevelError level_error(const LadderLevel& level, const std::vector<TruthCase>& cases) {
  LevelError out;
  std::vector<double> errors;
  for (const auto& c : cases) {
    if (c.truth.boundary) continue;
    ++out.judged;
    std::optional<double> t = level.nearest(c.input);
    if (t.has_value() != c.truth.hit) {
      ++out.wrong_decisions;
      continue;
    }
    if (t) errors.push_back(std::isfinite(*t) ? relative_error(*t, c.truth.t) : 1.0);
  }
  if (!errors.empty()) {
    std::sort(errors.begin(), errors.end());
    out.median_relative = errors[errors.size() / 2];
    out.max_relative = errors.back();
  }
  return out;
}

}  // namespace raygrade
