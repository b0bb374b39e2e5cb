// Grading by parts: every kind's declared parts, directions as directions, claimed misses,
// textbook conventions, bounded tangent tolerances and one precision rule, by values worked
// by hand.
#include "grading/parts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "check/problem_checks.h"
#include "grading/grade.h"
#include "grading/outputs.h"
#include "grading/submission.h"
#include "json/source.h"
#include "test_util.h"

namespace raygrade {
namespace {

using nlohmann::json;

using testing::part;

GradeResult grade(const std::string& problem, const char* answer) {
  Problem p = testing::problem(problem);
  return grade_answer(p, json::parse(answer));
}

bool says(const std::vector<std::string>& lines, const std::string& text) {
  for (const auto& l : lines) {
    if (l.find(text) != std::string::npos) return true;
  }
  return false;
}

// d = (1, −1, 0) off the floor y = 0: r = d − 2(d·n)n = (1, −1, 0) + 2(0, 1, 0) = (1, 1, 0).
const char* kReflect = R"({"id": "r", "kind": "reflect", "direction": [1, -1, 0],
  "normal": [0, 1, 0]})";

TEST(Parts, ReflectedDirectionAloneIsRight) {
  GradeResult r = grade(kReflect, R"({"direction": [1, 1, 0]})");
  EXPECT_DOUBLE_EQ(r.score, 1);
  EXPECT_DOUBLE_EQ(r.max_score, 1);
  EXPECT_EQ(part(r, "unit_direction"), nullptr);  // not asked, not required
}

TEST(Parts, ReflectedDirectionAsPositiveMultiple) {
  GradeResult r = grade(kReflect, R"({"direction": [2, 2, 0]})");
  EXPECT_DOUBLE_EQ(r.score, 1);
  // |(2, 2, 0)| = 2√2 = 2.828, while r keeps |d| = √2 = 1.414: a note, not a deduction.
  EXPECT_TRUE(says(part(r, "direction")->feedback, "length 2.828"));
  GradeResult back = grade(kReflect, R"({"direction": [-1, -1, 0]})");
  EXPECT_DOUBLE_EQ(back.score, 0);
  EXPECT_TRUE(says(part(back, "direction")->feedback, "opposite way"));
}

// A problem that asks for the unit vector: (1, 1, 0)/√2 = (0.7071, 0.7071, 0).
TEST(Parts, UnitDirectionIsItsOwnPart) {
  std::string p = R"({"id": "r", "kind": "reflect", "direction": [1, -1, 0], "normal": [0, 1, 0],
    "points": {"direction": 1, "unit_direction": 1}})";
  GradeResult unit = grade(p, R"({"unit_direction": [0.7071, 0.7071, 0]})");
  EXPECT_DOUBLE_EQ(unit.score, 2);  // a unit vector is a positive multiple too
  GradeResult plain = grade(p, R"({"direction": [1, 1, 0], "unit_direction": [1, 1, 0]})");
  EXPECT_DOUBLE_EQ(plain.score, 1);
  EXPECT_TRUE(says(part(plain, "unit_direction")->feedback, "length 1.414"));
}

// The two-light fixture: ambient 0.1·2 = 0.2; light A: L = (3, 4, 0)/5, N·L = 0.8, diffuse
// 0.5·0.8 = 0.4; V = (−3, 4, 0)/5 is L mirrored, so R·V = 1 and specular 0.3; B is blocked.
// I = 0.2 + 0.4 + 0.3 = 0.9.
TEST(Parts, ShadeIntensityAloneIsRight) {
  GradeResult r = grade(testing::kTwoLightShade, R"({"intensity": 0.9})");
  EXPECT_DOUBLE_EQ(r.score, 1);
  EXPECT_DOUBLE_EQ(r.max_score, 1);
  EXPECT_EQ(r.parts.size(), 1u);
}

