// Grading answers: parts, roots in either order, no-hit answers, the tangent's tolerance and
// error carried forward, by values derived by hand.
#include "grading/grade.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "test_util.h"

namespace raygrade {
namespace {

using nlohmann::json;

// Seed 000, sphere case 1: t = 1 and 3, P = (1,0,0) and (3,0,0).
const char* kSphere1 = R"({"id": "s1", "method": "geometric",
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})";

// Seed 000, sphere case 2: the sphere lies behind the origin (roots −3 and −1).
const char* kSphere2 = R"({"id": "s2", "method": "geometric",
  "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
  "object": {"type": "sphere", "center": [-2, 0, 0], "radius": 1}})";

using testing::part;

GradeResult grade(const char* problem, const char* answer) {
  Problem p = testing::problem(problem);
  return grade_answer(p, json::parse(answer));
}

TEST(Grade, SeedSphereCase1WithStepsIsRight) {
  auto r = grade(kSphere1, R"({"hits": [{"t": 1, "point": [1, 0, 0]},
      {"t": 3, "point": [3, 0, 0]}], "steps": {"L": [2, 0, 0], "t_ca": 2, "d2": 0, "t_hc": 1}})");
  EXPECT_DOUBLE_EQ(r.max_score, 3);  // t 2 + point 1 by default
  EXPECT_DOUBLE_EQ(r.score, 3);
  EXPECT_TRUE(r.mistakes.empty());
  ASSERT_NE(part(r, "steps"), nullptr);
  EXPECT_EQ(part(r, "steps")->status, PartStatus::kRight);
}

TEST(Grade, RootsMatchInEitherOrder) {
  for (const char* answer :
       {R"({"hits": [{"t": "3"}, {"t": 1}]})", R"({"hits": [{"t": 1}, {"t": 3}]})"}) {
    auto r = grade(kSphere1, answer);
    ASSERT_NE(part(r, "t"), nullptr);
    EXPECT_DOUBLE_EQ(part(r, "t")->points, 2) << answer;
  }
}

TEST(Grade, OneOfTwoRootsEarnsHalf) {
  auto r = grade(kSphere1, R"({"hits": [{"t": 1}]})");
  EXPECT_DOUBLE_EQ(part(r, "t")->points, 1);
  EXPECT_EQ(part(r, "t")->status, PartStatus::kPartial);
}

TEST(Grade, ExtraHitCostsItsShare) {
  auto r = grade(kSphere1, R"({"hits": [{"t": 1}, {"t": 3}, {"t": 5}]})");
  EXPECT_NEAR(part(r, "t")->points, 2.0 * 2 / 3, 1e-12);
}

TEST(Grade, NoIntersectionIsGradable) {
  auto r = grade(kSphere2, R"({"hits": []})");
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
  EXPECT_GT(r.max_score, 0);
  auto wrong = grade(kSphere1, R"({"hits": []})");
  EXPECT_DOUBLE_EQ(part(wrong, "t")->points, 0);
}

TEST(Grade, MissingPartsEarnNothing) {
  auto r = grade(kSphere1, R"({})");
  EXPECT_DOUBLE_EQ(r.score, 0);
  EXPECT_DOUBLE_EQ(r.max_score, 3);
  EXPECT_EQ(part(r, "t")->status, PartStatus::kMissing);
}

TEST(Grade, UnparsableNumberIsFeedbackNotError) {
  auto r = grade(kSphere1, R"({"hits": [{"t": "7.2.7"}, {"t": 3}]})");
  EXPECT_DOUBLE_EQ(part(r, "t")->points, 1);
  bool told = false;
  for (const auto& f : part(r, "t")->feedback) told |= f.find("character 4") != std::string::npos;
  EXPECT_TRUE(told);
}

TEST(Grade, WrongJsonTypeThrowsWithPath) {
  Problem p = testing::problem(kSphere1);
  GradeOptions o{"alice.json", "/answers/s1"};
  try {
    grade_answer(p, json::parse(R"({"hits": {"t": 1}})"), o);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().file, "alice.json");
    EXPECT_EQ(e.diagnostic().path, "/answers/s1/hits");
  }
}

