// The accuracy report: every level of the ladder (and the peers) timed and judged against
// MPFR truth on a random set and on the hard set, rendered as docs/accuracy.md and an SVG plot.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "accuracy/ladder.h"

namespace raygrade {

struct ReportRow {
  std::string level;  // a ladder level or a peer's name
  Primitive primitive{};
  bool peer = false;
  double ns_random = 0, ns_hard = 0;  // nanoseconds per intersection (hard: 0 if no cases)
  LevelError random, hard;
  // The largest error of the unit normal on the hard set, per component, against the MPFR
  // normal: for "reference double", the normal solve reports (the primitive's intersect); for
  // "naive double", the normal (P − C)/r of the rounded hit point at the naive t. Nothing for
  // the other levels, which give t alone.
  std::optional<double> normal_hard;
};

// The largest component error of the unit normal of the nearest hit on `cases` (those whose
// truth has a normal), as solve reports it (`solver`), or as the naive formulas give it from
// the rounded hit point P = O + t·D at the naive double t.
double solver_normal_error(const std::vector<TruthCase>& cases);
double naive_normal_error(const std::vector<TruthCase>& cases);

struct AccuracyReport {
  std::vector<ReportRow> rows;
  int random_per_primitive = 0;
  std::map<Primitive, int> hard_per_primitive;
  // Cases of each primitive's random set that the truth hits.
  std::map<Primitive, int> random_hits;
  std::map<std::string, int> adaptive_levels_hard;  // level name → cases of the hard set
  // Cases the static filter decides, per primitive that has one, of its random and hard sets.
  std::map<Primitive, int> filter_decided_random, filter_decided_hard;
  std::string command;  // the command that regenerates it
  std::optional<long long> stress_rays, stress_misses, spawn_rays, spawn_failures;
};

// A ladder level or a peer (which serves only the primitives it has a function for).
struct Measured {
  LadderLevel level;
  bool peer = false;
};

// Times and judges every level on every primitive's random set (`random_count` cases) and hard
// cases. `progress` gets (done, total) after each measurement.
AccuracyReport measure_accuracy(const std::vector<Measured>& levels, int random_count,
                                const std::vector<TruthCase>& hard,
                                const std::function<void(int, int)>& progress = {});

// The Markdown page (its first line says it is generated, and by which command) and the plot.
std::string render_accuracy_markdown(const AccuracyReport& report, const std::string& svg_name);
std::string render_accuracy_svg(const AccuracyReport& report);

}  // namespace raygrade