TEST(Parts, PointsSelectAnyField) {
  std::string p = testing::kTwoLightShade;
  p.insert(p.size() - 1, R"(, "points": {"intensity": 1, "diffuse": 2, "terms": 1})");
  GradeResult r = grade(p, R"({"intensity": 0.9, "diffuse": 0.5, "terms": ["ambient"]})");
  EXPECT_DOUBLE_EQ(r.max_score, 4);
  EXPECT_DOUBLE_EQ(r.score, 1);
  EXPECT_TRUE(says(part(r, "diffuse")->feedback, "diffuse is 0.4, not 0.5"));
  EXPECT_TRUE(says(part(r, "terms")->feedback, "ambient, diffuse, specular"));
  GradeResult lights = grade(testing::kTwoLightShade,
                             R"({"intensity": 0.9, "lights": [{"light": "B", "reaches": true}]})");
  EXPECT_TRUE(says(part(lights, "lights")->feedback, "shadow ray is blocked"));
  EXPECT_TRUE(says(lights.notes, "Not asked in this problem (no points): lights."));
}

// Into water at 60°: η = 3/4, cos θi = 1/2, k = 1 − (9/16)(3/4) = 37/64, √k = 0.76035;
// t = η d + (η cos θi − √k) n = (0.64952, −0.76035, 0); θt = acos √k = 40.506°.
const char* kWater = R"({"id": "w", "kind": "refract", "direction": [0.8660254037844386, -0.5, 0],
  "normal": [0, 1, 0], "n1": 1, "n2": 1.3333333333333333,
  "points": {"direction": 1, "angle_of_refraction": 1}})";

TEST(Parts, RefractionWithoutTheFlagNobodyAskedFor) {
  GradeResult r = grade(kWater, R"({"direction": [0.6495, -0.7603, 0],
    "angle_of_refraction": "40.51"})");
  EXPECT_DOUBLE_EQ(r.score, 2);
  EXPECT_DOUBLE_EQ(r.max_score, 2);
  GradeResult radians = grade(kWater, R"({"angle_of_refraction": 0.70697})");
  EXPECT_TRUE(says(part(radians, "angle_of_refraction")->feedback, "in radians"));
  // asin(0.75 sin 60°) typed with degrees, turned back into degrees.
  GradeResult typed = grade(kWater, R"({"angle_of_refraction": "asin(0.75 sin(60deg)) * 180/pi"})");
  EXPECT_DOUBLE_EQ(part(typed, "angle_of_refraction")->points, 1);
}

// Out of glass at 60°: sin θc = 1/1.5, θc = 41.81° < 60°: no refracted ray.
const char* kGlass = R"({"id": "g", "kind": "refract", "direction": [0.8660254037844386, 0.5, 0],
  "normal": [0, 1, 0], "n1": 1.5, "n2": 1})";

TEST(Parts, TotalInternalReflectionAnswersTheDirection) {
  EXPECT_DOUBLE_EQ(grade(kGlass, R"({"total_internal_reflection": true})").score, 1);
  EXPECT_DOUBLE_EQ(grade(kGlass, R"({"direction": null})").score, 1);
  GradeResult wrong = grade(kGlass, R"({"direction": [0.9, 0.4, 0]})");
  EXPECT_DOUBLE_EQ(wrong.score, 0);
  EXPECT_TRUE(says(part(wrong, "direction")->feedback, "41.81"));
}

// The two-light fixture with k_s = 0: no specular term at all. I = 0.2 + 0.4 = 0.6; the
// material has no colour, so there is no colour to give either.
const char* kMatteShade = R"({"id": "m", "kind": "shade",
    "point": [0, 0, 0], "normal": [0, 1, 0], "eye": [-3, 4, 0], "ambient_light": 2,
    "material": {"ambient": 0.1, "diffuse": 0.5, "specular": 0, "shininess": 12},
    "lights": [{"name": "A", "position": [3, 4, 0]},
               {"name": "B", "position": [0, 9, 0], "blocked": true}],
    "points": {"intensity": 1, "specular": 1, "colour": 1}})";

