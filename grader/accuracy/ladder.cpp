// The levels of the precision ladder and their error against ground truth.
#include "accuracy/ladder.h"

#include <algorithm>
#include <cmath>

#include "accuracy/certified.h"
#include "accuracy/formulations.h"
#include "math/interval.h"

namespace raygrade {
namespace {

template <typename T>
bool as_double(const std::optional<T>& hit, double& t) {
  if (!hit) return false;
  t = static_cast<double>(*hit);
  return true;
}

// The naive and the reference formulations in T, each instantiated per primitive, with the
// primitive's formula inlined.
template <typename T>
struct Naive {
  template <typename P>
  [[gnu::noinline]] static bool on(const AccuracyCase& c, double& t) {
    return as_double(P::Ladder::naive(vector_as<T>(c.origin), vector_as<T>(c.direction),
                                      points_as<T>(c), T(c.radius)),
                     t);
  }
};

template <typename T, typename P>
bool reference_hit(const AccuracyCase& c, double& t) {
  const auto& o = vector_as<T>(c.origin);
  const auto& d = vector_as<T>(c.direction);
  if constexpr (std::is_same_v<T, double>) {
    return P::Ladder::reference(o, d, c.points, c.radius, t);
  } else {
    T hit{};
    if (!P::Ladder::reference(o, d, points_as<T>(c), T(c.radius), hit)) return false;
    t = static_cast<double>(hit);
    return true;
  }
}

template <typename T>
struct Reference {
  template <typename P>
  [[gnu::noinline]] static bool on(const AccuracyCase& c, double& t) {
    if constexpr (std::is_same_v<T, Mpfr>) {
      MpfrPrecision bits(kMpfrBits);
      return reference_hit<T, P>(c, t);
    } else {
      return reference_hit<T, P>(c, t);
    }
  }
};

// The levels that start with the static filter, each instantiated per primitive with the
// primitive's filter inlined (as filtered_double, certified_double and adaptive_nearest run it,
// without their dispatch on the primitive); `Then` answers the cases the filter leaves.
template <typename Then>
struct FilterFirst {
  template <typename P>
  [[gnu::noinline]] static bool on(const AccuracyCase& c, double& t) {
    if constexpr (HasStaticFilter<P>) {
      FilterAnswer f;
      if (P::Ladder::filter(c.origin, c.direction, c.points, c.radius, f, 1.0)) {
        t = f.t;
        return f.hit;
      }
    }
    return Then::template on<P>(c, t);
  }
};

// What each of them runs where the filter cannot decide.
struct ThenReference {
  template <typename P>
  static bool on(const AccuracyCase& c, double& t) {
    return P::Ladder::reference(c.origin, c.direction, c.points, c.radius, t);
  }
};
struct ThenCertified {
  template <typename P>
  static bool on(const AccuracyCase& c, double& t) {
    Certified x = certified_double(c);
    if (!x.hit) return false;
    t = x.t;
    return true;
  }
};
struct ThenAdaptive {
  template <typename P>
  static bool on(const AccuracyCase& c, double& t) {
    Adaptive a = adaptive_nearest(c);
    if (!a.hit) return false;
    t = a.t;
    return true;
  }
};

template <typename F>
PerPrimitive per_primitive() {
  return []<std::size_t... I>(std::index_sequence<I...>) {
    return PerPrimitive{&F::template on<LadderPrimitive<I>>...};
  }
  (std::make_index_sequence<kPrimitiveCount>{});
}

}  // namespace

std::optional<double> LadderLevel::nearest(const AccuracyCase& c) const {
  NearestHit f = on[static_cast<std::size_t>(c.primitive)];
  double t = 0;
  if (!f || !f(c, t)) return std::nullopt;
  return t;
}

const std::vector<LadderLevel>& ladder_levels() {
  static const std::vector<LadderLevel> levels = {
      {"naive float", "b² − 4ac and (−b ± √Δ)/2a, plane then edge tests, plain slabs; float",
       per_primitive<Naive<float>>()},
      {"naive double", "the same textbook formulas in double", per_primitive<Naive<double>>()},
      {"reference float", "the solver's stable formulations in float",
       per_primitive<Reference<float>>()},
      {"reference double", "the solver's stable formulations in double (what solve runs)",
       per_primitive<Reference<double>>()},
      {"reference long double", "the same in x87 long double (64-bit significand)",
       per_primitive<Reference<long double>>()},
      {"reference double-double", "the same in double-double (about 106 bits)",
       per_primitive<Reference<DoubleDouble>>()},
      {"reference MPFR", "the same in MPFR at 256 bits", per_primitive<Reference<Mpfr>>()},
      {"static filter",
       "the reference double with a forward error bound on each quantity it decides by: its "
       "answer is exact where every such quantity lies beyond its bound (every primitive has "
       "one); the plain reference double where it cannot decide",
       per_primitive<FilterFirst<ThenReference>>()},
      {"certified double",
       "the static filter, then interval arithmetic in double with outward rounding where it "
       "cannot decide",
       per_primitive<FilterFirst<ThenCertified>>()},
      {"adaptive", "the static filter, then certified double, double-double, MPFR, until decided",
       per_primitive<FilterFirst<ThenAdaptive>>()},
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
