// Benchmark: grading generated answers from JSON text to results (JSON text) on one core.
// Run: cmake --build --preset release --target raygrade_grade_bench &&
//      build/release/bench/raygrade_grade_bench
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "grading/grade.h"
#include "json/source.h"

namespace raygrade {
namespace {

constexpr int kAnswers = 100000;

const char* kBank = R"({"problems": [
  {"id": "sphere", "method": "geometric",
   "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
   "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}},
  {"id": "plane", "method": "implicit",
   "ray": {"origin": [0, 0, 0], "direction": [1, 1, 1]},
   "object": {"type": "plane", "point": [3, 3, 3], "normal": [1, 1, 0]}},
  {"id": "first", "kind": "first-hit", "precision": 2,
   "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
   "objects": [{"name": "sphere 1", "type": "sphere", "center": [0, 0, 10], "radius": 2},
               {"name": "sphere 2", "type": "sphere", "center": [0, 3, 8], "radius": 2},
               {"name": "sphere 3", "type": "sphere", "center": [0, 1, 9], "radius": 2}]},
  {"id": "camera", "kind": "camera-ray", "convention": "center",
   "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 4,
              "resolution": [8, 6]}, "pixel": [2, 5]}
]})";

// A mix of what a class hands in: right answers (numbers and typed strings), wrong ones,
// named mistakes, and some with steps (right, and wrong with error carried forward).
const std::vector<std::pair<int, std::string>>& answer_kinds() {
  static const std::vector<std::pair<int, std::string>> kinds = {
      {0, R"({"hits": [{"t": 1, "point": [1, 0, 0]}, {"t": 3, "point": [3, 0, 0]}]})"},
      {0, R"({"hits": [{"t": "3"}, {"t": "1"}]})"},
      {0, R"({"hits": [{"t": -3}, {"t": -1}]})"},
      {0, R"({"steps": {"t_ca": 2, "d2": 0.75, "t_hc": 0.5}, "hits": [{"t": 1.5}, {"t": 2.5}]})"},
      {0,
       R"({"steps": {"L": [2, 0, 0], "t_ca": 2, "d2": 0, "t_hc": 1}, "hits": [{"t": 1}, {"t": 3}]})"},
      {1, R"({"hits": [{"t": 3, "point": [3, 3, 3]}]})"},
      {1, R"({"hits": [{"t": "6/2", "point": ["3", "3", "3"]}]})"},
      {2, R"({"object": "sphere 3", "hits": [{"t": 7.27, "point": [0, 0, 7.27]}]})"},
      {2, R"j({"object": "sphere 3", "hits": [{"t": "9 - sqrt(3)"}]})j"},
      {2, R"({"object": "sphere 3", "hits": [{"t": 10.73}]})"},
      {3, R"({"ray": {"origin": [0, 0, 0], "direction": [-1.5, 2.5, -4]}})"},
      {3, R"({"ray": {"origin": [0, 0, 0], "direction": [-2, 2, -4]}})"},
  };
  return kinds;
}

std::vector<std::pair<int, std::string>> generate() {
  const auto& kinds = answer_kinds();
  std::mt19937 rng(42);
  std::vector<std::pair<int, std::string>> out;
  out.reserve(kAnswers);
  for (int i = 0; i < kAnswers; ++i) out.push_back(kinds[rng() % kinds.size()]);
  return out;
}

// The bench bank's problems, each prepared for grading once. A Grader points at its problem,
// so the problems live as long as the program.
std::vector<Grader> prepared_graders() {
  static const std::vector<Problem> problems = [] {
    auto file = parse_json_text("bench.json", kBank);
    std::vector<Problem> out;
    for (const auto& item : Cursor(file).at("problems").items()) out.push_back(read_problem(item));
    return out;
  }();
  std::vector<Grader> graders;
  graders.reserve(problems.size());
  for (const auto& p : problems) graders.emplace_back(p);
  return graders;
}

// One answer, from JSON text to its result as JSON text: what the benchmark times.
std::string grade_to_json(const std::vector<Grader>& graders, int problem,
                          const std::string& text) {
  nlohmann::json answer = nlohmann::json::parse(text);
  GradeResult r = graders[static_cast<std::size_t>(problem)].grade(answer);
  std::string out;
  append_result_json(out, r);
  return out;
}

void BM_GradeAnswers(benchmark::State& state) {
  std::vector<Grader> graders = prepared_graders();
  auto answers = generate();
  std::size_t bytes = 0;
  for (auto _ : state) {
    for (const auto& [problem, text] : answers)
      bytes += grade_to_json(graders, problem, text).size();
  }
  benchmark::DoNotOptimize(bytes);
  state.SetItemsProcessed(state.iterations() * kAnswers);
}
BENCHMARK(BM_GradeAnswers)->Unit(benchmark::kMillisecond)->Iterations(3);

// One kind of answer at a time, to see where the time goes.
void BM_GradeOneKind(benchmark::State& state) {
  std::vector<Grader> graders = prepared_graders();
  auto [problem, text] = answer_kinds()[static_cast<std::size_t>(state.range(0))];
  for (auto _ : state) {
    std::string out = grade_to_json(graders, problem, text);
    benchmark::DoNotOptimize(out);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GradeOneKind)->DenseRange(0, 11);

}  // namespace
}  // namespace raygrade

BENCHMARK_MAIN();