TEST(Parts, ANoSpecularTermIsAnsweredByZeroOrNothing) {
  GradeResult zero = grade(kMatteShade, R"({"intensity": 0.6, "specular": 0})");
  EXPECT_DOUBLE_EQ(zero.score, 2);
  EXPECT_EQ(part(zero, "colour"), nullptr);  // no colour part to leave out
  EXPECT_DOUBLE_EQ(grade(kMatteShade, R"({"intensity": 0.6, "specular": null})").score, 2);
  GradeResult some = grade(kMatteShade, R"({"intensity": 0.6, "specular": 0.3})");
  EXPECT_DOUBLE_EQ(some.score, 1);
  EXPECT_TRUE(says(part(some, "specular")->feedback, "k_s = 0"));
}

// Into glass: n2 > n1, so there is no critical angle, and no reflected direction to give.
TEST(Parts, APartTheProblemHasNotSaysWhy) {
  const char* into_glass = R"({"id": "w", "kind": "refract", "direction": [1, -1, 0],
    "normal": [0, 1, 0], "n1": 1, "n2": 1.5,
    "points": {"critical_angle": 1, "reflected_direction": 1, "total_internal_reflection": 1}})";
  GradeResult r = grade(into_glass, R"({"critical_angle": 41.8, "reflected_direction": [1, 1, 0],
    "total_internal_reflection": true})");
  EXPECT_DOUBLE_EQ(r.score, 0);
  EXPECT_TRUE(says(part(r, "critical_angle")->feedback, "no critical angle"));
  EXPECT_TRUE(says(part(r, "reflected_direction")->feedback, "no reflected direction"));
  EXPECT_TRUE(says(part(r, "total_internal_reflection")->feedback, "never totally reflected"));
}

// The triangle a = 0, b = x, c = y, hit from above at (0.2, 0.3): P = 0.5a + 0.2b + 0.3c.
const char* kTriangle = R"({"id": "tri", "points": {"t": 1, "barycentric": 1},
  "ray": {"origin": [0.2, 0.3, 1], "direction": [0, 0, -1]},
  "object": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}})";

// The bank's check grades a stated answer's weights too, even where they carry no points.
TEST(Parts, CheckRefusesWrongStatedWeights) {
  Problem p = testing::problem(R"({"id": "tri",
    "ray": {"origin": [0.2, 0.3, 1], "direction": [0, 0, -1]},
    "object": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
    "expected": {"hits": [{"t": 1, "barycentric": [0.1, 0.1, 0.8]}]}})");
  auto d = check_expected(p, p.task->answer(), {});
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0].code, "wrong-expected");
  Problem right = testing::problem(R"({"id": "tri",
    "ray": {"origin": [0.2, 0.3, 1], "direction": [0, 0, -1]},
    "object": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
    "expected": {"hits": [{"t": 1, "barycentric": [0.5, 0.2, 0.3]}]}})");
  EXPECT_TRUE(check_expected(right, right.task->answer(), {}).empty());
}

TEST(Parts, BarycentricWeightsAreGraded) {
  EXPECT_DOUBLE_EQ(
      grade(kTriangle, R"({"hits": [{"t": 1, "barycentric": [0.5, 0.2, 0.3]}]})").score, 2);
  GradeResult swapped = grade(kTriangle, R"({"hits": [{"t": 1, "barycentric": [0.2, 0.3, 0.5]}]})");
  EXPECT_DOUBLE_EQ(part(swapped, "barycentric")->points, 0);
  EXPECT_TRUE(says(part(swapped, "barycentric")->feedback, "order of the vertices"));
  GradeResult off = grade(kTriangle, R"({"hits": [{"t": 1, "barycentric": [0.1, 0.1, 0.8]}]})");
  EXPECT_DOUBLE_EQ(part(off, "barycentric")->points, 0);
  EXPECT_DOUBLE_EQ(grade(kTriangle, R"({"hits": [{"t": 1, "u": 0.2, "v": 0.3}]})").score, 2);
  GradeResult uv = grade(kTriangle, R"({"hits": [{"t": 1, "u": 0.3, "v": 0.2}]})");
  EXPECT_DOUBLE_EQ(part(uv, "barycentric")->points, 0);
}

