// Grading ray trees node by node: seed 001's own answer is right; a shadowed point given its
// diffuse term, a missing ray and a ray the scene cannot spawn are marked with the reason.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "grading/grade.h"
#include "json/cursor.h"
#include "json/source.h"
#include "problems/problem.h"
#include "test_util.h"

namespace raygrade {
namespace {

const Problem& seed() {
  static const Bank bank =
      load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems/seeds/seed001-ray-tree.json"});
  return bank.problems.at(0);
}

// The seed's answer, as the sample submission gives it.
nlohmann::json seed_answer() {
  return nlohmann::json::parse(R"({
    "nodes": [
      {"label": "I1", "parent": null, "ray": "primary", "object": "glass sphere", "in_shadow": false},
      {"label": "I2", "parent": "I1", "ray": "reflection", "object": "mirror ceiling", "in_shadow": false},
      {"label": "I3", "parent": "I2", "ray": "reflection", "object": "floor", "in_shadow": false},
      {"label": "I4", "parent": "I1", "ray": "refraction", "object": "glass sphere", "in_shadow": true},
      {"label": "I5", "parent": "I4", "ray": "refraction", "object": "back wall", "in_shadow": true}],
    "all_terms": ["I1", "I2", "I3"],
    "ambient_only": ["I4", "I5"]})");
}

using testing::part;

std::string all_feedback(const PartResult& p) {
  std::string s;
  for (const auto& f : p.feedback) s += f + "\n";
  return s;
}

TEST(RayTreeGrade, SeedAnswerIsRight) {
  GradeResult r = grade_answer(seed(), seed_answer());
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
  EXPECT_DOUBLE_EQ(r.max_score, 3);
  EXPECT_TRUE(r.mistakes.empty());
}

TEST(RayTreeGrade, TheSolversOwnAnswerIsRight) {
  GradeResult r = grade_answer(seed(), seed().task->answer());
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
}

// A shadowed point (I4, whose shadow ray meets the glass sphere) given the diffuse term.
TEST(RayTreeGrade, DiffuseAtAShadowedPointIsWrongWithTheReason) {
  nlohmann::json a = seed_answer();
  a["all_terms"] = {"I1", "I2", "I3", "I4"};
  a["ambient_only"] = {"I5"};
  a["nodes"][3]["terms"] = {"ambient", "diffuse"};
  a["nodes"][3].erase("in_shadow");
  GradeResult r = grade_answer(seed(), a);
  const PartResult* terms = part(r, "terms");
  ASSERT_NE(terms, nullptr);
  EXPECT_EQ(terms->status, PartStatus::kPartial);
  EXPECT_DOUBLE_EQ(terms->points, 0.8);  // four of the five points right
  std::string fb = all_feedback(*terms);
  EXPECT_NE(fb.find("I4 needs ambient only, not ambient and diffuse:"), std::string::npos) << fb;
  EXPECT_NE(fb.find("blocked by glass sphere"), std::string::npos) << fb;
  ASSERT_TRUE(r.has_mistake("diffuse-in-shadow"));
  const PartResult* shadows = part(r, "shadows");
  ASSERT_NE(shadows, nullptr);
  EXPECT_DOUBLE_EQ(shadows->points, 0.8);  // "diffuse" says the student thought I4 lit
}

// I4's shadow ray meets the glass sphere: a student who names the blocker is graded on it.
TEST(RayTreeGrade, TheBlockerNamedIsGraded) {
  nlohmann::json a = seed_answer();
  a["nodes"][3]["shadowed_by"] = {"glass sphere"};
  a["nodes"][4]["shadowed_by"] = "glass sphere";
  GradeResult right = grade_answer(seed(), a);
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
  a["nodes"][3]["shadowed_by"] = {"back wall"};
  GradeResult r = grade_answer(seed(), a);
  const PartResult* shadows = part(r, "shadows");
  ASSERT_NE(shadows, nullptr);
  EXPECT_DOUBLE_EQ(shadows->points, 0.8);  // four of the five points right
  std::string fb = all_feedback(*shadows);
  EXPECT_NE(fb.find("I4 is in shadow, blocked by glass sphere, not back wall"), std::string::npos)
      << fb;
}

TEST(RayTreeGrade, LitPointGivenAmbientOnlyIsNamed) {
  nlohmann::json a = seed_answer();
  a["all_terms"] = {"I1", "I3"};
  a["ambient_only"] = {"I2", "I4", "I5"};
  a["nodes"][1].erase("in_shadow");
  GradeResult r = grade_answer(seed(), a);
  EXPECT_TRUE(r.has_mistake("lit-point-ambient-only"));
  EXPECT_NE(all_feedback(*part(r, "terms")).find("reaches the light"), std::string::npos);
}

// Only the seed's sentence (no tree): terms and shadows are right, the tree is missing.
TEST(RayTreeGrade, ListsAloneEarnTermsAndShadows) {
  nlohmann::json a = {{"all_terms", {"I1", "I2", "I3"}}, {"ambient_only", {"I4", "I5"}}};
  GradeResult r = grade_answer(seed(), a);
  EXPECT_EQ(part(r, "tree")->status, PartStatus::kMissing);
  EXPECT_DOUBLE_EQ(part(r, "terms")->points, 1);
  EXPECT_DOUBLE_EQ(part(r, "shadows")->points, 1);
  EXPECT_DOUBLE_EQ(r.score, 2);
}

// Dropping I5 loses one node of five; a reflection drawn from the matte floor costs half a
// node more and says why the floor spawns none.
TEST(RayTreeGrade, MissingAndImpossibleRaysCostPartOfTheTree) {
  nlohmann::json a = seed_answer();
  a["nodes"].erase(4);
  a["nodes"].push_back(
      {{"label", "I6"}, {"parent", "I3"}, {"ray", "reflection"}, {"object", "back wall"}});
  GradeResult r = grade_answer(seed(), a);
  const PartResult* tree = part(r, "tree");
  EXPECT_DOUBLE_EQ(tree->points, (4 - 0.5) / 5);
  std::string fb = all_feedback(*tree);
  // Named in the form's words: the student's own label of the parent, the object it meets.
  EXPECT_NE(fb.find("Missing: the point where the refraction ray from I4 meets back wall."),
            std::string::npos)
      << fb;
  EXPECT_NE(fb.find("floor does not reflect"), std::string::npos) << fb;
}

TEST(RayTreeGrade, WrongObjectEarnsHalfTheNode) {
  nlohmann::json a = seed_answer();
  a["nodes"][2]["object"] = "back wall";
  GradeResult r = grade_answer(seed(), a);
  EXPECT_DOUBLE_EQ(part(r, "tree")->points, 4.5 / 5);
  EXPECT_NE(all_feedback(*part(r, "tree"))
                .find("I3: the reflection ray from I2 meets floor, not back wall."),
            std::string::npos)
      << all_feedback(*part(r, "tree"));
}

// "object": null says the ray leaves the scene: where the tree's ray meets an object, that
// point earns nothing, and the feedback says what it meets.
TEST(RayTreeGrade, SayingARayLeavesTheSceneWhereItHitsEarnsNothing) {
  nlohmann::json a = seed_answer();
  a["nodes"][2]["object"] = nullptr;
  GradeResult r = grade_answer(seed(), a);
  EXPECT_DOUBLE_EQ(part(r, "tree")->points, 4.0 / 5);
  EXPECT_NE(all_feedback(*part(r, "tree"))
                .find("I3: the reflection ray from I2 meets floor; it does not leave the scene."),
            std::string::npos)
      << all_feedback(*part(r, "tree"));
}

// The ray (0, 0, 0) + t(0, −0.2, −1) reaches the ball of radius 1 at (0, −1, −6) where
// y = −1: at t = 5, the point (0, −1, −5) in front of its centre.
TEST(RayTreeGrade, HitOnlyQuestionGradesObjectAndT) {
  auto f = parse_json_text("hit.json", R"({"id": "h", "kind": "ray-tree", "ask": "hit",
    "ray": {"origin": [0, 0, 0], "direction": [0, -0.2, -1]},
    "scene": {"objects": [
      {"name": "floor", "type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0]},
      {"name": "ball", "type": "sphere", "center": [0, -1, -6], "radius": 1}]}})");
  Problem p = read_problem(Cursor(f));
  GradeResult right = grade_answer(p, {{"object", "ball"}, {"hits", {{{"t", 5}}}}});
  EXPECT_DOUBLE_EQ(right.score, 1);
  GradeResult wrong = grade_answer(p, {{"object", "floor"}, {"hits", {{{"t", 5}}}}});
  EXPECT_DOUBLE_EQ(wrong.score, 0.5);
}

// The ball's point faces away and the floor's is in shadow: I = 0.1 + 0.5·0.2 = 0.2 (the
// problem's own working). A wrong intensity is quoted as typed: "0.50" stays "0.50".
TEST(RayTreeGrade, AWrongIntensityIsQuotedAsTyped) {
  static const Bank bank =
      load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems/scenes/shadows.json"});
  const Problem& p = bank.problems.at(0);
  ASSERT_EQ(p.id, "scene-faces-away-and-shadow");
  for (const char* typed : {"0.50", "5e-1", "1/2"}) {
    GradeResult r = grade_answer(p, {{"intensity", typed}});
    const PartResult* i = part(r, "intensity");
    ASSERT_NE(i, nullptr);
    EXPECT_EQ(i->status, PartStatus::kWrong);
    EXPECT_EQ(i->feedback.at(0),
              fmt::format("The intensity along the primary ray is 0.2, not {}.", typed));
  }
}

// A ball A of radius 1 at the origin, seen from below: the ray from (0, −5, 0) up (0, 1, 0)
// meets it at P = (0, −1, 0), t = 4, N = (0, −1, 0). The lamp at (0, 10, 0) gives L = (0, 1, 0),
// N·L = −1: P faces away from it. A shadow ray cast anyway goes up through A itself and on to
// ball B (radius 1 at (0, 5, 0)), which blocks it: "in shadow" holds as well as "faces away".
// Without B, only "faces away" holds.
Problem facing_away_scene(bool with_blocker, const char* convention = nullptr) {
  std::string objects = R"({"name": "A", "type": "sphere", "center": [0, 0, 0], "radius": 1})";
  if (with_blocker)
    objects += R"(, {"name": "B", "type": "sphere", "center": [0, 5, 0], "radius": 1})";
  std::string conventions =
      convention ? fmt::format(R"("conventions": {{"facing_away": "{}"}},)", convention) : "";
  auto f = parse_json_text("away.json", fmt::format(R"({{"id": "away", "kind": "ray-tree", {}
    "ray": {{"origin": [0, -5, 0], "direction": [0, 1, 0]}},
    "scene": {{"objects": [{}], "lights": [{{"name": "lamp", "position": [0, 10, 0]}}],
               "ambient_light": 1}}}})",
                                                    conventions, objects));
  return read_problem(Cursor(f));
}