TEST(Grade, PointsFromTheProblem) {
  Problem p = testing::problem(R"({"id": "s", "points": {"t": 4, "point": 0, "normal": 2},
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  auto r = grade_answer(
      p,
      json::parse(R"({"hits": [{"t": 1, "normal": [-1, 0, 0]}, {"t": 3, "normal": [2, 0, 0]}]})"));
  EXPECT_DOUBLE_EQ(r.max_score, 6);
  EXPECT_DOUBLE_EQ(r.score, 6);  // a normal of length 2 is right as a direction
  Problem total = testing::problem(R"({"id": "s", "points": 9,
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  EXPECT_DOUBLE_EQ(Grader(total).max_score(), 9);  // t 6, point 3
}

// A ray along z at x = 1 grazes the unit sphere at (1, 0, 5): a = 1, b = −10, c = 25, Δ = 0.
// δΔ = 1e-4 (b² + 4|ac|) = 0.02, so t may be off by √0.02 / 2 = 0.0707.
TEST(Grade, TangentToleranceFollowsConditioning) {
  const char* tangent = R"({"id": "g", "ray": {"origin": [1, 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 5], "radius": 1}})";
  EXPECT_DOUBLE_EQ(part(grade(tangent, R"({"hits": [{"t": 5.07}]})"), "t")->points, 2);
  EXPECT_DOUBLE_EQ(part(grade(tangent, R"({"hits": [{"t": 5.072}]})"), "t")->points, 0);
  // Far from a tangent the usual 0.1% holds.
  EXPECT_DOUBLE_EQ(part(grade(kSphere1, R"({"hits": [{"t": 1.07}, {"t": 3}]})"), "t")->points, 1);
}

// A ray that nearly grazes the unit ball at (0, 10, 10): O = 0, D = (0, 10.6, 9.2) gives
// a = 197, b = 2 D·(O − C) = −396, c = 199, Δ = 396² − 4·197·199 = 4, so t = 394/394 = 1
// (entering at (0, 10.6, 9.2)) and t = 398/394 = 1.01015 (leaving at (0, 10.7076, 9.2934)).
// At one decimal the exit point is (0, 10.7, 9.3): never the entry, however the tolerance
// of a badly conditioned root is widened.
const char* kGrazeFirstHit = R"({"id": "g1", "kind": "first-hit",
  "ray": {"origin": [0, 0, 0], "direction": [0, 10.6, 9.2]},
  "objects": [{"name": "A", "type": "sphere", "center": [0, 10, 10], "radius": 1}],
  "tolerance": {"decimals": 1}})";
const char* kGrazeIntersect = R"({"id": "g2",
  "ray": {"origin": [0, 0, 0], "direction": [0, 10.6, 9.2]},
  "object": {"type": "sphere", "center": [0, 10, 10], "radius": 1},
  "tolerance": {"decimals": 1}})";

TEST(Grade, AWidenedToleranceNeverReachesTheOtherRoot) {
  auto exit = grade(kGrazeFirstHit, R"({"object": "A", "hits": [{"t": 1.0,
    "point": [0, 10.7, 9.3]}]})");
  EXPECT_EQ(part(exit, "point")->points, 0);
  EXPECT_NE(part(exit, "point")->feedback.front().find("at t = 1.01"), std::string::npos);
  auto entry = grade(kGrazeFirstHit, R"({"object": "A", "hits": [{"t": 1.0,
    "point": [0, 10.6, 9.2]}]})");
  EXPECT_EQ(entry.fraction(), 1);
  // t = 1.01 is nearer the exit (1.01015) than the entry (1): the far root, not the hit.
  auto far = grade(kGrazeFirstHit, R"({"object": "A", "hits": [{"t": 1.01}]})");
  EXPECT_EQ(part(far, "t")->points, 0);
  ASSERT_FALSE(far.mistakes.empty());
  EXPECT_EQ(far.mistakes.front().id, "far-root");
}