// Seed 000's sphere 1: O = 0, D = x, C = (2, 0, 0), r = 1: a = 1, b = 2D·(O − C) = −4, c = 3,
// t = 1 and 3.
const char* kPartsSphere = R"({"id": "s1",
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})";

TEST(Parts, ClaimedMissIsAnAnswer) {
  GradeResult r = grade(kPartsSphere, R"({"hits": []})");
  EXPECT_EQ(part(r, "t")->status, PartStatus::kWrong);
  EXPECT_TRUE(says(part(r, "t")->feedback, "You say the ray misses; it hits at t = 1 and 3."));
}

// b = +4 (the sign slip): Δ = 16 − 12 = 4, t = (−4 ∓ 2)/2 = −3 and −1, both behind the origin:
// no hit follows from the student's own steps.
TEST(Parts, ClaimedMissCarriesTheErrorForward) {
  GradeResult r = grade(kPartsSphere, R"({"steps": {"a": 1, "b": 4, "c": 3}, "hits": []})");
  EXPECT_DOUBLE_EQ(part(r, "t")->points, 1);  // half of 2
  EXPECT_TRUE(says(part(r, "t")->feedback, "error carried forward"));
  EXPECT_TRUE(r.carried_forward);
}

// An empty steps object gives no step: when steps carry points they are missing, and the
// feedback names the steps of the worked solution (the geometric method's t_ca and t_hc among
// them, the first method of a sphere), not an
// internal error; when they carry none, they are left out as any part not asked.
TEST(Parts, EmptyStepsAreMissing) {
  std::string graded_steps = kPartsSphere;
  graded_steps.insert(graded_steps.size() - 1, R"(, "points": {"steps": 2})");
  GradeResult r = grade(graded_steps, R"({"steps": {}, "hits": []})");
  ASSERT_NE(part(r, "steps"), nullptr);
  EXPECT_EQ(part(r, "steps")->status, PartStatus::kMissing);
  EXPECT_EQ(part(r, "steps")->points, 0);
  EXPECT_TRUE(says(part(r, "steps")->feedback, "the steps object is empty"));
  EXPECT_TRUE(says(part(r, "steps")->feedback, "t_ca"));
  EXPECT_TRUE(says(part(r, "steps")->feedback, "t_hc"));
  EXPECT_EQ(part(grade(kPartsSphere, R"({"steps": {}, "hits": []})"), "steps"), nullptr);
}

// The plane x = 2 meets the ray along +x once, at t = 2. A second hit listed with a point and
// no t is a hit too many: half the t part (one right t of two hits), and the feedback says why.
TEST(Parts, AHitWithoutTBesideOneWithT) {
  GradeResult r = grade(R"({"id": "p", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "plane", "point": [2, 0, 0], "normal": [-1, 0, 0]}})",
                        R"({"hits": [{"t": 2, "point": [2, 0, 0]}, {"point": [5, 0, 0]}]})");
  EXPECT_EQ(part(r, "t")->status, PartStatus::kPartial);
  EXPECT_DOUBLE_EQ(part(r, "t")->points, part(r, "t")->max_points / 2);
  EXPECT_TRUE(says(part(r, "t")->feedback, "Hit 2 gives no t."));
}

TEST(Parts, BlankFirstHitObject) {
  GradeResult r = grade(R"({"id": "f", "kind": "first-hit",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "objects": [{"name": "crate", "type": "sphere", "center": [5, 0, 0], "radius": 1}]})",
                        R"({"object": "", "hits": [{"t": 4}]})");
  EXPECT_EQ(part(r, "object")->status, PartStatus::kMissing);
  EXPECT_FALSE(says(part(r, "object")->feedback, "not ."));
  EXPECT_TRUE(says(part(r, "object")->feedback, "blank"));
}

