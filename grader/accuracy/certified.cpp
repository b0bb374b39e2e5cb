// Certified (interval) evaluation of the reference formulation, the adaptive ladder and the
// MPFR ground truth.
#include "accuracy/certified.h"

#include <cmath>
#include <limits>

#include "accuracy/formulations.h"
#include "math/interval.h"

namespace raygrade {
namespace {

double down(double x) { return x; }
double up(double x) { return x; }
double down(const DoubleDouble& x) { return Rounded<double>::add(x.hi, x.lo, false); }
double up(const DoubleDouble& x) { return Rounded<double>::add(x.hi, x.lo, true); }
double down(const Mpfr& x) { return x.to_double(Rounding::kDown); }
double up(const Mpfr& x) { return x.to_double(Rounding::kUp); }

template <typename T>
Certified certify(const AccuracyCase& c) {
  int before = interval_undecided_count();
  std::optional<Interval<T>> t = reference_nearest<Interval<T>>(c);
  Certified out;
  out.decided = interval_undecided_count() == before;
  interval_undecided_count() = before;
  out.hit = t.has_value();
  if (t) {
    out.t_lo = down(t->lo);
    out.t_hi = up(t->hi);
    out.t = static_cast<double>(t->mid());
  }
  return out;
}

// The order of a's and b's nearest t at precision T, when both hit with every comparison
// certain and their enclosures are disjoint, or are the same point.
template <typename T>
std::optional<int> order_at(const AccuracyCase& a, const AccuracyCase& b) {
  int before = interval_undecided_count();
  std::optional<Interval<T>> ta = reference_nearest<Interval<T>>(a);
  std::optional<Interval<T>> tb = reference_nearest<Interval<T>>(b);
  bool decided = interval_undecided_count() == before;
  interval_undecided_count() = before;
  if (!decided || !ta || !tb) return std::nullopt;
  if (ta->hi < tb->lo) return -1;
  if (tb->hi < ta->lo) return 1;
  if (ta->is_point() && tb->is_point() && ta->lo == tb->lo) return 0;
  return std::nullopt;
}

}  // namespace

std::optional<FilterAnswer> filtered_double(const AccuracyCase& c, double bound_scale) {
  FilterAnswer answer;
  bool decided = visit_primitive(c.primitive, [&]<typename P>() {
    if constexpr (HasStaticFilter<P>) {
      return P::Ladder::filter(c.origin, c.direction, c.points, c.radius, answer, bound_scale);
    } else {
      return false;
    }
  });
  if (!decided) return std::nullopt;
  return answer;
}

bool has_filter(Primitive primitive) {
  return visit_primitive(primitive, [&]<typename P>() { return HasStaticFilter<P>; });
}

std::string_view level_name(Level level) {
  switch (level) {
    case Level::kDouble: return "double";
    case Level::kDoubleDouble: return "double-double";
    case Level::kMpfr: return "mpfr";
    case Level::kExactBoundary: return "exact-boundary";
  }
  return "?";
}

Certified certified_double(const AccuracyCase& c) {
  if (std::optional<FilterAnswer> f = filtered_double(c)) {
    return Certified{true, f->hit, f->t_lo, f->t_hi, f->t};
  }
  return certify<double>(c);
}
Certified certified_double_double(const AccuracyCase& c) { return certify<DoubleDouble>(c); }
Certified certified_mpfr(const AccuracyCase& c, int bits) {
  MpfrPrecision precision(bits);
  return certify<Mpfr>(c);
}

Adaptive adaptive_nearest(const AccuracyCase& c) {
  auto from = [](Level level, const Certified& x) {
    return Adaptive{level, x.hit, x.t, x.t_lo, x.t_hi};
  };
  // The static filter's t is the reference double's own.
  if (std::optional<FilterAnswer> f = filtered_double(c)) {
    return Adaptive{Level::kDouble, f->hit, f->t, f->t_lo, f->t_hi};
  }
  Certified x = certify<double>(c);
  if (x.decided) {
    // The plain double reference is usually the more accurate value; keep it when it lies in
    // the certified enclosure.
    Adaptive a = from(Level::kDouble, x);
    std::optional<double> t = reference_nearest<double>(c);
    if (a.hit && t && *t >= x.t_lo && *t <= x.t_hi) a.t = *t;
    return a;
  }
  x = certified_double_double(c);
  if (x.decided) return from(Level::kDoubleDouble, x);
  x = certified_mpfr(c, kMpfrBits);
  if (x.decided) return from(Level::kMpfr, x);
  x = certified_mpfr(c, kMpfrBoundaryBits);
  return from(x.decided ? Level::kMpfr : Level::kExactBoundary, x);
}

Order order_nearest(const AccuracyCase& a, const AccuracyCase& b) {
  if (std::optional<int> s = order_at<double>(a, b)) return {*s, Level::kDouble};
  if (std::optional<int> s = order_at<DoubleDouble>(a, b)) return {*s, Level::kDoubleDouble};
  for (int bits : {kMpfrBits, kMpfrBoundaryBits}) {
    MpfrPrecision precision(bits);
    if (std::optional<int> s = order_at<Mpfr>(a, b)) return {*s, Level::kMpfr};
  }
  return {0, Level::kExactBoundary};
}

namespace {

// The bits of the ground truth: beyond any double-double or 256-bit answer it judges.
constexpr int kTruthBits = 1024;
// The relative step of the differences that estimate the condition number: far below the
// inputs' own ulps (2^-53), far above the truth's precision (2^-1024).
constexpr double kConditionStep = 0x1p-400;

// t at MPFR precision with one input coordinate scaled by (1 + h).
std::optional<Mpfr> t_perturbed(const AccuracyCase& c, int which, const Mpfr& h) {
  // Coordinates: origin (0..2), direction (3..5), points (6..), radius (last).
  auto coordinate = [&](int k, Vec3<Mpfr>& o, Vec3<Mpfr>& d, std::vector<Vec3<Mpfr>>& p,
                        Mpfr& r) -> Mpfr* {
    if (k < 3) return &o[k];
    if (k < 6) return &d[k - 3];
    k -= 6;
    if (k < static_cast<int>(3 * p.size())) return &p[k / 3][k % 3];
    return &r;
  };
  Vec3<Mpfr> o(c.origin), d(c.direction);
  std::vector<Vec3<Mpfr>> p = points_as<Mpfr>(c);
  Mpfr r(c.radius);
  Mpfr* x = coordinate(which, o, d, p, r);
  *x = *x * (Mpfr(1) + h);
  Mpfr t;
  if (!reference_hit_at(c.primitive, o, d, p, r, t)) return std::nullopt;
  return t;
}

}  // namespace

std::vector<TruthHit> truth_hits(const AccuracyCase& c) {
  MpfrPrecision precision(kTruthBits);
  Vec3<Mpfr> o(c.origin), d(c.direction);
  std::vector<Vec3<Mpfr>> p = points_as<Mpfr>(c);
  Mpfr r(c.radius);
  std::vector<std::pair<Mpfr, Vec3<Mpfr>>> hits;  // t and a normal, not yet unit
  auto add = [&](const Mpfr& t, const Vec3<Mpfr>& normal) {
    if (t >= Mpfr(0)) hits.emplace_back(t, normal);
  };
  visit_primitive(c.primitive, [&]<typename P>() { P::Ladder::hits(o, d, p, r, add); });
  std::vector<TruthHit> out;
  for (const auto& [t, n] : hits) {
    Mpfr length = sqrt(dot(n, n));
    Vec3d unit = length == Mpfr(0) ? Vec3d{} : Vec3d(n / length);
    out.push_back({static_cast<double>(t), unit});
  }
  return out;
}

Truth compute_truth(const AccuracyCase& c, bool with_condition) {
  Truth out;
  Certified x = certified_mpfr(c, kTruthBits);
  if (!x.decided) {
    Certified y = certified_mpfr(c, kMpfrBoundaryBits);
    out.boundary = !y.decided;
    x = y;
  }
  out.hit = x.hit;
  out.t = x.t;
  if (out.hit && !out.boundary) out.hits = truth_hits(c);
  if (!with_condition || !out.hit || out.boundary) return out;
  MpfrPrecision precision(kTruthBits);
  std::optional<Mpfr> t = reference_nearest<Mpfr>(c);
  if (!t || *t == Mpfr(0)) return out;
  int inputs = 6 + 3 * static_cast<int>(c.points.size()) + 1;
  Mpfr h(kConditionStep), sum(0);
  for (int k = 0; k < inputs; ++k) {
    std::optional<Mpfr> tk = t_perturbed(c, k, h);
    if (!tk) {
      out.condition = std::numeric_limits<double>::infinity();
      return out;
    }
    sum = sum + abs((*tk - *t) / (*t * h));
  }
  out.condition = static_cast<double>(sum);
  return out;
}

}  // namespace raygrade