nlohmann::json said_shadow(bool in_shadow, const char* by = nullptr) {
  nlohmann::json node = {{"label", "P"},
                         {"parent", nullptr},
                         {"ray", "primary"},
                         {"object", "A"},
                         {"in_shadow", in_shadow}};
  if (by) node["shadowed_by"] = {by};
  return {{"nodes", {node}}, {"ambient_only", {"P"}}, {"all_terms", nlohmann::json::array()}};
}

TEST(RayTreeGrade, FacingAwayAndBlockedAcceptsBothReadings) {
  Problem p = facing_away_scene(true);
  for (bool shadow : {false, true}) {
    GradeResult r = grade_answer(p, said_shadow(shadow));
    EXPECT_DOUBLE_EQ(r.score, r.max_score) << "in_shadow " << shadow;
  }
  GradeResult named = grade_answer(p, said_shadow(true, "B"));
  EXPECT_DOUBLE_EQ(named.score, named.max_score);
  // The wrong blocker is named, and both reasons are given.
  GradeResult wrong = grade_answer(p, said_shadow(true, "A"));
  const PartResult* shadows = part(wrong, "shadows");
  ASSERT_NE(shadows, nullptr);
  EXPECT_NE(shadows->status, PartStatus::kRight);
  EXPECT_NE(all_feedback(*shadows).find("blocked by B, not A"), std::string::npos)
      << all_feedback(*shadows);
}