TEST(Grade, OnePointGivenTwiceIsOneHit) {
  auto twice = grade(kGrazeIntersect, R"({"hits": [{"point": [0, 10.6, 9.2]},
    {"point": [0, 10.6, 9.2]}]})");
  EXPECT_DOUBLE_EQ(part(twice, "point")->points, 0.5);
  auto both = grade(kGrazeIntersect, R"({"hits": [{"point": [0, 10.7, 9.3]},
    {"point": [0, 10.6, 9.2]}]})");
  EXPECT_DOUBLE_EQ(part(both, "point")->points, 1);
  // Both roots are 1.0 to one decimal: at the precision asked, 1.0 twice is right.
  auto ts = grade(kGrazeIntersect, R"({"hits": [{"t": 1.0}, {"t": 1.0}]})");
  EXPECT_DOUBLE_EQ(part(ts, "t")->points, 2);
}

// A capped cylinder (r = 1, height 1 along z) entered through its side: from (−5, 0, 2.996)
// along (1, 0, −0.5), x = −1 at t = 4 (z = 0.996), and the bottom cap z = 0 at t = 5.992 (x =
// 0.992). The top cap's plane z = 1 is crossed at t = 3.992, at x = −1.008: outside the cap,
// no point of the cylinder. To two decimals 3.995 is right for t = 4, although nearer 3.992.
TEST(Grade, ARootOnNoSurfaceTakesNoValueFromTheHit) {
  auto r = grade(R"({"id": "c", "ray": {"origin": [-5, 0, 2.996], "direction": [1, 0, -0.5]},
    "object": {"type": "cylinder", "base": [0, 0, 0], "axis": [0, 0, 1], "radius": 1,
               "height": 1, "capped": true}, "tolerance": {"decimals": 2}})",
                 R"({"hits": [{"t": 3.995}, {"t": 5.992}]})");
  EXPECT_DOUBLE_EQ(part(r, "t")->points, 2);
}

// The triangle a = (0, 0, 0), b = (1, 0, 0), c = (0, 1, 0), hit from (0.2, 0.3, 1) along −z at
// t = 1, P = (0.2, 0.3, 0): P = a + u(b − a) + v(c − a) with u = 0.2, v = 0.3, so the weights
// are (w_a, w_b, w_c) = (0.5, 0.2, 0.3). Given alone, they give t and the point in another form.
TEST(Grade, AHitGivenByItsWeightsAloneIsGraded) {
  const char* triangle = R"({"id": "tri", "ray": {"origin": [0.2, 0.3, 1], "direction": [0, 0, -1]},
    "object": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}})";
  for (const char* answer :
       {R"({"hits": [{"u": 0.2, "v": 0.3}]})", R"({"hits": [{"barycentric": [0.5, 0.2, 0.3]}]})"}) {
    auto r = grade(triangle, answer);
    EXPECT_DOUBLE_EQ(r.score, 3) << answer;  // t 2, point 1
    EXPECT_EQ(std::count_if(r.notes.begin(), r.notes.end(),
                            [](const std::string& n) {
                              return n.find("weights alone") != std::string::npos;
                            }),
              1)
        << answer;
  }
  // Weights in the wrong order are no hit's: nothing is read from them.
  auto wrong = grade(triangle, R"({"hits": [{"barycentric": [0.3, 0.2, 0.5]}]})");
  EXPECT_DOUBLE_EQ(wrong.score, 0);
  auto swapped = grade(triangle, R"({"hits": [{"u": 0.3, "v": 0.2}]})");
  EXPECT_DOUBLE_EQ(swapped.score, 0);
}

// d² given as 0.75 instead of 0: t_hc = √(1 − 0.75) = 0.5 follows from it, and so do
// t = 2 ∓ 0.5 = 1.5 and 2.5 and the points (1.5, 0, 0) and (2.5, 0, 0).
TEST(Grade, ErrorCarriedForward) {
  auto r = grade(kSphere1, R"({"steps": {"t_ca": 2, "d2": 0.75, "t_hc": 0.5},
      "hits": [{"t": 1.5, "point": [1.5, 0, 0]}, {"t": 2.5, "point": [2.5, 0, 0]}]})");
  EXPECT_TRUE(r.carried_forward);
  EXPECT_DOUBLE_EQ(part(r, "t")->points, 1);        // half of 2
  EXPECT_DOUBLE_EQ(part(r, "point")->points, 0.5);  // half of 1
  bool said = false;
  for (const auto& f : part(r, "t")->feedback)
    said |= f.find("carried forward") != std::string::npos;
  EXPECT_TRUE(said);
  // Steps: t_ca right, d2 wrong, t_hc carried forward.
  EXPECT_NEAR(part(r, "steps")->max_points, 0, 0);
  // Worth no points, the steps are never partial: not all right, they are wrong.
  EXPECT_EQ(part(r, "steps")->status, PartStatus::kWrong);
  // Without the wrong step the same t values earn nothing.
  auto bare = grade(kSphere1, R"({"hits": [{"t": 1.5}, {"t": 2.5}]})");
  EXPECT_DOUBLE_EQ(part(bare, "t")->points, 0);
  EXPECT_FALSE(bare.carried_forward);
}

