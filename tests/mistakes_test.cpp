// Named mistakes: each is found when made, and never on a right answer.
#include "grading/mistakes.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>

#include "core/error.h"
#include "core/internal_error.h"
#include "grading/grade.h"
#include "grading/submission.h"
#include "shapes/cylinder.h"
#include "shapes/plane.h"
#include "test_util.h"

namespace raygrade {
namespace {

using nlohmann::json;

GradeResult grade(const char* problem, const char* answer) {
  Problem p = testing::problem(problem);
  return grade_answer(p, json::parse(answer));
}

std::vector<std::string> ids(const GradeResult& r) {
  std::vector<std::string> out;
  for (const auto& m : r.mistakes) out.push_back(m.id);
  return out;
}

const char* kMistakesSphere = R"({"id": "s1", "method": "algebraic",
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})";
const char* kSphere2 = R"({"id": "s2",
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [-2, 0, 0], "radius": 1}})";
const char* kFirstHit = R"({"id": "f", "kind": "first-hit", "precision": 2,
  "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
  "objects": [{"name": "sphere 1", "type": "sphere", "center": [0, 0, 10], "radius": 2},
              {"name": "sphere 3", "type": "sphere", "center": [0, 1, 9], "radius": 2}]})";
const char* kCamera = R"({"id": "c", "kind": "camera-ray", "convention": "%s",
  "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 4,
             "resolution": [8, 6]}, "pixel": [2, 5]})";
const char* kDerive = R"({"id": "d", "kind": "derive", "find": ["a", "b", "c"],
  "ray": {"origin": [-3, 0, 0.5], "direction": [1, 0, 0]},
  "object": {"type": "cylinder", "base": [0, 0, 0], "axis": [0, 0, 1], "radius": 1}})";

std::string camera(const char* convention) {
  std::string s = kCamera;
  return s.replace(s.find("%s"), 2, convention);
}

// b² + 4ac with a = 1, b = −4, c = 3: Δ = 28, t = 2 ± √7.
TEST(Mistakes, DiscriminantSign) {
  auto r = grade(kMistakesSphere, R"j({"hits": [{"t": "2 + sqrt(7)"}]})j");
  EXPECT_EQ(ids(r), std::vector<std::string>{"discriminant-sign"});
}

// Case 2 with f = C − O: b = −4 instead of 4 turns the roots −3, −1 into 1, 3.
TEST(Mistakes, QuadraticBSign) {
  auto r = grade(kSphere2, R"({"hits": [{"t": 1}, {"t": 3}]})");
  EXPECT_EQ(ids(r), std::vector<std::string>{"b-sign"});
  EXPECT_DOUBLE_EQ(r.score, 0);
}

TEST(Mistakes, NegativeTGivenAsHit) {
  auto r = grade(kSphere2, R"({"hits": [{"t": -1}, {"t": -3}]})");
  EXPECT_EQ(ids(r), std::vector<std::string>{"negative-t"});
}

// Sphere 3's far root is 9 + √3 = 10.73.
TEST(Mistakes, FarRootAsFirstHit) {
  auto r = grade(kFirstHit, R"({"object": "sphere 3", "hits": [{"t": 10.73}]})");
  EXPECT_EQ(ids(r), std::vector<std::string>{"far-root"});
}

// D = (2, 0, 0), sphere at (6, 0, 0) with r = 1: t = 2.5 and 3.5; along D/|D| 5 and 7.
TEST(Mistakes, TForNormalizedDirection) {
  auto r = grade(R"({"id": "u", "ray": {"origin": [0, 0, 0], "direction": [2, 0, 0]},
    "object": {"type": "sphere", "center": [6, 0, 0], "radius": 1}})",
                 R"({"hits": [{"t": 5}, {"t": 7}]})");
  EXPECT_EQ(ids(r), std::vector<std::string>{"unit-direction-t"});
}

// The unit sphere scaled by 2, seen from (0, 0, −5) along +z: in object space O' = (0, 0, −2.5)
// and D' = (0, 0, 0.5), so −2.5 + 0.5t = ∓1 gives t = 3 and 7. Along D'/|D'| = (0, 0, 1) the
// distances are 1.5 and 3.5 (the values a reader published for 3 and 7).
TEST(Mistakes, TAlongTheUnitObjectSpaceDirection) {
  const char* scaled = R"({"id": "o", "ray": {"origin": [0, 0, -5], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1,
               "transform": [{"scale": 2}]}})";
  auto r = grade(scaled, R"({"hits": [{"t": 1.5}, {"t": 3.5}]})");
  EXPECT_EQ(ids(r), std::vector<std::string>{"object-space-unit-t"});
  EXPECT_NE(r.mistakes.front().message.find("|A⁻¹D| = 0.5"), std::string::npos)
      << r.mistakes.front().message;
  // A rotation keeps lengths: |A⁻¹D| = 1, so there is no such slip to make.
  auto turned = grade(R"({"id": "q", "ray": {"origin": [0, 0, -5], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 0], "radius": 2,
               "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 90}}]}})",
                      R"({"hits": [{"t": 1.5}, {"t": 3.5}]})");
  EXPECT_TRUE(ids(turned).empty()) << ids(turned).front();
}

