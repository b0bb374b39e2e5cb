// Refraction into solids and half-spaces, and the list of nested media: every value here is
// worked by hand (Snell's law at 45°, the containers list by hand) or computed at high
// precision outside raygrade.
#include <gtest/gtest.h>

#include "core/error.h"
#include "grading/grade.h"
#include "kinds/ray_tree.h"
#include "test_util.h"

namespace raygrade {
namespace {

constexpr double kTight = 1e-12;

const RayTree& tree_of(const Problem& p) {
  return dynamic_cast<const RayTreeTask&>(*p.task).tree();
}

// Water (n = 1.33) below the plane y = 0 and an opaque bottom at y = −2; the ray comes in at
// 45° from (−1, 1, 0). `water` is the plane's JSON without its material.
std::string pool(const std::string& water) {
  return R"({"id": "p", "kind": "ray-tree",
    "ray": {"origin": [-1, 1, 0], "direction": [1, -1, 0]},
    "scene": {"max_depth": 3, "objects": [)" +
         water + R"(, "material": {"transparency": 1, "refractive_index": 1.33}},
      {"name": "bottom", "type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0]}]}})";
}

// sin θt = sin 45°/1.33 = 0.5316592339748478, cos θt = 0.8469583572580638 (at high
// precision); the bottom is 2/cos θt = 2.3613911863090697 further on, at x = 1.255455429228037.
TEST(HalfSpace, ARayEnteringWaterRefractsAndStaysInIt) {
  Problem p = testing::problem(pool(
      R"({"name": "water", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
          "half_space": true)"));
  const RayTree& t = tree_of(p);
  const TreeNode* in = t.find("P");
  ASSERT_NE(in, nullptr);
  EXPECT_DOUBLE_EQ(in->n1, 1);
  EXPECT_DOUBLE_EQ(in->n2, 1.33);
  const TreeNode* below = t.find("P.T");
  ASSERT_NE(below, nullptr);
  EXPECT_NEAR(below->ray.direction.x, 0.5316592339748478, kTight);
  EXPECT_NEAR(below->ray.direction.y, -0.8469583572580638, kTight);
  EXPECT_EQ(p.task->answer()["nodes"][1]["object"], "bottom");
  EXPECT_NEAR(below->point.x, 1.255455429228037, 1e-9);
  EXPECT_EQ(below->media, std::vector<int>{0});  // in the water
}

// Without half_space the plane is a thin sheet: the ray goes straight on to (2, −2, 0).
TEST(HalfSpace, WithoutItAPlaneIsAThinSheet) {
  Problem p = testing::problem(
      pool(R"({"name": "water", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0])"));
  const TreeNode* below = tree_of(p).find("P.T");
  ASSERT_NE(below, nullptr);
  EXPECT_NEAR(below->point.x, 2, kTight);
  EXPECT_TRUE(below->media.empty());
}

// Inside glass (n = 1.5) at 45° to the top face: k = 1 − 1.5²·(1 − 1/2) = −0.125 < 0, total
// internal reflection; the reflection ray stays in the glass.
TEST(HalfSpace, LeavingGlassPastTheCriticalAngleReflectsTotally) {
  Problem p = testing::problem(R"({"id": "p", "kind": "ray-tree",
    "ray": {"origin": [-1, -1, 0], "direction": [1, 1, 0]},
    "scene": {"max_depth": 3, "objects": [
      {"name": "glass", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
       "half_space": true, "material": {"transparency": 1, "refractive_index": 1.5}},
      {"name": "floor", "type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0]}]}})");
  const RayTree& t = tree_of(p);
  const TreeNode& top = t.nodes.front();
  EXPECT_TRUE(top.inside);
  EXPECT_DOUBLE_EQ(top.n1, 1.5);
  EXPECT_DOUBLE_EQ(top.n2, 1);
  EXPECT_NEAR(top.refraction_math.k, -0.125, kTight);
  EXPECT_EQ(top.refraction, -1);
  const TreeNode* back = t.find("P.R");
  ASSERT_NE(back, nullptr);
  EXPECT_TRUE(back->total_internal_reflection);
  EXPECT_NEAR(back->point.x, 2, 1e-12);
  EXPECT_EQ(back->media, std::vector<int>{0});
}

void expect_error(const std::string& text, const std::string& code, const std::string& words) {
  try {
    testing::problem(text);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().code, code) << e.diagnostic().message;
    EXPECT_NE(e.diagnostic().message.find(words), std::string::npos) << e.diagnostic().message;
  }
}

TEST(HalfSpace, OnlyATransparentPlaneInASceneBoundsOne) {
  std::string scene_start = R"({"id": "p", "kind": "ray-tree",
    "ray": {"origin": [0, 1, 0], "direction": [0, -1, 0]}, "scene": {"objects": [)";
  std::string glass = R"("material": {"transparency": 1, "refractive_index": 1.5})";
  expect_error(scene_start +
                   R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 0, 1]],
                   "half_space": true, )" +
                   glass + "}]}}",
               "invalid", "a triangle bounds no volume");
  expect_error(scene_start + R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                   "half_space": true, )" +
                   glass + "}]}}",
               "invalid", "already bounds its inside");
  expect_error(scene_start + R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                   "half_space": true}]}})",
               "invalid", "must be transparent");
  expect_error(R"({"id": "p", "kind": "intersect", "ray": {"origin": [0, 1, 0],
                 "direction": [0, -1, 0]}, "object": {"type": "plane", "point": [0, 0, 0],
                 "normal": [0, 1, 0], "half_space": true}})",
               "unused-key", "scenes only");
}

