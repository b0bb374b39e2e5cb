// Every catalogued mistake where it can occur: a named mistake is a change to a step of the
// worked derivation (grading/mistakes.h), so it applies to every kind whose derivation has
// that step. The table of (mistake, kind) pairs is derived here from the catalogue's changes
// and the derivations of the bundled bank; docs/grading.md shows it; and each pair is planted
// in an answer worked by hand, which must be graded with the mistake named.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "grading/grade.h"
#include "grading/mistakes.h"
#include "problems/problem.h"
#include "test_util.h"

namespace raygrade {
namespace step_mistakes_test {

using nlohmann::json;
using Pair = std::pair<std::string, std::string>;  // (mistake, kind)

// Every number of an answer (a triple counts as one vector), however deeply it is nested.
void answer_values(const json& j, std::vector<json>& out) {
  bool triple =
      j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number();
  if (j.is_number() || triple) {
    out.push_back(j);
    return;
  }
  if (j.is_array() || j.is_object()) {
    for (const auto& x : j) answer_values(x, out);
  }
}

// The pairs where a mistake changes a number of some bundled problem's answer: the step that
// computes the number has another value in the mistaken derivation.
std::set<Pair> derived_table() {
  Bank bank = load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems"});
  std::set<Pair> table;
  for (const auto& p : bank.problems) {
    std::string method = p.task->methods().front();
    std::vector<SolutionPart> right = p.task->derive(method, nullptr);
    std::vector<json> values;
    answer_values(p.task->answer(), values);
    for (const auto& m : mistaken_solutions(*p.task)) {
      if (m.method != method) continue;
      for (const auto& v : values) {
        const Step* step = find_answer_step(right, v);
        if (!step) continue;
        const Step* changed = find_step(m.parts, step->name);
        if (changed && !same_step_value(changed->value, step->value)) {
          table.insert({m.id, p.kind});
          break;
        }
      }
    }
  }
  return table;
}

// The table as docs/grading.md shows it: a row per mistake, its kinds in the table's order.
std::string markdown(const std::set<Pair>& table) {
  std::map<std::string, std::vector<std::string>> rows;
  for (const auto& k : kind_table()) {
    for (const auto& [id, kind] : table) {
      if (kind == k.name) rows[id].push_back(kind);
    }
  }
  std::string out = "| Mistake | Kinds whose derivation has the step it changes |\n| --- | --- |\n";
  for (const auto& m : mistake_catalogue()) {
    auto it = rows.find(std::string(m.id));
    if (it == rows.end()) continue;
    out += fmt::format("| `{}` | {} |\n", m.id, fmt::join(it->second, ", "));
  }
  return out;
}

// A problem and an answer with one slip in it, worked by hand.
struct Plant {
  const char* problem;
  const char* answer;
};

// Seed 004's camera (d × u = (1, 0, 0); pixel (2, 5) of 8 × 6, f = 4, d = (0, 0, −1)), the
// corner convention: x_diff = −2, y_diff = 2, so d_r = (−2, 2, −4); with u × d = (−1, 0, 0)
// for v it is (2, 2, −4).
constexpr const char* kCamera = R"({"id": "c", "kind": "camera-ray", "convention": "corner",
  "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 4,
             "resolution": [8, 6]}, "pixel": [2, 5]})";

// A camera by bounds: w = (0, 0, 1), u = up × w = (1, 0, 0), v = w × u = (0, 1, 0); pixel
// (2, 1) of 8 × 6 over [−2, 2] × [−1.5, 1.5], through its centre: u_s = −2 + 2.5·0.5 = −0.75,
// v_s = −1.5 + 1.5·0.5 = −0.75, D = −w + u_s·u + v_s·v = (−0.75, −0.75, −1). Both cross
// products turned: u = w × up = (−1, 0, 0), v = u × w = (0, 1, 0), D = (0.75, −0.75, −1).
constexpr const char* kViewRay = R"({"id": "v", "kind": "view-ray", "convention": "center",
  "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 1,
             "bounds": [-2, 2, -1.5, 1.5], "resolution": [8, 6], "pixel_origin": "bottom-left"},
  "pixel": [2, 1]})";

constexpr const char* kViewRayCorner = R"({"id": "v", "kind": "view-ray", "convention": "corner",
  "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 1,
             "bounds": [-2, 2, -1.5, 1.5], "resolution": [8, 6], "pixel_origin": "bottom-left"},
  "pixel": [2, 1]})";