// A course's convention picks one reading: "shadow-ray" casts the shadow ray first (B blocks it:
// in shadow), "normal-first" tests N·L = −1 first and never casts it (not in shadow).
TEST(RayTreeGrade, FacingAwayConventionPicksOneReading) {
  auto full = [](const Problem& p, bool shadow) {
    GradeResult r = grade_answer(p, said_shadow(shadow));
    return r.score == r.max_score;
  };
  Problem cast = facing_away_scene(true, "shadow-ray");
  EXPECT_TRUE(full(cast, true));
  EXPECT_FALSE(full(cast, false));
  GradeResult named = grade_answer(cast, said_shadow(true, "B"));
  EXPECT_DOUBLE_EQ(named.score, named.max_score);
  Problem normal = facing_away_scene(true, "normal-first");
  EXPECT_TRUE(full(normal, false));
  EXPECT_FALSE(full(normal, true));
  // Without a blocker the convention changes nothing: facing away alone is not a shadow.
  Problem alone = facing_away_scene(false, "shadow-ray");
  EXPECT_TRUE(full(alone, false));
  EXPECT_FALSE(full(alone, true));
  // An unknown value is an error naming its path.
  EXPECT_THROW(facing_away_scene(true, "sometimes"), Error);
}

// The convention decides the reference as it decides grading: under "shadow-ray" the answer
// says P is in shadow, blocked by B, and the worked solution concludes that its shadow ray is;
// under "normal-first" both say it faces away; a bank file's convention does the same. The
// reference answer always gets full marks.
TEST(RayTreeGrade, FacingAwayConventionDecidesTheReference) {
  auto conclusions = [](const Problem& p) {
    std::string all;
    for (const auto& c : p.task->conclusion()) all += c + "\n";
    return all;
  };
  Problem cast = facing_away_scene(true, "shadow-ray");
  nlohmann::json node = cast.task->answer()["nodes"][0];
  EXPECT_EQ(node["in_shadow"], true) << node;
  EXPECT_EQ(node["shadowed_by"], nlohmann::json({"B"})) << node;
  EXPECT_NE(conclusions(cast).find("shadow ray is blocked by B"), std::string::npos)
      << conclusions(cast);
  GradeResult own = grade_answer(cast, cast.task->answer());
  EXPECT_DOUBLE_EQ(own.score, own.max_score);
  Problem normal = facing_away_scene(true, "normal-first");
  node = normal.task->answer()["nodes"][0];
  EXPECT_EQ(node["in_shadow"], false) << node;
  EXPECT_FALSE(node.contains("shadowed_by")) << node;
  EXPECT_NE(conclusions(normal).find("faces away from every light"), std::string::npos)
      << conclusions(normal);
  own = grade_answer(normal, normal.task->answer());
  EXPECT_DOUBLE_EQ(own.score, own.max_score);
  // The convention of the bank file, inherited by its problem.
  auto f = parse_json_text("away.json", R"({"id": "away", "kind": "ray-tree",
    "ray": {"origin": [0, -5, 0], "direction": [0, 1, 0]},
    "scene": {"objects": [{"name": "A", "type": "sphere", "center": [0, 0, 0], "radius": 1},
                          {"name": "B", "type": "sphere", "center": [0, 5, 0], "radius": 1}],
              "lights": [{"name": "lamp", "position": [0, 10, 0]}], "ambient_light": 1}})");
  Conventions file;
  file.facing_away = Conventions::FacingAway::kShadowRay;
  Problem inherited = read_problem(Cursor(f), file);
  EXPECT_EQ(inherited.task->answer()["nodes"][0]["in_shadow"], true);
}