// Seed 001: n = ac × ab = (0, 0, −16) for a = 0, b = (4,0,0), c = (0,4,0).
TEST(Mistakes, CrossProductOrderFlipsTheNormal) {
  auto r = grade(R"({"id": "tri", "points": {"normal": 1},
    "ray": {"origin": [1, 1, 5], "direction": [0, 0, -1]},
    "object": {"type": "triangle", "vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]]}})",
                 R"({"hits": [{"t": 5, "normal": [0, 0, -16]}], "steps": {"n": [0, 0, -16]}})");
  EXPECT_TRUE(r.has_mistake("cross-order"));
  EXPECT_DOUBLE_EQ(r.score, 2 + 0.5);  // t right; the normal earns the mistake's half
}

TEST(Mistakes, InwardNormal) {
  auto r = grade(R"({"id": "s", "points": {"normal": 1},
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})",
                 R"({"hits": [{"t": 1, "normal": [1, 0, 0]}, {"t": 3, "normal": [1, 0, 0]}]})");
  EXPECT_EQ(ids(r), std::vector<std::string>{"inward-normal"});
}

// Seed 004's camera: d × u = (1, 0, 0); pixel (2, 5) of 8 × 6 with f = 4, d = (0, 0, −1).
// Corner: (−2, 2, −4). Centre: (−1.5, 2.5, −4). With u × d: (2, 2, −4).
TEST(Mistakes, PixelCornerAndCentre) {
  auto centre = grade(camera("center").c_str(), R"({"ray": {"direction": [-2, 2, -4]}})");
  EXPECT_EQ(ids(centre), std::vector<std::string>{"pixel-corner"});
  EXPECT_DOUBLE_EQ(centre.score, 0.5);
  auto corner = grade(camera("corner").c_str(), R"({"ray": {"direction": [-1.5, 2.5, -4]}})");
  EXPECT_EQ(ids(corner), std::vector<std::string>{"pixel-centre"});
  auto flipped = grade(camera("corner").c_str(), R"({"ray": {"direction": [2, 2, -4]}})");
  EXPECT_EQ(ids(flipped), std::vector<std::string>{"cross-order"});
  auto right = grade(camera("corner").c_str(), R"({"ray": {"direction": [-1, 1, -2]}})");
  EXPECT_TRUE(right.mistakes.empty());
  EXPECT_DOUBLE_EQ(right.score, 1);
}

TEST(Mistakes, CylinderSlipAndFormulaMistakes) {
  auto r = grade(kDerive, R"({"a": "vx^2 + vy^2", "b": "2*vx + 2*vy", "c": "px^2 + py^2 - r"})");
  EXPECT_TRUE(r.has_mistake("cylinder-b-no-origin"));
  EXPECT_TRUE(r.has_mistake("r-not-squared"));
  auto s = grade(kDerive, R"j({"b": "-2*(px*vx + py*vy)"})j");
  EXPECT_EQ(ids(s), std::vector<std::string>{"b-sign"});
}

// Sphere at (4, 0, 0) with r = 2: t = 2 and 6; with r for r², t_hc = √2 and t = 4 ∓ √2.
TEST(Mistakes, RadiusNotSquared) {
  auto r = grade(R"({"id": "r", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [4, 0, 0], "radius": 2}})",
                 R"j({"hits": [{"t": "4 - sqrt(2)"}, {"t": "4 + sqrt(2)"}]})j");
  EXPECT_EQ(ids(r), std::vector<std::string>{"r-not-squared"});
}