// x = 1 grazes the unit sphere at (1, 0, 5): a double root t = 5.
const char* kTangent = R"({"id": "g", "ray": {"origin": [1, 0, 0], "direction": [0, 0, 1]},
  "object": {"type": "sphere", "center": [0, 0, 5], "radius": 1}})";

TEST(Parts, DoubleRootListedTwiceIsRight) {
  GradeResult r = grade(kTangent, R"({"hits": [{"t": 5, "point": [1, 0, 5]},
    {"t": 5, "point": [1, 0, 5]}]})");
  EXPECT_DOUBLE_EQ(r.score, 3);
  EXPECT_FALSE(says(part(r, "t")->feedback, "not a hit"));
  // At a tangent's two distinct roots, 5 twice is one right root and one wrong.
  GradeResult near = grade(R"({"id": "n", "ray": {"origin": [0.6, 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 5], "radius": 1}})",
                           R"({"hits": [{"t": 4.2}, {"t": 4.2}]})");
  EXPECT_DOUBLE_EQ(part(near, "t")->points, 1);  // roots 5 ∓ 0.8
}

// x0 = 0.9998: roots 5 ∓ √(1 − x0²) = 4.980001 and 5.019999, 0.04 apart. a = 1, b = −10,
// c = 24.9996, Δ = 0.0016, δΔ = 1e-4 (100 + 99.9984) = 0.02, so the tangent's widening is
// (√0.0216 − √0.0016)/2 = 0.0535: more than the gap. Bounded by half the gap (0.02), the exit
// root given twice is one right root, not both.
TEST(Parts, WidenedToleranceNeverReachesTheOtherRoot) {
  const char* grazing = R"({"id": "z", "ray": {"origin": [0.9998, 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 5], "radius": 1}})";
  GradeResult twice = grade(grazing, R"({"hits": [{"t": 5.02}, {"t": 5.02}]})");
  EXPECT_DOUBLE_EQ(part(twice, "t")->points, 1);
  EXPECT_TRUE(says(part(twice, "t")->feedback, "listed twice"));
  EXPECT_TRUE(says(part(twice, "t")->feedback, "also hits at t = 4.98"));
  EXPECT_DOUBLE_EQ(part(grade(grazing, R"({"hits": [{"t": 4.98}, {"t": 5.02}]})"), "t")->points, 2);
}

const char* kInPlane = R"({"id": "c", "ray": {"origin": [1, 2, 4], "direction": [1, 1, 0]},
  "object": {"type": "plane", "point": [0, 0, 4], "normal": [0, 0, 1]}})";
const char* kAlongSide = R"({"id": "c", "ray": {"origin": [2, 0, -5], "direction": [0, 0, 1]},
  "object": {"type": "cylinder", "base": [0, 0, 0], "radius": 2}})";

TEST(Parts, ContainedRayAnsweredAsNoIntersection) {
  GradeResult miss = grade(kInPlane, R"({"hits": []})");
  EXPECT_DOUBLE_EQ(miss.score, miss.max_score);
  EXPECT_TRUE(says(part(miss, "t")->feedback, "whole line"));
  EXPECT_DOUBLE_EQ(grade(kInPlane, R"({"hits": [], "contained": true})").score, 3);
  GradeResult side = grade(kAlongSide, R"({"hits": []})");
  EXPECT_DOUBLE_EQ(side.score, side.max_score);
  EXPECT_FALSE(says(part(side, "t")->feedback, "plane"));
  EXPECT_TRUE(says(part(side, "t")->feedback, "cylinder's side"));
}

