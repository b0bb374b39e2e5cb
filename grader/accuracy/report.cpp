// Measuring the ladder, and the Markdown page of the accuracy report.
#include "accuracy/report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace raygrade {
namespace {

// Each timing runs the set repeatedly for at least this long, so that a cheap formula is timed
// over many thousands of calls; the clock's resolution (about 1e-8 s) is then negligible.
constexpr double kMinTimingSeconds = 0.03;
// The reported time is the least of this many timings: what the formula costs, without the
// moments another process took the core (the noise is one-sided). The timings of one primitive
// go in rounds, every level once per round, so that a slow spell of the machine, which can last
// longer than one timing, spoils at most one timing of each level rather than all of one.
constexpr int kTimingRounds = 5;

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
  for (const auto& c : cases) out.push_back(c.input);
  return out;
}

}  // namespace

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
                      level_error(m.level, hard_p)});
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
    for (const auto& c : hard_in)
      ++report.adaptive_levels_hard[std::string(level_name(adaptive_nearest(c).level))];
  }
  return report;
}

}  // namespace raygrade