// Ball A (r = 1 at (10, 0, 0)) lies behind ball B (r = 2 at (5, 0, 0)) on the +x axis: B is
// hit first at t = 3, A at t = 9. r for r² leaves A's roots as they are (1 = 1²), so t = 9 is
// no sign of that slip: it is A's own hit.
TEST(Mistakes, NeverNamedWhereTheRewriteChangesNothing) {
  auto r = grade(R"({"id": "a", "kind": "first-hit",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "objects": [{"name": "A", "type": "sphere", "center": [10, 0, 0], "radius": 1},
                {"name": "B", "type": "sphere", "center": [5, 0, 0], "radius": 2}]})",
                 R"({"object": "A", "hits": [{"t": 9}]})");
  EXPECT_TRUE(ids(r).empty()) << ids(r).front();
  const PartResult* t = nullptr;
  for (const auto& p : r.parts) t = p.name == "t" ? &p : t;
  ASSERT_NE(t, nullptr);
  EXPECT_NE(t->feedback.front().find("where the ray meets A"), std::string::npos)
      << t->feedback.front();
}

// D = (2, 0, 0) towards the unit ball at (3, 0, 0): a = 4, b = −12, c = 8, Δ = 16, t = 1 and
// 2. t = 2 is the far root, and also the distance to the entry (2) along D/|D|: two readings
// fit, so neither is named, and the feedback gives both.
TEST(Mistakes, TwoReadingsThatFitNameNeither) {
  auto r = grade(R"({"id": "u", "kind": "first-hit",
    "ray": {"origin": [0, 0, 0], "direction": [2, 0, 0]},
    "objects": [{"name": "A", "type": "sphere", "center": [3, 0, 0], "radius": 1}]})",
                 R"({"object": "A", "hits": [{"t": 2}]})");
  EXPECT_TRUE(ids(r).empty()) << ids(r).front();
  std::string said;
  for (const auto& p : r.parts) {
    if (p.name == "t") said = fmt::format("{}", fmt::join(p.feedback, " "));
  }
  EXPECT_NE(said.find("Far root"), std::string::npos) << said;
  EXPECT_NE(said.find("D/|D|"), std::string::npos) << said;
  // Either alone is named: t = 2 along D = (1, 0, 0) to the ball at (1.5, 0, 0), r = 0.5, is
  // the far root only (t = 1 and 2).
  auto far = grade(R"({"id": "f", "kind": "first-hit",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "objects": [{"name": "A", "type": "sphere", "center": [1.5, 0, 0], "radius": 0.5}]})",
                   R"({"object": "A", "hits": [{"t": 2}]})");
  EXPECT_EQ(ids(far), std::vector<std::string>{"far-root"});
}

// Ball r = 4 at (3, 1, 0), ray from the origin along +x: f = (−3, −1, 0), f·f = 10, b = −6,
// c = 10 − 16 = −6, Δ = 36 + 24 = 60. A discriminant of 12 comes from b² + 4ac = 36 − 24
// and equally from r for r² (c = 10 − 4 = 6, Δ = 36 − 24): neither slip is named.
TEST(Mistakes, AStepTwoSlipsExplainNamesNeither) {
  const char* ball = R"({"id": "b", "method": "algebraic",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [3, 1, 0], "radius": 4}})";
  auto r = grade(ball, R"({"steps": {"discriminant": 12}})");
  EXPECT_TRUE(ids(r).empty()) << ids(r).front();
  std::string said;
  for (const auto& p : r.parts) {
    if (p.name == "steps") said = fmt::format("{}", fmt::join(p.feedback, " "));
  }
  EXPECT_NE(said.find("More than one slip"), std::string::npos) << said;
  EXPECT_NE(said.find("Sign slip in the discriminant"), std::string::npos) << said;
  EXPECT_NE(said.find("r where r² belongs"), std::string::npos) << said;
  // c = 6 alone is r for r² only.
  EXPECT_EQ(ids(grade(ball, R"({"steps": {"c": 6}})")), std::vector<std::string>{"r-not-squared"});
}

TEST(Mistakes, PlaneDSign) {
  auto r = grade(R"({"id": "p", "method": "implicit",
    "ray": {"origin": [0, 0, 0], "direction": [1, 1, 1]},
    "object": {"type": "plane", "point": [3, 3, 3], "normal": [1, 1, 0]}})",
                 R"({"steps": {"D": 6}})");
  EXPECT_EQ(ids(r), std::vector<std::string>{"plane-d-sign"});
}

// The reference answer of every problem of the bank earns full marks and no mistake.
TEST(Mistakes, NeverReportedOnTheReferenceAnswer) {
  Bank bank = load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems"});
  ASSERT_FALSE(bank.problems.empty());
  for (const auto& p : bank.problems) {
    GradeResult r = grade_answer(p, p.task->answer());
    EXPECT_TRUE(r.mistakes.empty()) << p.id << ": " << r.mistakes.front().id;
    EXPECT_NEAR(r.fraction(), 1, 1e-12) << p.id;
  }
}