// Nothing is carried forward from a trivial value. Seed 000's sphere case 1 (C = (2, 0, 0),
// r = 1, D = +x): L = C − O = (2, 0, 0) and t_ca = L·D = 2. L given as the zero vector makes
// t_ca = 0 "follow" from it for free; L = (3, 0, 0), a real slip, still carries t_ca = 3.
// t = 0 puts P = O + 0·D at the ray's origin (0, 0, 0): no carried credit for that point.
TEST(Grade, NoCreditCarriedFromATrivialValue) {
  auto zero = grade(kSphere1, R"({"steps": {"L": [0, 0, 0], "t_ca": 0}})");
  EXPECT_EQ(part(zero, "steps")->status, PartStatus::kWrong);
  EXPECT_FALSE(zero.carried_forward);
  std::string said = fmt::format("{}", fmt::join(part(zero, "steps")->feedback, " "));
  EXPECT_NE(said.find("nothing later is carried forward"), std::string::npos) << said;
  auto slip = grade(kSphere1, R"({"steps": {"L": [3, 0, 0], "t_ca": 3}})");
  // The steps carry no points, so the slip's are wrong, not partial (a part worth nothing is
  // never partial); what sets it apart is that t_ca is carried forward from it.
  EXPECT_EQ(part(slip, "steps")->status, PartStatus::kWrong);
  said = fmt::format("{}", fmt::join(part(slip, "steps")->feedback, " "));
  EXPECT_EQ(said.find("nothing later is carried forward"), std::string::npos) << said;
  EXPECT_NE(said.find("t_ca = 3 follows correctly from your earlier values"), std::string::npos)
      << said;
  // No credit came of it (the steps are worth nothing), so the result is not marked as carrying
  // credit forward.
  EXPECT_FALSE(slip.carried_forward);
  auto origin = grade(kSphere1, R"({"hits": [{"t": 0, "point": [0, 0, 0]}]})");
  EXPECT_DOUBLE_EQ(part(origin, "point")->points, 0);
  EXPECT_FALSE(origin.carried_forward);
  // A wrong t that is not 0 still carries its point: t = 1.5 gives (1.5, 0, 0), half the
  // credit of one of the two hits' points.
  auto own = grade(kSphere1, R"({"hits": [{"t": 1.5, "point": [1.5, 0, 0]}]})");
  EXPECT_DOUBLE_EQ(part(own, "point")->points, 0.25);
}

// Steps of the wrong shape or a yes/no are feedback, never an error or a crash.
TEST(Grade, StepsOfTheWrongShapeAreFeedback) {
  auto r = grade(kSphere1, R"({"steps": {"t_ca": [1, 2, 3], "L": 2, "d2": true, "x": 1},
      "hits": [{"t": 1}, {"t": 3}]})");
  EXPECT_DOUBLE_EQ(part(r, "t")->points, 2);
  EXPECT_EQ(part(r, "steps")->status, PartStatus::kWrong);
  EXPECT_GE(part(r, "steps")->feedback.size(), 3u);
}

TEST(Grade, CarriedForwardCreditFromProblem) {
  auto r = grade(R"({"id": "s1", "method": "geometric", "points": {"carried_forward": 1},
      "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
      "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})",
                 R"({"steps": {"d2": 0.75}, "hits": [{"t": 1.5}, {"t": 2.5}]})");
  EXPECT_DOUBLE_EQ(part(r, "t")->points, 2);
}