TEST(Parts, ContainedConventionMakesEitherStrict) {
  std::string line = kInPlane;
  line.insert(line.size() - 1, R"(, "conventions": {"contained": "line"})");
  EXPECT_DOUBLE_EQ(part(grade(line, R"({"hits": []})"), "t")->points, 1);  // half of 2
  EXPECT_DOUBLE_EQ(part(grade(line, R"({"hits": [], "contained": true})"), "t")->points, 2);
  std::string miss = kInPlane;
  miss.insert(miss.size() - 1, R"(, "conventions": {"contained": "miss"})");
  EXPECT_DOUBLE_EQ(part(grade(miss, R"({"hits": [], "contained": true})"), "t")->points, 1);
  EXPECT_THROW(testing::problem(R"({"id": "c", "conventions": {"contained": "both"},
    "ray": {"origin": [1, 2, 4], "direction": [1, 1, 0]},
    "object": {"type": "plane", "point": [0, 0, 4], "normal": [0, 0, 1]}})"),
               Error);
}

TEST(Parts, BankConventionAppliesToItsProblems) {
  std::string dir = ::testing::TempDir() + "/conventions";
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir + "/bank.json");
    f << R"({"conventions": {"contained": "line"}, "problems": [)" << kInPlane << "]}";
  }
  Bank bank = load_bank({dir});
  ASSERT_EQ(bank.problems.size(), 1u) << (bank.errors.empty() ? "" : bank.errors[0].message);
  EXPECT_EQ(bank.problems[0].conventions.contained, Conventions::Contained::kLine);
  EXPECT_DOUBLE_EQ(grade_answer(bank.problems[0], json::parse(R"({"hits": []})")).score, 1.5);
}

// The sphere of radius √14 about the origin, met from (1, 2, 10) straight down: t = 7 at
// P = (1, 2, 3), N = (1, 2, 3)/√14 = (0.26726, 0.53452, 0.80178). Rounded to two decimals,
// (0.27, 0.53, 0.80) is right to its digits, as t = 7.0 would be: "too imprecise".
TEST(Parts, OnePrecisionRuleForEveryNumber) {
  const char* p = R"({"id": "n", "points": {"t": 2, "normal": 1},
    "ray": {"origin": [1, 2, 10], "direction": [0, 0, -1]},
    "object": {"type": "sphere", "center": [0, 0, 0], "radius": 3.7416573867739413}})";
  GradeResult r = grade(p, R"({"hits": [{"t": 7, "normal": ["0.27", "0.53", "0.80"]},
    {"t": 13, "normal": [-1, -2, 3]}]})");
  EXPECT_TRUE(says(part(r, "normal")->feedback, "right to the digits given"));
  GradeResult t = grade(p, R"({"hits": [{"t": "7.1"}, {"t": 13}]})");
  EXPECT_TRUE(says(part(t, "t")->feedback, "not a hit"));  // 7.1 is not 7 to one decimal
}

TEST(Parts, InwardNormalSaysTheShapesOwnNormal) {
  GradeResult r =
      grade(R"({"id": "cy", "points": {"t": 2, "normal": 1},
    "ray": {"origin": [-5, 0, 1], "direction": [1, 0, 0]},
    "object": {"type": "cylinder", "base": [0, 0, 0], "radius": 2}})",
            R"({"hits": [{"t": 3, "normal": [1, 0, 0]}, {"t": 7, "normal": [1, 0, 0]}]})");
  ASSERT_TRUE(r.has_mistake("inward-normal"));
  for (const auto& m : r.mistakes) {
    EXPECT_EQ(m.message.find("sphere"), std::string::npos) << m.message;
    EXPECT_NE(m.message.find("cylinder"), std::string::npos) << m.message;
  }
}

// 9 ∓ √3 = 7.268 and 10.732: every number of the feedback with the same three decimals.
TEST(Parts, OneDisplayPrecisionPerMessage) {
  GradeResult r = grade(R"({"id": "d", "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 9], "radius": 1.7320508075688772}})",
                        R"({"hits": [{"t": 7.268}]})");
  EXPECT_TRUE(says(part(r, "t")->feedback, "t = 10.732."));
}