// d = (0.6, −0.8, 0) into n2 = 1.5 from n1 = 1 through the floor n = (0, 1, 0): cos θi = 0.8.
// With η = n2/n1 = 1.5 instead of 1/1.5: k = 1 − 2.25·(1 − 0.64) = 0.19 and
// t = 1.5·d + (1.5·0.8 − √0.19)·n = (0.9, −√0.19, 0) = (0.9, −0.435889894354, 0).
constexpr const char* kRefract = R"({"id": "r", "kind": "refract", "direction": [0.6, -0.8, 0],
  "normal": [0, 1, 0], "n1": 1, "n2": 1.5})";

// Air to glass at 60°: the right reflectance is about 0.09. With the indices exchanged,
// η = 1.5 and k = 1 − 2.25·sin²60° = 1 − 2.25·0.75 < 0: total internal reflection, F = 1.
constexpr const char* kFresnel = R"({"id": "f", "kind": "fresnel", "model": "exact", "n1": 1,
  "n2": 1.5, "angle": 60})";

// testing::kTwoLightShade by hand: I_amb = 0.1·2 = 0.2. Light A: L = (0.6, 0.8, 0), N·L = 0.8,
// diffuse 0.5·0.8 = 0.4, R = (−0.6, 0.8, 0) = V so R·V = 1 and specular 0.3; I = 0.9. Light
// B (blocked): L = (0, 1, 0), N·L = 1, diffuse 0.5, R = (0, 1, 0), R·V = 0.8, specular
// 0.3·0.8¹² = 0.0206158430208. Counting B: I = 0.9 + 0.5 + 0.0206158430208; A left out too:
// I = 0.2, the ambient term alone.
constexpr const char* kShadeCountingB = R"({"intensity": 1.4206158430208})";
constexpr const char* kShadeAmbientOnly = R"({"intensity": 0.2})";

// Ball r = 2 at (4, 0, 0) from the origin along +x: t = 2 and 6. With r for r², t_hc = √2.
constexpr const char* kBall = R"({"id": "b", "method": "algebraic",
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [4, 0, 0], "radius": 2}})";

// Phong against Blinn-Phong by hand: the light at (0, 5, 0) over the floor N = (0, 1, 0), the
// eye at (−3, 4, 0): L = (0, 1, 0), V = (−0.6, 0.8, 0), R = L, R·V = 0.8. I = 0.1·2 + 0.5·1 +
// 0.3·0.8¹² = 0.7206158430208. With H = (L + V)/‖L + V‖ = (−0.6, 1.8, 0)/√3.6, (N·H)² = 3.24/3.6
// = 0.9, so (N·H)¹² = 0.9⁶ = 0.531441 and I = 0.2 + 0.5 + 0.3·0.531441 = 0.8594323.
constexpr const char* kOverheadShade = R"({"id": "s", "kind": "shade",
    "point": [0, 0, 0], "normal": [0, 1, 0], "eye": [-3, 4, 0], "ambient_light": 2,
    "material": {"ambient": 0.1, "diffuse": 0.5, "specular": 0.3, "shininess": 12},
    "lights": [{"name": "A", "position": [0, 5, 0]}]})";