// Water over a glass slab: at y = −1 the ray is in the water, so n1 = 1.33 (not 1) and
// sin θ = 1.33·0.5316592339748478/1.5 = sin 45°/1.5 = 0.47140452079103173.
TEST(NestedMedia, RefractionUsesTheMediumTheRayIsIn) {
  Problem p = testing::problem(R"({"id": "p", "kind": "ray-tree",
    "ray": {"origin": [-1, 1, 0], "direction": [1, -1, 0]},
    "scene": {"max_depth": 4, "objects": [
      {"name": "water", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
       "half_space": true, "material": {"transparency": 1, "refractive_index": 1.33}},
      {"name": "slab", "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0],
       "half_space": true, "material": {"transparency": 1, "refractive_index": 1.5}},
      {"name": "floor", "type": "plane", "point": [0, -3, 0], "normal": [0, 1, 0]}]}})");
  const RayTree& t = tree_of(p);
  const TreeNode* slab = t.find("P.T");
  ASSERT_NE(slab, nullptr);
  EXPECT_DOUBLE_EQ(slab->n1, 1.33);
  EXPECT_DOUBLE_EQ(slab->n2, 1.5);
  const TreeNode* floor = t.find("P.T.T");
  ASSERT_NE(floor, nullptr);
  EXPECT_NEAR(floor->ray.direction.x, 0.47140452079103173, kTight);
  EXPECT_NEAR(floor->ray.direction.y, -0.8819171036881968, kTight);
  EXPECT_EQ(floor->media, (std::vector<int>{0, 1}));
}

// Overlapping spheres A (z from −1.5 to 0.5, n = 1.5) and B (z from −0.5 to 1.5, n = 2).
const char* kOverlap = R"({"id": "p", "kind": "ray-tree", "ask": "media",
    "ray": {"origin": [0, 0, -4], "direction": [0, 0, 1]},
    "scene": {"objects": [
      {"name": "A", "type": "sphere", "center": [0, 0, -0.5], "radius": 1,
       "material": {"transparency": 1, "refractive_index": 1.5}},
      {"name": "B", "type": "sphere", "center": [0, 0, 0.5], "radius": 1,
       "material": {"transparency": 1, "refractive_index": 2}}]}})";

TEST(NestedMedia, OverlappingSpheresByTheList) {
  Problem p = testing::problem(kOverlap);
  const auto& c = tree_of(p).crossings;
  ASSERT_EQ(c.size(), 4u);
  double want[4][3] = {{2.5, 1, 1.5}, {3.5, 1.5, 2}, {4.5, 2, 2}, {5.5, 2, 1}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(c[i].t, want[i][0], kTight) << i;
    EXPECT_DOUBLE_EQ(c[i].n1, want[i][1]) << i;
    EXPECT_DOUBLE_EQ(c[i].n2, want[i][2]) << i;
  }
  EXPECT_EQ(c[2].after, std::vector<int>{1});  // A left from under B: B stays the medium
}

// A ray from the centre of a glass ball starts inside it: one crossing, 1.5 → 1.
TEST(NestedMedia, ARayThatStartsInsideABallLeavesIt) {
  Problem p = testing::problem(R"({"id": "p", "kind": "ray-tree", "ask": "media",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "scene": {"objects": [{"name": "A", "type": "sphere", "center": [0, 0, 0], "radius": 1,
       "material": {"transparency": 1, "refractive_index": 1.5}}]}})");
  const auto& c = tree_of(p).crossings;
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].before, std::vector<int>{0});
  EXPECT_DOUBLE_EQ(c[0].n1, 1.5);
  EXPECT_DOUBLE_EQ(c[0].n2, 1);
}

nlohmann::json overlap_answer() {
  return nlohmann::json::parse(R"({"hits": [
    {"n1": 1, "n2": 1.5}, {"n1": 1.5, "n2": 2}, {"n1": 2, "n2": 2}, {"n1": 2, "n2": 1}]})");
}

TEST(MediaGrade, TheRightIndicesEarnFullCredit) {
  Problem p = testing::problem(kOverlap);
  GradeResult r = grade_answer(p, overlap_answer());
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
  EXPECT_DOUBLE_EQ(r.max_score, 1);
  EXPECT_DOUBLE_EQ(grade_answer(p, p.task->answer()).score, 1);
}

// Leaving A while inside B, a student who says the ray goes back to the air (n2 = 1) loses
// half of that hit: 3.5 of 4 hits.
TEST(MediaGrade, TheAirInsteadOfTheOuterMediumIsNamed) {
  Problem p = testing::problem(kOverlap);
  nlohmann::json a = overlap_answer();
  a["hits"][2]["n2"] = 1;
  GradeResult r = grade_answer(p, a);
  EXPECT_DOUBLE_EQ(r.score, 3.5 / 4);
  EXPECT_TRUE(r.has_mistake("media-not-nested"));
}

TEST(MediaGrade, SwappedIndicesAreNamedAndAMissingHitCosts) {
  Problem p = testing::problem(kOverlap);
  nlohmann::json a = overlap_answer();
  a["hits"][0] = {{"n1", 1.5}, {"n2", 1}};
  a["hits"].erase(3);
  GradeResult r = grade_answer(p, a);
  EXPECT_DOUBLE_EQ(r.score, 2.0 / 4);
  EXPECT_TRUE(r.has_mistake("n1-n2-swapped"));
  ASSERT_FALSE(r.parts.empty());
  bool missing = false;
  for (const auto& f : r.parts.front().feedback) missing |= f.find("Missing: Hit 4") == 0;
  EXPECT_TRUE(missing);
}

}  // namespace
}  // namespace raygrade
