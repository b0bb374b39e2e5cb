// Scenes and Whitted tracing: ray counts, shadows through transparent and opaque blockers,
// total internal reflection and the depth limit, against values derived by hand.
#include "scenes/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "kinds/ray_tree.h"
#include "scenes/trace.h"
#include "scenes/tree_json.h"
#include "test_util.h"

namespace raygrade {
namespace {

const RayTreeTask& tree_task(const Problem& p) { return dynamic_cast<const RayTreeTask&>(*p.task); }

// A floor y = 0, a light straight above the origin, and a sphere of radius 1 at (0, 3, 0)
// between them. The primary ray comes straight down onto the floor at (2, 0, 0)... or under
// the sphere at (0, 0, 0), where the sphere blocks the light.
std::string blocker_problem(const std::string& blocker_material, const std::string& shadows,
                            const std::string& ask = "tree") {
  return R"({"id": "b", "kind": "ray-tree", "ask": ")" + ask + R"(",
    "ray": {"origin": [0, 10, 5], "direction": [0, -10, -5]},
    "scene": {"objects": [
      {"name": "floor", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]},
      {"name": "ball", "type": "sphere", "center": [0, 3, 0], "radius": 1, "material": )" +
         blocker_material + R"(}],
      "lights": [{"name": "sun", "position": [0, 8, 0]}],
      "transparent_shadows": ")" +
         shadows + R"("}})";
}

// The ray (0,10,5) + t(0,−10,−5) meets the floor at t = 1, at the origin, passing beside the
// ball (its distance from (0,3,0) is 7·5/√125 ≈ 3.13 > 1). From the origin the light at
// (0,8,0) is straight up, through the ball.
TEST(RayTree, OpaqueBlockerShadowsThePoint) {
  Problem p = testing::problem(blocker_problem(R"({"diffuse": 0.5})", "block"));
  const RayTree& t = tree_task(p).tree();
  ASSERT_EQ(t.nodes.size(), 1u);
  const TreeNode& n = t.nodes[0];
  EXPECT_DOUBLE_EQ(n.t, 1);
  ASSERT_EQ(n.lights.size(), 1u);
  EXPECT_EQ(n.lights[0].status, LightStatus::kBlocked);
  ASSERT_EQ(n.lights[0].blockers.size(), 1u);
  EXPECT_EQ(n.lights[0].blockers[0], 1);
  EXPECT_TRUE(in_shadow(n));
  EXPECT_EQ(node_terms(n), std::vector<std::string>{"ambient"});
}

