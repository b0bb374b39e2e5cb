// Grading components of a node's intensity, one part each, with the values worked by hand in
// the statements of problems/scenes/components.json.
#include <gtest/gtest.h>

#include "core/error.h"
#include "grading/grade.h"
#include "test_util.h"

namespace raygrade {
namespace {

const Problem& bank_problem(const std::string& id) {
  static const Bank bank =
      load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems/scenes/components.json"});
  for (const auto& p : bank.problems) {
    if (p.id == id) return p;
  }
  throw std::runtime_error("no problem " + id);
}

using testing::part;

nlohmann::json components(const std::string& text) {
  return {{"components", nlohmann::json::parse(text)}};
}

// Ambient 0.1, diffuse 0.6, specular 0.3·(√2/2)² = 0.15, reflected 0.5·0.4 = 0.2.
TEST(ComponentGrade, EachComponentIsAPart) {
  const Problem& p = bank_problem("components-mirror-floor");
  GradeResult r =
      grade_answer(p, components(R"({"I1": {"ambient": 0.1, "diffuse": 0.6, "specular": 0.15,
                               "reflected": 0.2}})"));
  EXPECT_DOUBLE_EQ(r.max_score, 4);
  EXPECT_DOUBLE_EQ(r.score, 4);
  for (const char* name : {"I1.ambient", "I1.diffuse", "I1.specular", "I1.reflected"}) {
    ASSERT_NE(part(r, name), nullptr) << name;
  }
  EXPECT_DOUBLE_EQ(grade_answer(p, p.task->answer()).score, 4);
}

// The total 1.05 given as the diffuse term: that part alone is wrong, and named.
TEST(ComponentGrade, TheTotalForAComponentIsNamed) {
  const Problem& p = bank_problem("components-mirror-floor");
  GradeResult r =
      grade_answer(p, components(R"({"I1": {"ambient": 0.1, "diffuse": 1.05, "specular": 0.15,
                               "reflected": 0.2}})"));
  EXPECT_DOUBLE_EQ(r.score, 3);
  EXPECT_EQ(part(r, "I1.diffuse")->status, PartStatus::kWrong);
  EXPECT_TRUE(r.has_mistake("component-is-total"));
}

// Light B is blocked: counting it gives diffuse 0.9 and specular 0.509117 (0.296985 + 0.3·√2/2).
TEST(ComponentGrade, TermsWithoutTheShadowAreNamed) {
  const Problem& p = bank_problem("components-two-lights-one-blocked");
  GradeResult right = grade_answer(p, components(R"({"I1": {"diffuse": 0.4, "specular": 0.296985,
                                             "local": 0.796985}})"));
  EXPECT_DOUBLE_EQ(right.score, 3);
  GradeResult r = grade_answer(
      p, components(R"({"I1": {"diffuse": 0.4, "specular": 0.509117, "local": 0.796985}})"));
  EXPECT_DOUBLE_EQ(r.score, 2);
  EXPECT_TRUE(r.has_mistake("diffuse-in-shadow"));
  // Graded to 6 decimals (the problem's precision), shown to 6.
  EXPECT_NE(
      part(r, "I1.specular")->feedback.front().find("I1's specular is 0.296985, not 0.509117"),
      std::string::npos)
      << part(r, "I1.specular")->feedback.front();
}

// The wall's 0.4 given as what the mirror reflects, instead of k_r·I_R = 0.2.
TEST(ComponentGrade, AnUnweightedChildIsNamed) {
  const Problem& p = bank_problem("components-mirror-and-wall");
  GradeResult r =
      grade_answer(p, components(R"({"I1": {"ambient": 0.1, "reflected": 0.4, "total": 0.5},
                        "I2": {"total": 0.4}})"));
  EXPECT_DOUBLE_EQ(r.score, 2);
  EXPECT_TRUE(r.has_mistake("secondary-unweighted"));
}

// k_t·I_T = 0.8·0.5 = 0.4 through the water's surface; a missing component earns nothing.
TEST(ComponentGrade, TheTransmittedShareAndAMissingPart) {
  const Problem& p = bank_problem("components-into-water");
  GradeResult r = grade_answer(p, components(R"({"I1": {"transmitted": 0.4}})"));
  EXPECT_DOUBLE_EQ(r.score, 1);
  EXPECT_DOUBLE_EQ(r.max_score, 3);
  EXPECT_EQ(part(r, "I2.ambient")->status, PartStatus::kMissing);
}

// A wrong component is quoted as the student typed it ("0.40", "4e-1"), not reformatted.
TEST(ComponentGrade, AWrongComponentIsQuotedAsTyped) {
  const Problem& p = bank_problem("components-mirror-and-wall");
  GradeResult r = grade_answer(
      p, components(R"({"I1": {"ambient": "0.10", "reflected": "0.40", "total": "3e-1"},
                        "I2": {"total": "4e-1"}})"));
  EXPECT_DOUBLE_EQ(r.score, 3);
  EXPECT_EQ(part(r, "I1.reflected")->feedback.at(0), "I1's reflected is 0.2, not 0.40.");
  GradeResult e = grade_answer(p, components(R"({"I1": {"total": "5e-1"}})"));
  EXPECT_EQ(part(e, "I1.total")->feedback.at(0), "I1's intensity is 0.3, not 5e-1.");
}

void expect_error(const std::string& components, const std::string& ask, const std::string& words) {
  try {
    testing::problem(R"({"id": "c", "kind": "ray-tree", "ask": ")" + ask + R"(",
      "ray": {"origin": [0, 1, 0], "direction": [0, -1, 0]},
      "scene": {"objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}]},
      "components": )" +
                     components + "}");
    ADD_FAILURE() << "no error for " << components;
  } catch (const Error& e) {
    EXPECT_NE(e.diagnostic().message.find(words), std::string::npos) << e.diagnostic().message;
  }
}

TEST(ComponentGrade, BadComponentsAreErrors) {
  expect_error(R"({"I1": ["diffuse"]})", "tree", "needs \"ask\": \"intensity\"");
  expect_error(R"({"I7": ["diffuse"]})", "intensity",
               "no hit point labelled 'I7' (its points: I1)");
  expect_error(R"({"I1": ["refracted"]})", "intensity", "unknown component 'refracted'");
  expect_error(R"({"I1": ["diffuse", "diffuse"]})", "intensity", "asked twice");
}

// A colour scene's intensities are graded channel by channel as a whole; its components are
// not asked one by one.
TEST(ComponentGrade, ComponentsOfAColourSceneAreAnErrorAtThem) {
  try {
    testing::problem(R"({"id": "c", "kind": "ray-tree", "ask": "intensity",
      "ray": {"origin": [0, 1, 0], "direction": [0, -1, 0]},
      "scene": {"objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                             "material": {"diffuse": [0.5, 0.25, 0]}}],
                "lights": [{"position": [0, 5, 0]}]},
      "components": {"I1": ["diffuse"]}})");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().path, "/components");
    EXPECT_EQ(e.diagnostic().code, "unsupported");
  }
}

}  // namespace
}  // namespace raygrade