// The plants, one per pair.
const std::map<Pair, Plant>& plants() {
  static const std::map<Pair, Plant> p = {
      // b² + 4ac with a = 1, b = −8, c = 12: Δ = 112, t = 4 ± √28.
      {{"discriminant-sign", "intersect"}, {kBall, R"j({"hits": [{"t": "4 + sqrt(28)"}]})j"}},
      // b = 2D·(C − O) = +8 instead of 2D·(O − C) = −8.
      {{"b-sign", "intersect"}, {kBall, R"({"steps": {"b": 8}})"}},
      {{"r-not-squared", "intersect"},
       {kBall, R"j({"hits": [{"t": "4 - sqrt(2)"}, {"t": "4 + sqrt(2)"}]})j"}},
      // n = ab × ac = (4, 0, 0) × (0, 4, 0) = (0, 0, 16); ac × ab = (0, 0, −16).
      {{"cross-order", "intersect"},
       {R"({"id": "tri", "points": {"normal": 1},
    "ray": {"origin": [1, 1, 5], "direction": [0, 0, -1]},
    "object": {"type": "triangle", "vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]]}})",
        R"({"hits": [{"t": 5, "normal": [0, 0, -16]}]})"}},
      {{"cross-order", "camera-ray"}, {kCamera, R"({"ray": {"direction": [2, 2, -4]}})"}},
      {{"cross-order", "view-ray"}, {kViewRay, R"({"direction": [0.75, -0.75, -1]})"}},
      // The same pixel at its corner: u_s = −2 + 2·0.5 = −1, v_s = −1.5 + 1·0.5 = −1, so
      // D = (−1, −1, −1); a corner problem answered at the centre gives (−0.75, −0.75, −1).
      {{"pixel-corner", "view-ray"}, {kViewRay, R"({"direction": [-1, -1, -1]})"}},
      {{"pixel-centre", "view-ray"}, {kViewRayCorner, R"({"direction": [-0.75, -0.75, -1]})"}},
      {{"n1-n2-swapped", "refract"}, {kRefract, R"({"direction": [0.9, -0.435889894354, 0]})"}},
      {{"n1-n2-swapped", "fresnel"}, {kFresnel, R"({"reflectance": 1})"}},
      // A ray from the centre of a glass ball leaves it once: from 1.5 into the air's 1.
      {{"n1-n2-swapped", "ray-tree"},
       {R"({"id": "p", "kind": "ray-tree", "ask": "media",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "scene": {"objects": [{"name": "A", "type": "sphere", "center": [0, 0, 0], "radius": 1,
       "material": {"transparency": 1, "refractive_index": 1.5}}]}})",
        R"({"hits": [{"n1": 1, "n2": 1.5}]})"}},
      // The triangle (0, 0, 0), (2, 0, 0), (0, 2, 2): e1 × e2 = (2, 0, 0) × (0, 2, 2) =
      // (0, −4, 4); e2 × e1 = (0, 4, −4).
      {{"cross-order", "normal"},
       {R"({"id": "n", "kind": "normal", "point": [0.5, 0.5, 0.5],
    "object": {"type": "triangle", "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 2]]}})",
        R"({"normal": [0, 4, -4]})"}},
      // The z-axis cylinder of radius 1, the ray from (2, 0, 0) along −x: b = 2(p_x·v_x +
      // p_y·v_y) = −4; without the origin's terms, 2v_x + 2v_y = −2.
      {{"cylinder-b-no-origin", "intersect"},
       {R"({"id": "cy", "ray": {"origin": [2, 0, 0], "direction": [-1, 0, 0]},
    "object": {"type": "cylinder", "base": [0, 0, 0], "axis": [0, 0, 1], "radius": 1}})",
        R"({"steps": {"b": -2}})"}},
      // Ball A of radius 2 at (4, 0, 0), the only object, from the origin along +x: first hit
      // at t = 2; with r for r², t_hc = √2 and t = 4 − √2.
      {{"r-not-squared", "first-hit"},
       {R"({"id": "fh", "kind": "first-hit",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "objects": [{"name": "A", "type": "sphere", "center": [4, 0, 0], "radius": 2}]})",
        R"j({"object": "A", "hits": [{"t": "4 - sqrt(2)"}]})j"}},
      {{"diffuse-in-shadow", "shade"}, {testing::kTwoLightShade, kShadeCountingB}},
      {{"lit-point-ambient-only", "shade"}, {testing::kTwoLightShade, kShadeAmbientOnly}},
      {{"halfway-vector", "shade"}, {kOverheadShade, R"({"intensity": 0.8594323})"}},
  };
  return p;
}

TEST(StepMistakes, TableIsDerivedFromTheStepsAndShownInTheDocs) {
  std::set<Pair> table = derived_table();
  std::string shown = markdown(table);
  std::string docs = testing::read_all(std::string(RAYGRADE_SOURCE_DIR) + "/docs/grading.md");
  EXPECT_NE(docs.find(shown), std::string::npos)
      << "docs/grading.md does not show the table of mistakes and kinds as derived:\n"
      << shown;
  for (const auto& pair : table) {
    EXPECT_TRUE(plants().contains(pair))
        << "no planted answer for " << pair.first << " in " << pair.second;
  }
  // The three mistakes once found only in ray trees apply wherever their step is.
  EXPECT_TRUE(table.contains({"n1-n2-swapped", "refract"}));
  EXPECT_TRUE(table.contains({"n1-n2-swapped", "fresnel"}));
  EXPECT_TRUE(table.contains({"diffuse-in-shadow", "shade"}));
  EXPECT_TRUE(table.contains({"lit-point-ambient-only", "shade"}));
}

TEST(StepMistakes, EveryPairPlantedIsNamed) {
  for (const auto& [pair, plant] : plants()) {
    Problem p = testing::problem(plant.problem);
    ASSERT_EQ(p.kind, pair.second) << pair.first;
    GradeResult r = grade_answer(p, json::parse(plant.answer));
    EXPECT_TRUE(r.has_mistake(pair.first))
        << pair.first << " in " << pair.second << ": "
        << (r.mistakes.empty() ? std::string("no mistake named") : r.mistakes.front().id);
  }
}

// The reference answer of a problem where a step mistake applies names none.
TEST(StepMistakes, RightAnswersNameNone) {
  for (const auto& [pair, plant] : plants()) {
    Problem p = testing::problem(plant.problem);
    GradeResult r = grade_answer(p, p.task->answer());
    EXPECT_TRUE(r.mistakes.empty()) << pair.second << ": " << r.mistakes.front().id;
  }
}

}  // namespace step_mistakes_test
}  // namespace raygrade
