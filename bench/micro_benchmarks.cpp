// Google Benchmark micro-benchmarks of the precision ladder: every level on the same random
// rays, per primitive (run build/release/bench/raygrade_micro; not part of ctest).
#include <benchmark/benchmark.h>

#include "accuracy/ladder.h"
#include "bench/peers.h"

namespace raygrade {
namespace {

// Cases per primitive: enough to defeat the branch predictor, few enough to stay in cache.
constexpr int kCases = 512;

void run(benchmark::State& state, NearestHit f, Primitive p) {
  std::vector<AccuracyCase> cases = random_cases(p, kCases, 7);
  std::size_t i = 0;
  for (auto _ : state) {
    double t = 0;
    benchmark::DoNotOptimize(f(cases[i], t));
    benchmark::DoNotOptimize(t);
    i = (i + 1) % cases.size();
  }
}

int register_all() {
  for (Primitive p : kAllPrimitives) {
    for (const auto& level : ladder_levels()) {
      std::string name = fmt::format("{}/{}", primitive_name(p), level.name);
      NearestHit f = level.on[static_cast<std::size_t>(p)];
      benchmark::RegisterBenchmark(name.c_str(), [f, p](benchmark::State& s) { run(s, f, p); });
    }
  }
  for (const auto& peer : peers()) {
    std::string name = fmt::format("{}/{}", primitive_name(peer.primitive), peer.name);
    benchmark::RegisterBenchmark(name.c_str(), [f = peer.nearest, p = peer.primitive](
                                                   benchmark::State& s) { run(s, f, p); });
  }
  return 0;
}

const int kRegistered = register_all();

}  // namespace
}  // namespace raygrade

BENCHMARK_MAIN();
