// raygrade bench: the precision ladder timed and judged against MPFR truth (writes
// docs/accuracy.md and its plot), the hard-case corpus generator, and the mesh stress runs.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "accuracy/mesh.h"
#include "accuracy/report.h"
#include "accuracy/settle.h"
#include "bench/peers.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/error.h"

namespace raygrade::cli {
namespace {

struct BenchOptions {
  std::string out = "docs/accuracy.md";
  std::string corpus = "tests/data/hard_cases.json";
  std::string write_corpus;
  std::string corpus_problems;
  int random = 2000;
  long long stress = 0;
  long long spawn = 0;
};

// A progress bar on standard error, only when it is a terminal.
void progress_bar(const char* what, double fraction) {
  if (!isatty(fileno(stderr))) return;
  int filled = static_cast<int>(fraction * 30);
  fmt::print(stderr, "\r{:<12} [{:<30}] {:3.0f}%", what, std::string(filled, '#'), fraction * 100);
  if (fraction >= 1) fmt::print(stderr, "\n");
}

int write_corpus(const std::string& path) {
  std::vector<TruthCase> cases;
  auto inputs = hard_cases();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    cases.push_back({inputs[i], compute_truth(inputs[i])});
    progress_bar("truth", static_cast<double>(i + 1) / static_cast<double>(inputs.size()));
  }
  write_file_atomically(path, corpus_json(cases).dump(1) + "\n");
  fmt::print("wrote {} cases to {}\n", cases.size(), path);
  return kExitOk;
}

// Every case of the corpus as an intersect problem: its object (the primitive's own JSON, from
// the case) and its ray, for tests that run the hard cases through every command.
int write_corpus_problems(const std::string& corpus, const std::string& path) {
  nlohmann::ordered_json problems = nlohmann::ordered_json::array();
  for (const TruthCase& c : read_corpus(corpus)) {
    std::string id = c.input.id;
    std::replace(id.begin(), id.end(), '/', '-');
    const Vec3d &o = c.input.origin, &d = c.input.direction;
    problems.push_back({{"id", id},
                        {"title", c.input.id},
                        {"statement", fmt::format("The hard case {}.", c.input.id)},
                        {"ray", {{"origin", {o.x, o.y, o.z}}, {"direction", {d.x, d.y, d.z}}}},
                        {"object", shape_of(c.input)->to_json()}});
  }
  std::size_t count = problems.size();
  write_file_atomically(path,
                        nlohmann::ordered_json{{"problems", std::move(problems)}}.dump(1) + "\n");
  fmt::print("wrote {} problems to {}\n", count, path);
  return kExitOk;
}

int run_bench(const BenchOptions& o) {
  if (!o.write_corpus.empty()) return write_corpus(o.write_corpus);
  if (!o.corpus_problems.empty()) return write_corpus_problems(o.corpus, o.corpus_problems);
  AccuracyReport report;
  if (o.stress > 0 || o.spawn > 0) {
    TriangleMesh mesh = subdivided_sphere(3);
    auto start = std::chrono::steady_clock::now();
    StressResult edges =
        stress_edge_rays(mesh, o.stress, 1, [](double f) { progress_bar("edge rays", f); });
    progress_bar("edge rays", 1);
    StressResult spawn = stress_spawned_rays(mesh, o.spawn, 2);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print(
        "edge and vertex rays: {} misses in {}\nspawned rays: {} failures in {}\n({:.1f} s)\n",
        edges.failures, edges.rays, spawn.failures, spawn.rays, s);
    return edges.failures == 0 && spawn.failures == 0 ? kExitOk : kExitFailed;
  }
  std::vector<Measured> levels;
  for (const auto& level : ladder_levels()) levels.push_back({level, false});
  for (const auto& peer : peers()) {
    LadderLevel level{peer.name, "", {}};
    level.on[static_cast<std::size_t>(peer.primitive)] = peer.nearest;
    levels.push_back({level, true});
  }
  std::vector<TruthCase> hard = read_corpus(o.corpus);
  report = measure_accuracy(levels, o.random, hard, [](int done, int total) {
    progress_bar("measuring", static_cast<double>(done) / total);
  });
  report.command = fmt::format("raygrade bench --out {}", o.out);
  std::filesystem::path md(o.out);
  std::string svg_name = md.stem().string() + ".svg";
  write_file_atomically((md.parent_path() / svg_name).string(), render_accuracy_svg(report));
  write_file_atomically(o.out, render_accuracy_markdown(report, svg_name));
  fmt::print("wrote {} and {}\n", o.out, (md.parent_path() / svg_name).string());
  return kExitOk;
}

}  // namespace

Runner setup_bench(CLI::App& sub) {
  auto o = std::make_shared<BenchOptions>();
  sub.add_option("--out", o->out, "the Markdown report to write (the SVG plot goes beside it)");
  sub.add_option("--corpus", o->corpus, "the hard-case corpus to judge on");
  sub.add_option("--random", o->random, "random cases per primitive")
      ->check(CLI::Range(10, 1000000));
  sub.add_option("--write-corpus", o->write_corpus,
                 "generate the hard cases, compute their MPFR truth, write them here, and stop");
  sub.add_option("--corpus-problems", o->corpus_problems,
                 "write every case of --corpus as an intersect problem here, and stop");
  sub.add_option("--stress", o->stress,
                 "instead of the report: this many edge and vertex rays at a closed mesh");
  sub.add_option("--spawn", o->spawn, "with --stress: this many hits to spawn rays from");
  return [o] {
    try {
      return run_bench(*o);
    } catch (const Error& e) {
      fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
      return static_cast<int>(kExitBadInput);
    } catch (const std::exception& e) {
      fmt::print(stderr, "raygrade bench: {}\n", e.what());
      return static_cast<int>(kExitBadInput);
    }
  };
}

}  // namespace raygrade::cli