// The same floor and ray, the light 5 below the floor: the floor faces away from it (N·L = −1
// at the origin), which is not a shadow; nothing blocks anything.
TEST(RayTree, FacingAwayFromTheLightIsNotAShadow) {
  Problem p = testing::problem(R"({"id": "b", "kind": "ray-tree",
    "ray": {"origin": [0, 10, 5], "direction": [0, -10, -5]},
    "scene": {"objects": [
      {"name": "floor", "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}],
      "lights": [{"name": "lamp", "position": [0, -5, 0]}]}})");
  const TreeNode& n = tree_task(p).tree().nodes[0];
  ASSERT_EQ(n.lights.size(), 1u);
  EXPECT_EQ(n.lights[0].status, LightStatus::kBehind);
  EXPECT_FALSE(in_shadow(n));
  EXPECT_TRUE(faces_away(n));
  nlohmann::json a = p.task->answer();
  EXPECT_FALSE(a["nodes"][0]["in_shadow"].get<bool>());
  EXPECT_TRUE(a["nodes"][0]["faces_away"].get<bool>());
  EXPECT_FALSE(a["nodes"][0].contains("shadowed_by"));
  auto parts = p.task->derive("");
  std::string said;
  for (const auto& part : parts) {
    for (const auto& c : part.derivation.conclusion) said += c + "\n";
  }
  EXPECT_NE(said.find("I1 faces away from every light"), std::string::npos) << said;
  EXPECT_EQ(said.find("in shadow"), std::string::npos) << said;
}

// In shadow, the answer names what blocks the light: the ball (see above).
TEST(RayTree, InShadowNamesTheBlocker) {
  Problem p = testing::problem(blocker_problem(R"({"diffuse": 0.5})", "block"));
  nlohmann::json node = p.task->answer()["nodes"][0];
  EXPECT_TRUE(node["in_shadow"].get<bool>());
  EXPECT_EQ(node["shadowed_by"], nlohmann::json::array({"ball"}));
  EXPECT_FALSE(node.contains("faces_away"));
}

const char* kGlassMaterial = R"({"transparency": 0.8, "refractive_index": 1.5})";

TEST(RayTree, TransparentBlockerBlocksInBlockMode) {
  Problem p = testing::problem(blocker_problem(kGlassMaterial, "block"));
  const TreeNode& n = tree_task(p).tree().nodes[0];
  EXPECT_EQ(n.lights[0].status, LightStatus::kBlocked);
  EXPECT_TRUE(in_shadow(n));
}

// In transmit mode the glass ball passes k_t = 0.8 of the light: diffuse and specular apply
// and the diffuse term is k_d·0.8·I_p·(N·L) = 0.7·0.8·1·1 = 0.56 (default k_d = 0.7).
TEST(RayTree, TransparentBlockerTransmitsInTransmitMode) {
  Problem p = testing::problem(blocker_problem(kGlassMaterial, "transmit", "intensity"));
  const TreeNode& n = tree_task(p).tree().nodes[0];
  EXPECT_EQ(n.lights[0].status, LightStatus::kTransmitted);
  EXPECT_DOUBLE_EQ(n.lights[0].transmission, 0.8);
  EXPECT_FALSE(in_shadow(n));
  EXPECT_NEAR(n.lights[0].phong.diffuse, 0.56, 1e-12);
}

TEST(RayTree, OpaqueBlockerBlocksInTransmitModeToo) {
  Problem p = testing::problem(blocker_problem(R"({"diffuse": 0.5})", "transmit"));
  EXPECT_EQ(tree_task(p).tree().nodes[0].lights[0].status, LightStatus::kBlocked);
}

// Nothing is transparent or reflective: one primary and one shadow ray, no others.
TEST(RayTree, NothingTransparentCastsNoRefractionRays) {
  Problem p = testing::problem(blocker_problem(R"({"reflectivity": 0.5})", "block"));
  const RayCounts& c = tree_task(p).tree().counts;
  EXPECT_EQ(c.primary, 1);
  EXPECT_EQ(c.refraction, 0);
  EXPECT_EQ(c.shadow, 1);
  EXPECT_EQ(c.reflection, 0);  // the floor (hit) does not reflect; the ball is not hit
  bool skipped = false;
  for (const auto& e : tree_task(p).tree().effects) {
    if (e.name == "refraction") skipped = !e.simulated;
  }
  EXPECT_TRUE(skipped);
}

TEST(RayTree, AskingOnlyForTheHitCastsNoShadowRays) {
  Problem p = testing::problem(blocker_problem(kGlassMaterial, "block", "hit"));
  const RayTree& t = tree_task(p).tree();
  EXPECT_EQ(t.counts.shadow, 0);
  EXPECT_EQ(t.counts.total(), 1);
  EXPECT_FALSE(t.nodes[0].shaded);
  nlohmann::json a = p.task->answer();
  EXPECT_EQ(a["object"], "floor");
  EXPECT_DOUBLE_EQ(a["hits"][0]["t"].get<double>(), 1);
}

TEST(RayTree, NoLightsCastNoShadowRays) {
  Problem p = testing::problem(R"({"id": "n", "kind": "ray-tree",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "scene": {"objects": [{"type": "sphere", "center": [0, 0, 5], "radius": 1}]}})");
  const RayTree& t = tree_task(p).tree();
  EXPECT_EQ(t.counts.shadow, 0);
  EXPECT_EQ(node_terms(t.nodes[0]), std::vector<std::string>{"ambient"});
  EXPECT_EQ(t.nodes[0].label, "I1");
}

// Two facing mirrors x = 0 and x = 10; a ray along +x bounces between them until the depth
// limit: max_depth 4 gives the primary ray and three reflections, the last one noting why it
// stops.
TEST(RayTree, DepthLimitStopsTheBounces) {
  Problem p = testing::problem(R"({"id": "m", "kind": "ray-tree",
    "ray": {"origin": [5, 0, 0], "direction": [1, 0, 0]},
    "scene": {"max_depth": 4, "objects": [
      {"name": "left", "type": "plane", "point": [0, 0, 0], "normal": [1, 0, 0],
       "material": {"reflectivity": 1}},
      {"name": "right", "type": "plane", "point": [10, 0, 0], "normal": [-1, 0, 0],
       "material": {"reflectivity": 1}}]}})");
  const RayTree& t = tree_task(p).tree();
  ASSERT_EQ(t.nodes.size(), 4u);
  EXPECT_EQ(t.counts.reflection, 3);
  EXPECT_DOUBLE_EQ(t.nodes[0].t, 5);
  EXPECT_NEAR(t.nodes[1].t, 10, 1e-12);
  EXPECT_EQ(t.nodes[3].path, "P.R.R.R");
  EXPECT_EQ(t.nodes[3].depth, 4);
  ASSERT_EQ(t.nodes[3].notes.size(), 1u);
  EXPECT_NE(t.nodes[3].notes[0].find("depth limit"), std::string::npos);
}

