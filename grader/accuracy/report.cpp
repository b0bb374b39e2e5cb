// Measuring the ladder, and the Markdown page of the accuracy report.
#include "accuracy/report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "accuracy/formulations.h"
#include "accuracy/settle.h"

namespace raygrade {
namespace {

// Each timing runs the set repeatedly for at least this long, so that a cheap formula is timed
// over many thousands of calls; the clock's resolution (about 1e-8 s) is then negligible.
constexpr double kMinTimingSeconds = 0.03;
// The reported time is the least of this many timings: what the formula costs, without the
// moments another process took the core (the noise is one-sided). The timings of one primitive
// go in rounds, every level once per round, so that a slow spell of the machine, which can last
// longer than one timing, spoils at most one timing of each level rather than all of one.
constexpr int kTimingRounds = 9;

double time_once(NearestHit f, const std::vector<AccuracyCase>& cases) {
  if (cases.empty()) return 0;
  using Clock = std::chrono::steady_clock;
  long long calls = 0;
  double sink = 0;
  auto start = Clock::now();
  double elapsed = 0;
  do {
    for (const auto& c : cases) {
      double t = 0;
      sink += f(c, t) ? t : 1;
    }
    calls += static_cast<long long>(cases.size());
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < kMinTimingSeconds);
  volatile double keep = sink;
  (void)keep;
  return elapsed * 1e9 / static_cast<double>(calls);
}

constexpr double kNever = std::numeric_limits<double>::infinity();

std::vector<AccuracyCase> inputs(const std::vector<TruthCase>& cases) {
  std::vector<AccuracyCase> out;
  out.reserve(cases.size());
  for (const auto& c : cases) out.push_back(c.input);
  return out;
}

// The largest component of a − b.
double component_error(const Vec3d& a, const Vec3d& b) {
  Vec3d e = a - b;
  return std::max({std::abs(e.x), std::abs(e.y), std::abs(e.z)});
}

// The textbook normal at the point O + t·D rounded: (P − C)/r for a sphere, the normalized
// normal or cross product for the flats, ... (each primitive's Ladder::naive_normal).
std::optional<Vec3d> naive_normal(const AccuracyCase& c, double t) {
  Vec3d point = c.origin + t * c.direction;
  return visit_primitive(c.primitive, [&]<typename P>() {
    return P::Ladder::naive_normal(c.points, c.radius, point);
  });
}

}  // namespace

double solver_normal_error(const std::vector<TruthCase>& cases) {
  double worst = 0;
  for (const auto& c : cases) {
    if (c.truth.hits.empty() || c.truth.hits.front().normal == Vec3d{}) continue;
    std::unique_ptr<Shape> shape = shape_of(c.input);
    Ray ray{c.input.origin, c.input.direction};
    Intersection x = shape->intersect(ray);
    settle_nearest(*shape, ray, x);
    if (x.hits.empty()) continue;  // a wrong decision: counted in the t columns
    worst = std::max(worst, component_error(x.hits.front().normal, c.truth.hits.front().normal));
  }
  return worst;
}

double naive_normal_error(const std::vector<TruthCase>& cases) {
  double worst = 0;
  for (const auto& c : cases) {
    if (c.truth.hits.empty() || c.truth.hits.front().normal == Vec3d{}) continue;
    std::optional<double> t = naive_nearest<double>(c.input);
    if (!t) continue;
    std::optional<Vec3d> n = naive_normal(c.input, *t);
    if (!n) continue;
    // A normal that is not finite (a t that overflowed) is as far off as two unit vectors can be.
    worst = std::max(worst, is_finite(*n) ? component_error(*n, c.truth.hits.front().normal) : 2.0);
  }
  return worst;
}

AccuracyReport measure_accuracy(const std::vector<Measured>& levels, int random_count,
                                const std::vector<TruthCase>& hard,
                                const std::function<void(int, int)>& progress) {
  AccuracyReport report;
  report.random_per_primitive = random_count;
  int total = 0, done = 0;
  for (Primitive p : kAllPrimitives) {
    for (const auto& m : levels)
      total += kTimingRounds * (m.level.on[static_cast<std::size_t>(p)] != nullptr);
  }
  for (Primitive p : kAllPrimitives) {
    std::vector<TruthCase> random;
    for (auto& c : random_cases(p, random_count, 1000 + static_cast<int>(p))) {
      Truth t = compute_truth(c, false);
      report.random_hits[p] += t.hit;
      random.push_back({std::move(c), t});
    }
    std::vector<TruthCase> hard_p;
    for (const auto& c : hard) {
      if (c.input.primitive == p) hard_p.push_back(c);
    }
    report.hard_per_primitive[p] = static_cast<int>(hard_p.size());
    std::vector<AccuracyCase> random_in = inputs(random), hard_in = inputs(hard_p);
    std::vector<ReportRow> rows;
    std::vector<NearestHit> timed;
    for (const auto& m : levels) {
      NearestHit f = m.level.on[static_cast<std::size_t>(p)];
      if (!f) continue;
      rows.push_back({m.level.name, p, m.peer, kNever, kNever, level_error(m.level, random),
                      level_error(m.level, hard_p), std::nullopt});
      if (m.level.name == "reference double") rows.back().normal_hard = solver_normal_error(hard_p);
      if (m.level.name == "naive double") rows.back().normal_hard = naive_normal_error(hard_p);
      timed.push_back(f);
    }
    for (int round = 0; round < kTimingRounds; ++round) {
      for (std::size_t i = 0; i < rows.size(); ++i) {
        rows[i].ns_random = std::min(rows[i].ns_random, time_once(timed[i], random_in));
        rows[i].ns_hard = std::min(rows[i].ns_hard, time_once(timed[i], hard_in));
        if (progress) progress(++done, total);
      }
    }
    for (auto& row : rows) report.rows.push_back(std::move(row));
    if (has_filter(p)) {
      auto decided = [](const std::vector<AccuracyCase>& cases) {
        return static_cast<int>(std::count_if(cases.begin(), cases.end(), [](const auto& c) {
          return filtered_double(c).has_value();
        }));
      };
      report.filter_decided_random[p] = decided(random_in);
      report.filter_decided_hard[p] = decided(hard_in);
    }
    for (const auto& c : hard_in)
      ++report.adaptive_levels_hard[std::string(level_name(adaptive_nearest(c).level))];
  }
  return report;
}

}  // namespace raygrade