TEST(RayTreeGrade, FacingAwayAloneIsNotAShadow) {
  Problem p = facing_away_scene(false);
  EXPECT_DOUBLE_EQ(grade_answer(p, said_shadow(false)).score,
                   grade_answer(p, said_shadow(false)).max_score);
  GradeResult r = grade_answer(p, said_shadow(true));
  const PartResult* shadows = part(r, "shadows");
  ASSERT_NE(shadows, nullptr);
  EXPECT_EQ(shadows->status, PartStatus::kWrong);
  EXPECT_NE(all_feedback(*shadows).find("P is not in shadow: it faces away from lamp"),
            std::string::npos)
      << all_feedback(*shadows);
}

// Where the answer is wrong (the point given the diffuse term), the feedback gives both
// reasons the lamp does not light P.
TEST(RayTreeGrade, FacingAwayAndBlockedGivesBothReasons) {
  Problem p = facing_away_scene(true);
  nlohmann::json a = said_shadow(false);
  a["all_terms"] = {"P"};
  a["ambient_only"] = nlohmann::json::array();
  std::string fb;
  for (const auto& part : grade_answer(p, a).parts) fb += all_feedback(part);
  EXPECT_NE(fb.find("it faces away from lamp, and its shadow ray toward lamp would also be "
                    "blocked by B"),
            std::string::npos)
      << fb;
}

}  // namespace
}  // namespace raygrade