// Inside a glass sphere (n = 1.5) of radius 1 at the origin, a ray from (0, 0.9, 0) along
// +x meets the surface where sin θi = 0.9 > 1/1.5: beyond the critical angle (41.8°), so
// the refraction becomes a reflection.
TEST(RayTree, TotalInternalReflectionReplacesTheRefraction) {
  Problem p = testing::problem(R"({"id": "tir", "kind": "ray-tree",
    "ray": {"origin": [0, 0.9, 0], "direction": [1, 0, 0]},
    "scene": {"max_depth": 2, "objects": [{"name": "glass", "type": "sphere",
      "center": [0, 0, 0], "radius": 1,
      "material": {"transparency": 0.9, "refractive_index": 1.5}}]}})");
  const RayTree& t = tree_task(p).tree();
  const TreeNode& n = t.nodes[0];
  EXPECT_TRUE(n.inside);
  EXPECT_NEAR(n.t, std::sqrt(1 - 0.81), 1e-15);
  EXPECT_TRUE(n.refraction_math.total_internal_reflection);
  EXPECT_EQ(n.refraction, -1);
  ASSERT_GE(n.reflection, 0);
  EXPECT_TRUE(t.nodes[n.reflection].total_internal_reflection);
  EXPECT_EQ(t.counts.refraction, 0);
  EXPECT_EQ(t.counts.reflection, 1);
  EXPECT_DOUBLE_EQ(t.nodes[n.reflection].weight, 0.9);  // k_t goes to the reflected ray
}

TEST(RayTree, NoInternalReflectionAssumedSkipsTheTotalReflection) {
  Problem p = testing::problem(R"({"id": "tir", "kind": "ray-tree",
    "ray": {"origin": [0, 0.9, 0], "direction": [1, 0, 0]},
    "scene": {"internal_reflection": false, "objects": [{"name": "glass", "type": "sphere",
      "center": [0, 0, 0], "radius": 1,
      "material": {"transparency": 0.9, "refractive_index": 1.5}}]}})");
  const RayTree& t = tree_task(p).tree();
  EXPECT_EQ(t.nodes.size(), 1u);
  EXPECT_EQ(t.counts.total(), 1);
}

