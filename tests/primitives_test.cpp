// Every primitive of the list: its schema examples are read, solved, worked in every solution
// format with a sketch, and graded (its own answer right, a flipped normal named).
#include "shapes/primitives.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "grading/grade.h"
#include "reports/json_report.h"
#include "reports/render.h"
#include "test_util.h"

namespace raygrade {
namespace {

// A ray towards the example's centre along −w, from 10 sizes away: w is no axis and lies in no
// plane of the examples, so the ray meets every example, flat or solid, from outside.
nlohmann::json ray_towards(const Shape& s) {
  const Vec3d w{0.36, 0.48, 0.8};
  Vec3d o = s.center() + (10 * (s.extent() + 1)) * w;
  return {{"origin", {o.x, o.y, o.z}}, {"direction", {-w.x, -w.y, -w.z}}};
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
    std::string mistake = shape->normal_rule().mistake;
    if (!mistake.empty()) {
      EXPECT_TRUE(wrong.has_mistake(mistake)) << mistake;
    }
  }
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
// list, as a string literal ("sphere", with its quotes). grader/accuracy/ is left out: its
// study names its six primitives itself until it too is derived from the list.
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
    if (!entry.is_regular_file() || top == "shapes" || top == "accuracy") continue;
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

}  // namespace
}  // namespace raygrade
