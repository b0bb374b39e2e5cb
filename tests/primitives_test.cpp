// Every primitive of the list: its schema examples are read, solved, worked in every solution
// format with a sketch, and graded (its own answer right, a flipped normal named); every level
// of the precision ladder is run on its random and hard cases against the MPFR truth.
#include "shapes/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "accuracy/certified.h"
#include "accuracy/ladder.h"
#include "grading/grade.h"
#include "reports/json_report.h"
#include "reports/render.h"
#include "test_util.h"

namespace raygrade {
namespace primitives_test {  // named: a unity batch of tests shares one anonymous namespace

// A ray towards the example's centre along −w, from 10 sizes away: w is no axis and lies in no
// plane of the examples, so the ray meets every example, flat or solid, from outside.
nlohmann::json ray_towards(const Shape& s) {
  const Vec3d w{0.36, 0.48, 0.8};
  Vec3d o = s.center() + (10 * (s.extent() + 1)) * w;
  return {{"origin", {o.x, o.y, o.z}}, {"direction", {-w.x, -w.y, -w.z}}};
}

const std::vector<TruthCase>& corpus() {
  static const std::vector<TruthCase> cases =
      read_corpus(fmt::format("{}/tests/data/hard_cases.json", RAYGRADE_SOURCE_DIR));
  return cases;
}

// What each level of the ladder is expected to do on ordinary (random) cases: how many wrong
// hit-or-miss decisions it may make in 1000 and the largest relative error of t where it and
// the truth both hit; and on the hard cases whether it decides right wherever certified double
// decides (the boundary is then beyond double rounding), or on every case.
struct Expected {
  const char* level;
  int wrong_per_1000;
  double max_relative;
  enum { kNothing, kWhereDoubleDecides, kEverywhere } hard;
};
constexpr Expected kExpected[] = {
    {"naive float", 20, 1e-3, Expected::kNothing},
    {"naive double", 0, 1e-10, Expected::kNothing},
    {"reference float", 20, 1e-3, Expected::kNothing},
    {"reference double", 0, 1e-12, Expected::kWhereDoubleDecides},
    {"reference long double", 0, 1e-15, Expected::kWhereDoubleDecides},
    {"reference double-double", 0, 1e-15, Expected::kWhereDoubleDecides},
    {"reference MPFR", 0, 1e-15, Expected::kEverywhere},
    {"static filter", 0, 1e-12, Expected::kWhereDoubleDecides},
    {"certified double", 0, 1e-12, Expected::kWhereDoubleDecides},
    {"adaptive", 0, 1e-12, Expected::kEverywhere},
};

// Every level of the ladder on the primitive's random cases and its hard cases of the corpus.
template <typename T>
void check_ladder() {
  Primitive p = primitive_of<T>();
  EXPECT_EQ(primitive_name(p), T::kType);
  std::vector<TruthCase> random;
  for (AccuracyCase& c : random_cases(p, 200, 77)) {
    Truth truth = compute_truth(c, false);
    random.push_back({std::move(c), truth});
  }
  std::vector<TruthCase> hard;
  for (const TruthCase& c : corpus()) {
    if (c.input.primitive == p && !c.truth.boundary) hard.push_back(c);
  }
  EXPECT_GE(hard.size(), 20u) << "hard cases in tests/data/hard_cases.json";
  ASSERT_EQ(ladder_levels().size(), std::size(kExpected));
  for (std::size_t i = 0; i < std::size(kExpected); ++i) {
    const LadderLevel& level = ladder_levels()[i];
    const Expected& e = kExpected[i];
    ASSERT_EQ(level.name, e.level);
    SCOPED_TRACE(level.name);
    ASSERT_NE(level.on[static_cast<std::size_t>(p)], nullptr);
    LevelError r = level_error(level, random);
    EXPECT_EQ(r.judged, 200);
    EXPECT_LE(r.wrong_decisions * 1000, e.wrong_per_1000 * r.judged);
    EXPECT_LE(r.max_relative, e.max_relative);
    if (e.hard == Expected::kNothing) continue;
    for (const TruthCase& c : hard) {
      if (e.hard == Expected::kWhereDoubleDecides && !certified_double(c.input).decided) continue;
      std::optional<double> t = level.nearest(c.input);
      ASSERT_EQ(t.has_value(), c.truth.hit) << c.input.id;
      if (t && e.hard == Expected::kEverywhere && std::isfinite(c.truth.t)) {
        EXPECT_LE(relative_error(*t, c.truth.t), 1e-12 * std::max(1.0, c.truth.condition))
            << c.input.id;
      }
    }
  }
}

template <typename T>
void check_primitive() {
  SCOPED_TRACE(std::string(T::kType));
  nlohmann::ordered_json examples = T::schema().at("examples");
  ASSERT_FALSE(examples.empty());
  for (const auto& example : examples) {
    SCOPED_TRACE(example.dump());
    std::unique_ptr<Shape> shape = testing::shape(example.dump());
    EXPECT_EQ(shape->type(), T::kType);
    nlohmann::json problem_json = {{"id", "example"},
                                   {"points", {{"normal", 1}}},
                                   {"ray", ray_towards(*shape)},
                                   {"object", nlohmann::json::parse(example.dump())}};
    Problem p = testing::problem(problem_json.dump());
    nlohmann::json answer = p.task->answer();
    ASSERT_FALSE(answer.at("hits").empty());

    // Every solution format, with the sketch of the object and the ray.
    Solution s = make_solution(p, "", number_format_for(p));
    EXPECT_FALSE(s.sketch.empty());
    for (Format f : all_formats()) EXPECT_FALSE(render_document(f, {&s}).empty());
    EXPECT_NE(render_document(Format::kHtml, {&s}).find("<svg"), std::string::npos);

    // Its own answer is right.
    GradeResult right = grade_answer(p, answer);
    EXPECT_EQ(right.score, right.max_score);
    EXPECT_TRUE(right.mistakes.empty());

    // The first hit's normal the other way: the primitive's named mistake, or no credit.
    nlohmann::json flipped = answer;
    for (auto& c : flipped["hits"][0]["normal"]) c = -c.get<double>();
    GradeResult wrong = grade_answer(p, flipped);
    EXPECT_LT(wrong.score, wrong.max_score);
    std::string mistake = normal_rule(shape->type()).mistake;
    if (!mistake.empty()) {
      EXPECT_TRUE(wrong.has_mistake(mistake)) << mistake;
    }
  }
  // Every primitive of the list is in the precision study.
  static_assert(HasLadder<T>, "a primitive joins the precision study (shapes/ladder_primitives.h)");
  check_ladder<T>();
}

TEST(Primitives, EveryPrimitiveSolvesRendersAndGradesItsExamples) {
  for_each_primitive([]<PrimitiveType T>() { check_primitive<T>(); });
}

// The table of primitives is the list, in its order, and the schema's object types with it.
TEST(Primitives, TheTableIsTheList) {
  std::vector<std::string_view> listed;
  for_each_primitive([&]<PrimitiveType T>() { listed.push_back(T::kType); });
  std::vector<std::string_view> table;
  for (const ShapeEntry& e : shape_table()) table.push_back(e.type);
  EXPECT_EQ(table, listed);
  EXPECT_EQ(listed.size(), Primitives::size);
}

// No code outside a primitive's own files names it: no .cpp or .h of grader/ outside
// grader/shapes/ (where each primitive's files are) contains a primitive's type, taken from the
// list, as a string literal ("sphere", with its quotes): not the accuracy study, the mistake
// catalogue or the generator, which take the primitives from the list.
TEST(Primitives, NoCodeOutsideTheShapesNamesOne) {
  namespace fs = std::filesystem;
  std::vector<std::string> literals;
  for_each_primitive([&]<typename T>() { literals.push_back(fmt::format("\"{}\"", T::kType)); });
  ASSERT_EQ(literals.size(), Primitives::size);
  fs::path grader = fs::path(RAYGRADE_SOURCE_DIR) / "grader";
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(grader)) {
    fs::path rel = entry.path().lexically_relative(grader);
    std::string top = rel.begin()->string();
    std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || top == "shapes") continue;
    if (ext != ".cpp" && ext != ".h") continue;
    ++files;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    for (const auto& literal : literals) {
      EXPECT_EQ(text.str().find(literal), std::string::npos)
          << "grader/" << rel.string() << " names a primitive: " << literal;
    }
  }
  EXPECT_GT(files, 100);  // the scan found the sources
}

}  // namespace primitives_test
}  // namespace raygrade