// Seed 001: the glass sphere, mirror ceiling, floor and back wall of the bank's exercise.
TEST(RayTree, SeedOneHasFivePointsTwoInShadow) {
  Bank bank =
      load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems/seeds/seed001-ray-tree.json"});
  ASSERT_TRUE(bank.errors.empty());
  const Problem& p = bank.problems.at(0);
  nlohmann::json a = p.task->answer();
  EXPECT_EQ(a["all_terms"], nlohmann::json({"I1", "I2", "I3"}));
  EXPECT_EQ(a["ambient_only"], nlohmann::json({"I4", "I5"}));
  const RayTree& t = tree_task(p).tree();
  // I1: (x − 6)² + 1 = 4 gives x = 6 − √3; the mirror reflection (−1/2, √3/2) reaches y = 6
  // after t = 5/(√3/2) = 10/√3, at x = 6 − √3 − 5/√3.
  EXPECT_NEAR(t.nodes[0].t, 6 - std::sqrt(3.0), 1e-14);
  const TreeNode* i2 = t.find("P.R");
  ASSERT_NE(i2, nullptr);
  EXPECT_NEAR(i2->t, 10 / std::sqrt(3.0), 1e-13);
  EXPECT_NEAR(i2->point.x, 6 - std::sqrt(3.0) - 5 / std::sqrt(3.0), 1e-13);
  // Snell at I1: θi = 30°, sin θt = 0.5/1.5.
  const Refraction& r = t.nodes[0].refraction_math;
  EXPECT_NEAR(r.cos_i, std::sqrt(3.0) / 2, 1e-15);
  double sin_t = std::sqrt(1 - r.k);
  EXPECT_NEAR(sin_t, 1.0 / 3, 1e-15);
  EXPECT_EQ(t.counts.primary, 1);
  EXPECT_EQ(t.counts.reflection, 2);
  EXPECT_EQ(t.counts.refraction, 2);
  EXPECT_EQ(t.counts.shadow, 5);
}

// The answer says, as data, what the tree simulated and what it left out: seed 001 casts five
// shadow rays (one per hit point; the light is one), two reflection and two refraction rays
// (counted by hand above), shades every point and leaves intensities out (ask: tree).
TEST(RayTree, EffectsAreDataInTheAnswer) {
  Bank bank =
      load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems/seeds/seed001-ray-tree.json"});
  ASSERT_TRUE(bank.errors.empty());
  nlohmann::json effects = bank.problems.at(0).task->answer()["effects"];
  ASSERT_TRUE(effects.is_array()) << effects;
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& e : effects) {
    ASSERT_TRUE(e["effect"].is_string()) << e;
    ASSERT_TRUE(e["simulated"].is_boolean()) << e;
    ASSERT_TRUE(e["why"].is_string() && !e["why"].get<std::string>().empty()) << e;
    by_name[e["effect"].get<std::string>()] = e;
  }
  EXPECT_EQ(by_name["shadow rays"]["simulated"], true);
  EXPECT_EQ(by_name["shadow rays"]["rays"], 5);
  EXPECT_EQ(by_name["reflection"]["rays"], 2);
  EXPECT_EQ(by_name["refraction"]["rays"], 2);
  EXPECT_EQ(by_name["shading"]["simulated"], true);
  EXPECT_FALSE(by_name["shading"].contains("rays"));
  EXPECT_EQ(by_name["intensity"]["simulated"], false);
  EXPECT_EQ(by_name["intensity"]["why"], "the question does not ask for intensities");
  // Asking only for the hit skips the shadow rays, and says why.
  Problem hit = testing::problem(blocker_problem(kGlassMaterial, "block", "hit"));
  nlohmann::json answer = hit.task->answer();
  bool said = false;
  for (const auto& e : answer["effects"]) {
    if (e["effect"] == "shadow rays") {
      said = e["simulated"] == false && e["why"] == "the question asks only for the hit" &&
             !e.contains("rays");
    }
  }
  EXPECT_TRUE(said) << answer.dump();
}

TEST(Scene, UnknownMaterialNameIsAnErrorWithItsPath) {
  try {
    testing::problem(R"({"id": "x", "kind": "ray-tree",
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "scene": {"objects": [{"type": "sphere", "center": [0, 0, 5], "radius": 1,
                             "material": "glas"}]}})");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().path, "/scene/objects/0/material");
    EXPECT_EQ(e.diagnostic().code, "unknown-material");
  }
}