// Seed 000 plane case 1: the student's D = −2 (they took D = N·V0), t = 2 right.
TEST(Grade, SeedPlaneDSignSlipFlaggedWhileTIsRight) {
  auto r = grade(R"({"id": "p1", "method": "implicit",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "plane", "point": [2, 0, 0], "normal": [-1, 0, 0]}})",
                 R"({"hits": [{"t": 2, "point": [2, 0, 0]}], "steps": {"D": -2}})");
  EXPECT_TRUE(r.has_mistake("plane-d-sign"));
  EXPECT_DOUBLE_EQ(r.score, 3);
}

TEST(Grade, FirstHitSeed001AtTwoDecimals) {
  const char* p = R"({"id": "f", "kind": "first-hit", "precision": 2,
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "objects": [{"name": "sphere 1", "type": "sphere", "center": [0, 0, 10], "radius": 2},
                {"name": "sphere 2", "type": "sphere", "center": [0, 3, 8], "radius": 2},
                {"name": "sphere 3", "type": "sphere", "center": [0, 1, 9], "radius": 2}]})";
  auto r = grade(p, R"({"object": "Sphere 3", "hits": [{"t": 7.27, "point": [0, 0, 7.27]}]})");
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
  EXPECT_TRUE(r.mistakes.empty());
  auto coarse = grade(p, R"({"object": "sphere 3", "hits": [{"t": 7.3}]})");
  EXPECT_EQ(part(coarse, "t")->status, PartStatus::kWrong);
  EXPECT_NE(part(coarse, "t")->feedback.front().find("2 decimal places"), std::string::npos);
  auto wrong = grade(p, R"({"object": "sphere 1", "hits": [{"t": 8}]})");
  EXPECT_DOUBLE_EQ(part(wrong, "object")->points, 0);
  EXPECT_DOUBLE_EQ(part(wrong, "t")->points, 0);
}

TEST(Grade, FormulaAnswers) {
  const char* p = R"({"id": "d", "kind": "derive", "find": ["a", "b", "c"],
    "ray": {"origin": [-3, 0, 0.5], "direction": [1, 0, 0]},
    "object": {"type": "cylinder", "base": [0, 0, 0], "axis": [0, 0, 1], "radius": 1}})";
  for (const char* b :
       {"2*(px*vx + py*vy)", "2px vx + 2 py vy", "2\u00b7(p_x\u00b7v_x + p_y\u00b7v_y)",
        "(px + vx)^2 - px^2 - vx^2 + 2*py*vy"}) {
    auto r = grade(p, fmt::format(R"({{"b": "{}"}})", b).c_str());
    EXPECT_EQ(part(r, "b")->status, PartStatus::kRight) << b;
  }
  auto wrong = grade(p, R"({"a": "vx^2 + vy", "b": "2*px*vx"})");
  EXPECT_EQ(part(wrong, "a")->status, PartStatus::kWrong);
  EXPECT_EQ(part(wrong, "b")->status, PartStatus::kWrong);
  EXPECT_TRUE(wrong.mistakes.empty());
  auto bad = grade(p, R"({"b": "2*(px*vx + py*vy"})");
  EXPECT_EQ(part(bad, "b")->status, PartStatus::kWrong);
  EXPECT_NE(part(bad, "b")->feedback.front().find("at character 17"), std::string::npos);
  auto unknown = grade(p, R"({"c": "px^2 + pz^2 - r^2"})");
  EXPECT_NE(part(unknown, "c")->feedback.front().find("'pz'"), std::string::npos);
  // The offset case uses cx, cy for the axis (the seed's a, b).
  auto off =
      grade(R"({"id": "o", "kind": "derive", "find": ["b", "c"],
    "ray": {"origin": [0, 0, 0], "direction": [1, 1, 0.2]},
    "object": {"type": "cylinder", "base": [2, 3, 0], "axis": [0, 0, 1], "radius": 2}})",
            R"j({"b": "2*((px - cx)*vx + (py - cy)*vy)", "c": "(px-cx)^2 + (py-cy)^2 - r^2"})j");
  EXPECT_DOUBLE_EQ(off.score, 2);
}

}  // namespace
}  // namespace raygrade
