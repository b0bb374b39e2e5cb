// Fresnel reflectance: the exact equations and Schlick's approximation against values worked
// by hand, the kind, and scenes whose materials mix reflection and refraction by them.
#include "scenes/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "grading/grade.h"
#include "kinds/ray_tree.h"
#include "test_util.h"

namespace raygrade {
namespace {

// At normal incidence both models give ((n1 − n2)/(n1 + n2))² = (0.5/2.5)² = 0.04.
TEST(Fresnel, NormalIncidenceIsR0) {
  EXPECT_NEAR(fresnel_reflectance(FresnelModel::kExact, 1, 1, 1.5).reflectance, 0.04, 1e-15);
  EXPECT_NEAR(fresnel_reflectance(FresnelModel::kSchlick, 1, 1, 1.5).reflectance, 0.04, 1e-15);
}

// At Brewster's angle tan θB = n2/n1: R_p = 0 and R_s = ((1 − 2.25)/(1 + 2.25))² = (5/13)².
TEST(Fresnel, BrewsterAngleReflectsNoParallelLight) {
  double cos_b = 1 / std::sqrt(3.25);
  Reflectance r = fresnel_reflectance(FresnelModel::kExact, cos_b, 1, 1.5);
  EXPECT_NEAR(r.r_p, 0, 1e-15);
  EXPECT_NEAR(r.r_s, 25.0 / 169, 1e-15);
  EXPECT_NEAR(r.reflectance, 25.0 / 338, 1e-15);
}

// 45° into glass: cos θt = √(7/9); R_s = ((√2/2 − 1.5√7/3)/(√2/2 + 1.5√7/3))², R_p likewise.
TEST(Fresnel, ExactAtFortyFiveDegrees) {
  double ci = std::sqrt(0.5), ct = std::sqrt(7.0) / 3;
  double rs = std::pow((ci - 1.5 * ct) / (ci + 1.5 * ct), 2);
  double rp = std::pow((ct - 1.5 * ci) / (ct + 1.5 * ci), 2);
  Reflectance r = fresnel_reflectance(FresnelModel::kExact, ci, 1, 1.5);
  EXPECT_NEAR(r.r_s, rs, 1e-15);
  EXPECT_NEAR(r.r_p, rp, 1e-15);
  EXPECT_NEAR(r.reflectance, 0.0502399110122359, 1e-13);
}

// Leaving glass at 30°: sin θt = 0.75, cos θt = √0.4375; Schlick takes the angle on the air
// side, F = 0.04 + 0.96(1 − √0.4375)⁵ = 0.044270, not 0.04 + 0.96(1 − cos 30°)⁵ = 0.040040.
TEST(Fresnel, SchlickLeavingTheDenserMediumUsesTheRefractedAngle) {
  double f = fresnel_reflectance(FresnelModel::kSchlick, std::sqrt(3.0) / 2, 1.5, 1).reflectance;
  EXPECT_NEAR(f, 0.04 + 0.96 * std::pow(1 - std::sqrt(0.4375), 5), 1e-15);
  EXPECT_NEAR(f, 0.0442703, 1e-7);
}

// Leaving glass at 45°: 1.5·sin 45° = 1.06 > 1.
TEST(Fresnel, TotalInternalReflectionReflectsEverything) {
  for (auto m : {FresnelModel::kSchlick, FresnelModel::kExact}) {
    Reflectance r = fresnel_reflectance(m, std::sqrt(0.5), 1.5, 1);
    EXPECT_TRUE(r.total_internal_reflection);
    EXPECT_EQ(r.reflectance, 1);
  }
}

TEST(FresnelKind, AnswerAndGrading) {
  Problem p = testing::problem(R"({"id": "f", "kind": "fresnel", "model": "schlick",
    "n1": 1, "n2": 1.33, "angle": 60})");
  nlohmann::json a = p.task->answer();
  // R0 = (0.33/2.33)², F = R0 + (1 − R0)·0.5⁵.
  double r0 = std::pow(0.33 / 2.33, 2);
  EXPECT_NEAR(a["r0"].get<double>(), r0, 1e-15);
  EXPECT_NEAR(a["reflectance"].get<double>(), r0 + (1 - r0) / 32, 1e-15);
  GradeResult right = grade_answer(p, nlohmann::json{{"reflectance", 0.050682}});
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
  GradeResult wrong = grade_answer(p, nlohmann::json{{"reflectance", 0.020059}});
  EXPECT_DOUBLE_EQ(wrong.score, 0);
}

TEST(FresnelKind, AngleOrDirectionNotBoth) {
  EXPECT_THROW(testing::problem(R"({"id": "f", "kind": "fresnel", "n1": 1, "n2": 1.5,
    "angle": 30, "direction": [1, -1, 0], "normal": [0, 1, 0]})"),
               Error);
  EXPECT_THROW(testing::problem(R"({"id": "f", "kind": "fresnel", "n1": 1, "n2": 1.5,
    "angle": 30, "model": "fresnl"})"),
               Error);
}

// A glass ball (k_r = k_t = 1, n = 1.5) hit head-on, a wall of ambient 0.5 behind it, the
// background 0.2, no lights, no internal reflection.
std::string glass_ball(const std::string& fresnel) {
  return R"({"id": "g", "kind": "ray-tree", "ask": "intensity",
    "ray": {"origin": [0, 0, 5], "direction": [0, 0, -1]},
    "scene": {"objects": [
      {"name": "ball", "type": "sphere", "center": [0, 0, 0], "radius": 1,
       "material": {"ambient": 0, "diffuse": 0, "specular": 0, "reflectivity": 1,
                    "transparency": 1, "refractive_index": 1.5)" +
         fresnel + R"(}},
      {"name": "wall", "type": "plane", "point": [0, 0, -5], "normal": [0, 0, 1],
       "material": {"ambient": 0.5}}],
      "lights": [], "background": 0.2, "internal_reflection": false}})";
}

// With Schlick: F = 0.04 at both surfaces; the exit passes 0.96·0.5 = 0.48, and the entry
// 0.04·0.2 + 0.96·0.48 = 0.4688. Without: k_r and k_t alone, 1·0.2 + 1·(1·0.5) = 0.7.
TEST(FresnelScene, MaterialMixesReflectionAndRefraction) {
  Problem with = testing::problem(glass_ball(R"(, "fresnel": "schlick")"));
  nlohmann::json a = with.task->answer();
  EXPECT_NEAR(a["intensity"].get<double>(), 0.4688, 1e-15);
  EXPECT_NEAR(a["nodes"][0]["fresnel"].get<double>(), 0.04, 1e-15);
  Problem without = testing::problem(glass_ball(""));
  nlohmann::json b = without.task->answer();
  EXPECT_NEAR(b["intensity"].get<double>(), 0.7, 1e-15);
  EXPECT_FALSE(b["nodes"][0].contains("fresnel"));
}

TEST(FresnelScene, OnlyATransparentMaterialMixes) {
  EXPECT_THROW(testing::problem(R"({"id": "g", "kind": "ray-tree",
    "ray": {"origin": [0, 0, 5], "direction": [0, 0, -1]},
    "scene": {"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "material": {"reflectivity": 1, "fresnel": "exact"}}]}})"),
               Error);
}

}  // namespace
}  // namespace raygrade