TEST(Scene, TransparentMaterialNeedsAnIndex) {
  EXPECT_THROW(testing::problem(R"({"id": "x", "kind": "ray-tree",
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "scene": {"objects": [{"type": "sphere", "center": [0, 0, 5], "radius": 1,
                             "material": {"transparency": 0.5}}]}})"),
               Error);
}

// A mirror floor (k_r = 0.5) under a matte ball, lamp at (5, 1, 0), default material
// otherwise (k_a 0.1, k_d 0.7, k_s 0.2, n 10), I_a = I_p = 1. Worked by hand:
// floor point (0, −1, 0): N = V = (0, 1, 0), L = (5, 2, 0)/√29, N·L = R·V = 2/√29;
// ball point (0, 29, 0): N = V = (0, −1, 0), L = (5, −28, 0)/√809, N·L = R·V = 28/√809.
TEST(RayTree, IntensityAddsTheReflectionWeighted) {
  Problem p = testing::problem(R"({"id": "i", "kind": "ray-tree", "ask": "intensity",
    "ray": {"origin": [0, 10, 0], "direction": [0, -1, 0]},
    "scene": {"objects": [
      {"name": "floor", "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0],
       "material": {"reflectivity": 0.5}},
      {"name": "ball", "type": "sphere", "center": [0, 30, 0], "radius": 1}],
      "lights": [{"name": "lamp", "position": [5, 1, 0]}]}})");
  double c1 = 2 / std::sqrt(29.0), c2 = 28 / std::sqrt(809.0);
  double floor_local = 0.1 + 0.7 * c1 + 0.2 * std::pow(c1, 10);
  double ball = 0.1 + 0.7 * c2 + 0.2 * std::pow(c2, 10);
  const RayTree& t = dynamic_cast<const RayTreeTask&>(*p.task).tree();
  ASSERT_EQ(t.nodes.size(), 2u);
  EXPECT_NEAR(t.nodes[1].intensity, ball, 1e-13);
  EXPECT_NEAR(t.nodes[0].local, floor_local, 1e-13);
  EXPECT_NEAR(t.nodes[0].intensity, floor_local + 0.5 * ball, 1e-13);
  EXPECT_NEAR(p.task->answer()["intensity"].get<double>(), floor_local + 0.5 * ball, 1e-13);
}

// Ten panes that reflect and transmit inside a mirror room branch at nearly every hit: the
// tree would grow toward 2^16 nodes by depth alone, and stops at the node limit instead,
// saying so (a spawn in progress may add its second child, one per generation at most).
TEST(RayTree, NodeLimitCutsABranchingTree) {
  std::string objects =
      R"({"name": "room", "type": "box", "min": [-9, -9, -9], "max": [9, 9, 9],
          "material": {"reflectivity": 0.5}})";
  for (int x : {-6, -3, 0, 3, 6}) {
    for (const char* axis : {"[1, 0, 0]", "[0, 1, 0]"}) {
      objects += fmt::format(
          R"(, {{"type": "plane", "point": [{0}, {0}, 0], "normal": {1},
               "material": {{"reflectivity": 0.3, "transparency": 0.6,
                             "refractive_index": 1.5}}}})",
          x, axis);
    }
  }
  Problem p = testing::problem(R"({"id": "many", "kind": "ray-tree",
    "ray": {"origin": [0.3, 0.2, -3], "direction": [0.7, 0.5, 1]},
    "scene": {"max_depth": 16, "lights": [{"position": [4, 4, -4]}], "objects": [)" +
                               objects + "]}}");
  const RayTree& t = tree_task(p).tree();
  EXPECT_GE(static_cast<int>(t.nodes.size()), kMaxTreeNodes);
  EXPECT_LE(static_cast<int>(t.nodes.size()), kMaxTreeNodes + kMaxTreeDepth);
  int cut = 0;
  for (const auto& n : t.nodes) {
    for (const auto& note : n.notes) cut += note.find("the most one problem") != std::string::npos;
  }
  EXPECT_GT(cut, 0);
}

}  // namespace
}  // namespace raygrade