TEST(Parts, UnaskedPartsAreNotMissingButNotedWhenGiven) {
  std::string p = R"({"id": "s1", "points": {"t": 0, "point": 1},
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})";
  GradeResult r = grade(p, R"({"hits": [{"point": [1, 0, 0]}, {"point": [3, 0, 0]}]})");
  EXPECT_EQ(part(r, "t"), nullptr);
  EXPECT_DOUBLE_EQ(r.score, 1);
  GradeResult normal = grade(kPartsSphere, R"({"hits": [{"t": 1, "normal": [-1, 0, 0]},
    {"t": 3, "normal": [1, 0, 0]}]})");
  EXPECT_TRUE(says(normal.notes, "Not asked in this problem (no points): normal."));
  ASSERT_EQ(normal.notes.size(), 1u);  // noted once, for both hits' normals
  // No verdict beside a score: "normal (not counted)", never "normal (0/0, partial)".
  auto lines = feedback_lines(normal);
  EXPECT_TRUE(says(lines, "normal (not counted)"));
  EXPECT_FALSE(says(lines, "normal (0/0"));
  EXPECT_DOUBLE_EQ(normal.score, 2);  // t's 2 points: the normals change nothing
}

// The sphere's normals at t = 1 and 3 are (−1, 0, 0) and (1, 0, 0); normals are worth no
// points by default. One right and one wrong is half right, but a part worth nothing has no
// share to be partly earned: it is right or wrong, in the part and in the JSON alike, and the
// score is t's 2 points either way (the points, not given, earn nothing). The same with the
// normal named worth 0 in "points".
TEST(Parts, AZeroPointPartIsNeverPartial) {
  for (const std::string& problem :
       {std::string(kPartsSphere), std::string(R"({"id": "s1", "points": {"t": 2, "normal": 0},
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})")}) {
    GradeResult r = grade(problem, R"({"hits": [{"t": 1, "normal": [-1, 0, 0]},
      {"t": 3, "normal": [0, 1, 0]}]})");
    ASSERT_NE(part(r, "normal"), nullptr) << problem;
    EXPECT_EQ(part(r, "normal")->status, PartStatus::kWrong) << problem;
    EXPECT_DOUBLE_EQ(r.score, 2);
    const nlohmann::json graded = result_json(r);  // kept: the loop reads into it
    for (const auto& p : graded["parts"]) EXPECT_NE(p["status"], "partial") << p;
    // Both right: right.
    GradeResult right = grade(problem, R"({"hits": [{"t": 1, "normal": [-1, 0, 0]},
      {"t": 3, "normal": [1, 0, 0]}]})");
    EXPECT_EQ(part(right, "normal")->status, PartStatus::kRight) << problem;
  }
}

TEST(Parts, EveryKindDeclaresItsParts) {
  for (const char* kind : {"intersect", "first-hit", "camera-ray", "reflect", "refract", "shade",
                           "ray-tree", "derive"}) {
    EXPECT_FALSE(kind_parts(kind).empty()) << kind;
  }
  EXPECT_EQ(find_part("intersect", "barycentric")->compare, Comparison::kWeights);
  EXPECT_EQ(find_part("reflect", "direction")->compare, Comparison::kDirection);
}

// One mistyped id: the other answers are graded, and the unknown id is a finding.
TEST(Parts, MistypedProblemIdIsAFinding) {
  Problem p = testing::problem(kPartsSphere);
  std::vector<Problem> problems;
  problems.push_back(std::move(p));
  Assignment a(problems);
  auto file = testing::json_file(R"({"answers": {"s1": {"hits": [{"t": 1}, {"t": 3}]},
    "s2": {"hits": []}}})");
  SubmissionGrade g = a.grade(file);
  ASSERT_TRUE(g.gradable);
  EXPECT_DOUBLE_EQ(g.score, 2);
  ASSERT_EQ(g.findings.size(), 1u);
  EXPECT_EQ(g.findings[0].path, "/answers/s2");
  EXPECT_NE(g.findings[0].message.find("did you mean 's1'"), std::string::npos);
}

}  // namespace
}  // namespace raygrade