TEST(Mistakes, CatalogueIsComplete) {
  for (const char* id :
       {"discriminant-sign", "b-sign", "plane-d-sign", "far-root", "negative-t", "unit-direction-t",
        "cross-order", "inward-normal", "pixel-corner", "pixel-centre", "cylinder-b-no-origin",
        "r-not-squared", "object-space-unit-t"}) {
    EXPECT_FALSE(mistake_info(id).explanation.empty()) << id;
  }
}

// A primitive's own mistakes join the catalogue and the formula mistakes from its own files,
// after grading's own, and no id is in the catalogue twice.
TEST(Mistakes, PrimitivesOwnMistakesJoinFromTheirFiles) {
  for (const auto* own : {&Plane::mistakes(), &Cylinder::mistakes()}) {
    for (const PrimitiveMistake& m : *own) {
      EXPECT_EQ(mistake_info(m.info.id).title, m.info.title) << m.info.id;
      auto it = std::find_if(formula_mistakes().begin(), formula_mistakes().end(),
                             [&](const FormulaMistake& f) { return f.id == m.info.id; });
      ASSERT_NE(it, formula_mistakes().end()) << m.info.id;
      EXPECT_EQ(it->rewrite, m.rewrite) << m.info.id;
      EXPECT_GT(it - formula_mistakes().begin(), 3) << m.info.id << " is tried after b-sign";
    }
  }
  std::set<std::string_view> ids;
  for (const MistakeInfo& m : mistake_catalogue()) EXPECT_TRUE(ids.insert(m.id).second) << m.id;
  // The plane's D = +N·V0: step D's formula −N·V0 negated; another step untouched.
  E d = -dot(sym("N", "N"), sym("V0", "V_0"));
  ASSERT_TRUE(Plane::mistakes().front().rewrite("D", d).has_value());
  EXPECT_FALSE(Plane::mistakes().front().rewrite("t", d).has_value());
}

// A mistake id missing from the catalogue is a bug of raygrade, never bad input: an
// InternalError, which no handler of Error (the input's faults) takes for the file's fault.
TEST(Mistakes, UnknownIdIsAnInternalErrorNotBadInput) {
  EXPECT_THROW(mistake_info("no-such-mistake"), InternalError);
  bool reported_as_input = false;
  try {
    mistake_info("no-such-mistake");
  } catch (const Error&) {
    reported_as_input = true;
  } catch (const InternalError&) {
  }
  EXPECT_FALSE(reported_as_input);
}

}  // namespace
}  // namespace raygrade

namespace raygrade {
namespace {

// Every mistake id the code names is in the catalogue. The places a named mistake starts from
// are read in the sources: make_mistake("id", ...), mistake_info("id"), `id = "id"`, a reading
// {"id", ...} pushed onto `readings`, and a primitive's kNormalMistake. An id written
// there that the catalogue lacks would only fail when a student made that mistake.
TEST(Mistakes, EveryIdTheCodeNamesIsInTheCatalogue) {
  std::set<std::string> catalogue;
  for (const auto& m : mistake_catalogue()) catalogue.emplace(m.id);
  const std::regex uses[] = {
      std::regex(R"re(make_mistake\(\s*"([^"]*)")re"),
      std::regex(R"re(mistake_info\(\s*"([^"]*)")re"),
      std::regex(R"re(\bid\s*=\s*"([^"]*)")re"),
      std::regex(R"re(readings\.push_back\(\s*\{\s*"([^"]+)")re"),
      std::regex(R"re(kNormalMistake\s*=\s*"([^"]*)")re"),
  };
  int found = 0;
  std::vector<std::string> unknown;
  for (const char* folder : {"grader/grading", "grader/shapes", "grader/kinds", "grader/scenes"}) {
    for (const auto& entry : std::filesystem::directory_iterator(testing::kSource + "/" + folder)) {
      std::string text = testing::read_all(entry.path());
      for (const auto& use : uses) {
        for (std::sregex_iterator it(text.begin(), text.end(), use), end; it != end; ++it) {
          std::string id = (*it)[1];
          ++found;
          if (!catalogue.count(id)) {
            unknown.push_back(fmt::format("{}: '{}'", entry.path().filename().string(), id));
          }
        }
      }
    }
  }
  EXPECT_GE(found, 20) << "the scan finds the places mistakes are named: has their form changed?";
  EXPECT_TRUE(unknown.empty()) << "ids the catalogue lacks: "
                               << fmt::format("{}", fmt::join(unknown, "; "));
}

}  // namespace
}  // namespace raygrade
