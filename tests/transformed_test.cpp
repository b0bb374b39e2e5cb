// Transformed objects in the intersect and first-hit kinds: the ray goes into object space by
// M⁻¹, the primitive is hit there, and the hit comes back (t kept, normals by (A⁻¹)ᵀ). Every
// expected value is worked by hand in the comment above it.
#include "shapes/transformed.h"

#include <gtest/gtest.h>

#include <cmath>

#include "grading/grade.h"
#include "kinds/intersect.h"
#include "test_util.h"

namespace raygrade {
namespace {

using nlohmann::json;

constexpr double kClose = 1e-12;

void expect_vec(const Vec3d& got, const Vec3d& want) {
  EXPECT_NEAR(got.x, want.x, kClose) << fmt::format("{}", got);
  EXPECT_NEAR(got.y, want.y, kClose) << fmt::format("{}", got);
  EXPECT_NEAR(got.z, want.z, kClose) << fmt::format("{}", got);
}

Intersection hits_of(const std::string& object, Vec3d origin, Vec3d direction) {
  return testing::shape(object)->intersect(testing::ray(origin, direction));
}

// The unit sphere scaled by 2 (radius 2), from (0, 0, −5) along +z. Object space:
// O' = (0, 0, −5)/2 = (0, 0, −2.5), D' = (0, 0, 1)/2 = (0, 0, 0.5); |O' + tD'| = 1 gives
// −2.5 + 0.5t = ±1, t = 3 and 7 (world points (0, 0, ∓2)). Untransformed: t = 4 and 6.
const char* kScaledSphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
    "transform": [{"scale": 2}]})";

TEST(Transformed, ScaledSphereIsHitAtThreeAndSeven) {
  Intersection x = hits_of(kScaledSphere, {0, 0, -5}, {0, 0, 1});
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, 3, kClose);
  EXPECT_NEAR(x.hits[1].t, 7, kClose);
  expect_vec(x.hits[0].point, {0, 0, -2});
  expect_vec(x.hits[1].point, {0, 0, 2});
  expect_vec(x.hits[0].normal, {0, 0, -1});
  expect_vec(x.hits[1].normal, {0, 0, 1});
}

// The ellipsoid x²/9 + y²/4 + z² = 1 (the unit sphere scaled by (3, 2, 1)), from (−5, 1.6, 0)
// along +x. At y = 1.6: x²/9 = 1 − 2.56/4 = 0.36, x = ±1.8, so t = 5 ∓ 1.8 = 3.2 and 6.8.
// The gradient (2x/9, 2y/4, 2z) at (∓1.8, 1.6, 0) is ∝ (∓0.2, 0.4, 0), unit (∓1, 2, 0)/√5.
// The scaled normal A·N' = (3·∓0.6, 2·0.8, 0) = (∓1.8, 1.6, 0) would be wrong.
TEST(Transformed, EllipsoidNormalsByTheInverseTranspose) {
  Intersection x = hits_of(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "transform": [{"scale": [3, 2, 1]}]})",
                           {-5, 1.6, 0}, {1, 0, 0});
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, 3.2, kClose);
  EXPECT_NEAR(x.hits[1].t, 6.8, kClose);
  expect_vec(x.hits[0].point, {-1.8, 1.6, 0});
  expect_vec(x.hits[1].point, {1.8, 1.6, 0});
  double s5 = std::sqrt(5.0);
  expect_vec(x.hits[0].normal, {-1 / s5, 2 / s5, 0});
  expect_vec(x.hits[1].normal, {1 / s5, 2 / s5, 0});
}

// The elliptic cylinder x²/4 + y² = 1 (the unit cylinder about z scaled by (2, 1, 1)), from
// (1.2, −5, 7) along (0, 2, 0): at x = 1.2, y² = 1 − 1.44/4 = 0.64, y = ∓0.8, reached at
// t = (5 ∓ 0.8)/2 = 2.1 and 2.9 (t is the world ray's: D is not normalized). The gradient
// (x/2, 2y, 0) at (1.2, ∓0.8) is (0.6, ∓1.6, 0) ∝ (0.3, ∓0.8, 0), of length √0.73.
TEST(Transformed, EllipticCylinderKeepsTheWorldT) {
  Intersection x = hits_of(R"({"type": "cylinder", "base": [0, 0, 0], "radius": 1,
      "transform": [{"scale": [2, 1, 1]}]})",
                           {1.2, -5, 7}, {0, 2, 0});
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, 2.1, kClose);
  EXPECT_NEAR(x.hits[1].t, 2.9, kClose);
  expect_vec(x.hits[0].point, {1.2, -0.8, 7});
  expect_vec(x.hits[1].point, {1.2, 0.8, 7});
  double s = std::sqrt(0.73);
  expect_vec(x.hits[0].normal, {0.3 / s, -0.8 / s, 0});
  expect_vec(x.hits[1].normal, {0.3 / s, 0.8 / s, 0});
}

// The box [0, 2] × [0, 1] × [−1, 1] turned 90° about z ((x, y) → (−y, x)) and moved by
// (10, 0, 0) fills [9, 10] × [0, 2] × [−1, 1]. From (9.5, −5, 0) along +y it is entered at
// y = 0 (t = 5) and left at y = 2 (t = 7). In object space O' = (−5, 0.5, 0), D' = (1, 0, 0):
// the faces x = 0 and x = 2, normals (∓1, 0, 0), turned to (0, ∓1, 0). The unturned box
// (x in [10, 12]) is missed.
TEST(Transformed, RotatedBoxIsEnteredAndLeftThroughItsTurnedFaces) {
  Intersection x = hits_of(R"({"type": "box", "min": [0, 0, -1], "max": [2, 1, 1],
      "transform": [{"rotate": {"axis": [0, 0, 1], "degrees": 90}}, {"translate": [10, 0, 0]}]})",
                           {9.5, -5, 0}, {0, 1, 0});
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, 5, kClose);
  EXPECT_NEAR(x.hits[1].t, 7, kClose);
  expect_vec(x.hits[0].point, {9.5, 0, 0});
  expect_vec(x.hits[1].point, {9.5, 2, 0});
  expect_vec(x.hits[0].normal, {0, -1, 0});
  expect_vec(x.hits[1].normal, {0, 1, 0});
}

// A matrix step: [[2, 0, 0], [0, 1, 0], [0, 0, 1]] is the scale (2, 1, 1); the unit sphere
// becomes x²/4 + y² + z² = 1, met from (−5, 0, 0) along +x at x = −2 and 2: t = 3 and 7.
TEST(Transformed, MatrixStepActsLikeItsScale) {
  Intersection x = hits_of(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "transform": [{"matrix": [[2, 0, 0], [0, 1, 0], [0, 0, 1]]}]})",
                           {-5, 0, 0}, {1, 0, 0});
  ASSERT_EQ(x.hits.size(), 2u);
  EXPECT_NEAR(x.hits[0].t, 3, kClose);
  EXPECT_NEAR(x.hits[1].t, 7, kClose);
}

// Spheres A at (0, 0, 5) and B at (0, 0, 10), radius 1, on the ray from the origin along +z:
// untransformed, A is hit first at t = 4. A moved by (3, 0, 0) passes 3 > 1 from the ray (a
// miss); B moved by (0, 0, −2) has its center at z = 8 and is hit first at t = 7, at
// (0, 0, 7), normal (0, 0, −1).
TEST(Transformed, TranslatedObjectsChangeTheFirstHit) {
  Problem p = testing::problem(R"({"id": "f", "kind": "first-hit",
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "objects": [
        {"name": "A", "type": "sphere", "center": [0, 0, 5], "radius": 1,
         "transform": [{"translate": [3, 0, 0]}]},
        {"name": "B", "type": "sphere", "center": [0, 0, 10], "radius": 1,
         "transform": [{"translate": [0, 0, -2]}]}]})");
  json a = p.task->answer();
  EXPECT_EQ(a["object"], "B");
  ASSERT_EQ(a["hits"].size(), 1u);
  EXPECT_NEAR(a["hits"][0]["t"].get<double>(), 7, kClose);
  expect_vec(Vec3d{a["hits"][0]["point"][0].get<double>(), a["hits"][0]["point"][1].get<double>(),
                   a["hits"][0]["point"][2].get<double>()},
             {0, 0, 7});
}

const char* kScaledSphereProblem = R"({"id": "s", "kind": "intersect", "method": "geometric",
    "ray": {"origin": [0, 0, -5], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1,
               "transform": [{"scale": 2}]}})";

const Step* find_step(const Derivation& d, const std::string& name) {
  const Step* s = d.find(name);
  EXPECT_NE(s, nullptr) << name;
  return s;
}

// The worked solution of the scaled sphere: O' = (0, 0, −2.5), D' = (0, 0, 0.5); the geometric
// method in object space: L = C − O' = (0, 0, 2.5), |D'| = 0.5, t_ca = 2.5, d² = 0, t_hc = 1,
// t0 = (2.5 − 1)/0.5 = 3, P0 = (0, 0, −1) in object space; back in the world P0_world =
// (0, 0, −5) + 3·(0, 0, 1) = (0, 0, −2), m0 = (A⁻¹)ᵀ(0, 0, −1) = (0, 0, −0.5), N0_world =
// (0, 0, −1).
TEST(Transformed, WorkedSolutionShowsTheStepsBothWays) {
  Problem p = testing::problem(kScaledSphereProblem);
  Derivation d = p.task->derive("", nullptr).front().derivation;
  auto vector_of = [&](const char* name) {
    const Step* s = find_step(d, name);
    return s ? s->value.vector : Vec3d{1e9, 1e9, 1e9};
  };
  expect_vec(vector_of("O_obj"), {0, 0, -2.5});
  expect_vec(vector_of("D_obj"), {0, 0, 0.5});
  const Step* t0 = find_step(d, "t0");
  ASSERT_NE(t0, nullptr);
  EXPECT_NEAR(t0->value.scalar, 3, kClose);
  expect_vec(vector_of("P0"), {0, 0, -1});
  expect_vec(vector_of("P0_world"), {0, 0, -2});
  expect_vec(vector_of("m0"), {0, 0, -0.5});
  expect_vec(vector_of("N0_world"), {0, 0, -1});
  expect_vec(vector_of("P1_world"), {0, 0, 2});
}

PartStatus status_of(const GradeResult& r, const std::string& part) {
  for (const auto& x : r.parts) {
    if (x.name == part) return x.status;
  }
  ADD_FAILURE() << "no part " << part;
  return PartStatus::kWrong;
}

TEST(Transformed, WorldAnswerIsGradedRight) {
  Problem p = testing::problem(kScaledSphereProblem);
  GradeResult r = grade_answer(p, json::parse(R"({"hits": [
      {"t": 3, "point": [0, 0, -2], "normal": [0, 0, -1]},
      {"t": 7, "point": [0, 0, 2], "normal": [0, 0, 1]}],
      "steps": {"O_obj": [0, 0, -2.5], "D_obj": [0, 0, 0.5], "t0": 3}})"));
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
  EXPECT_EQ(status_of(r, "steps"), PartStatus::kRight);
}

// The untransformed sphere's answer (t = 4 and 6) is the silent wrong answer the solver gave
// before transforms were applied outside scenes.
TEST(Transformed, UntransformedAnswerIsGradedWrong) {
  Problem p = testing::problem(kScaledSphereProblem);
  GradeResult r = grade_answer(p, json::parse(R"({"hits": [{"t": 4}, {"t": 6}]})"));
  EXPECT_EQ(status_of(r, "t"), PartStatus::kWrong);
  EXPECT_LT(r.score, r.max_score);
}

// The ray taken into object space by M instead of M⁻¹: O' = 2·(0, 0, −5) = (0, 0, −10) and
// D' = (0, 0, 2). Then |−10 + 2t| = 1 gives t = 4.5 and 5.5, the world points (0, 0, −5) + t·ẑ
// = (0, 0, −0.5) and (0, 0, 0.5). They follow from the wrong steps: error carried forward, half
// of the t part's 2 points.
TEST(Transformed, RayTakenByTheMatrixIsCarriedForward) {
  Problem p = testing::problem(kScaledSphereProblem);
  GradeResult r = grade_answer(p, json::parse(R"({"steps": {"O_obj": [0, 0, -10],
      "D_obj": [0, 0, 2]},
      "hits": [{"t": 4.5, "point": [0, 0, -0.5]}, {"t": 5.5, "point": [0, 0, 0.5]}]})"));
  EXPECT_TRUE(r.carried_forward);
  for (const auto& x : r.parts) {
    if (x.name == "t") {
      EXPECT_DOUBLE_EQ(x.points, 1);
    }
  }
  EXPECT_EQ(status_of(r, "steps"), PartStatus::kWrong);  // both steps given are wrong
}

// The ellipsoid of EllipsoidNormalsByTheInverseTranspose: at (−1.8, 1.6, 0) the object-space
// normal is N' = (−0.6, 0.8, 0); taken back by A = diag(3, 2, 1) it would be (−1.8, 1.6, 0),
// not the right (−0.2, 0.4, 0) ∝ (−1, 2, 0) that (A⁻¹)ᵀ = diag(1/3, 1/2, 1) gives.
TEST(Transformed, NormalByTheMatrixIsNamed) {
  Problem p = testing::problem(R"({"id": "e", "kind": "intersect",
      "ray": {"origin": [-5, 1.6, 0], "direction": [1, 0, 0]},
      "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "transform": [{"scale": [3, 2, 1]}]}})");
  GradeResult wrong = grade_answer(p, json::parse(R"({"hits": [
      {"t": 3.2, "point": [-1.8, 1.6, 0], "normal": [-1.8, 1.6, 0]},
      {"t": 6.8, "point": [1.8, 1.6, 0], "normal": [1, 2, 0]}]})"));
  ASSERT_EQ(wrong.mistakes.size(), 1u);
  EXPECT_EQ(wrong.mistakes[0].id, "normal-not-inverse-transpose");
  // One of two normals right; worth no points, the part is wrong, never partial.
  EXPECT_EQ(status_of(wrong, "normal"), PartStatus::kWrong);
  GradeResult right = grade_answer(p, json::parse(R"({"hits": [
      {"t": 3.2, "point": [-1.8, 1.6, 0], "normal": [-1, 2, 0]},
      {"t": 6.8, "point": [1.8, 1.6, 0], "normal": [1, 2, 0]}]})"));
  EXPECT_TRUE(right.mistakes.empty());
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
}

void expect_error_at(const char* problem, const std::string& path) {
  try {
    testing::problem(problem);
    ADD_FAILURE() << "no error; expected one at " << path;
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().path, path) << e.diagnostic().message;
  }
}

// det [[1, 2, 3], [2, 4, 6], [0, 0, 1]] = 0: the second row is twice the first.
TEST(Transformed, SingularMatrixIsAnErrorAtItsPath) {
  expect_error_at(R"({"id": "s", "kind": "intersect",
      "ray": {"origin": [0, 0, -5], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "transform": [{"translate": [1, 0, 0]},
                               {"matrix": [[1, 2, 3], [2, 4, 6], [0, 0, 1]]}]}})",
                  "/object/transform/1/matrix");
}

// Scales of 1e-200 twice: each step is invertible, their product (1e-400) rounds to 0.
TEST(Transformed, SingularProductIsAnErrorAtTheTransform) {
  expect_error_at(R"({"id": "s", "kind": "first-hit",
      "ray": {"origin": [0, 0, -5], "direction": [0, 0, 1]},
      "objects": [{"name": "A", "type": "sphere", "center": [0, 0, 0], "radius": 1,
                   "transform": [{"scale": 1e-200}, {"scale": 1e-200}]}]})",
                  "/objects/0/transform");
}

TEST(Transformed, MaterialOutsideAScene) {
  expect_error_at(R"({"id": "s", "kind": "intersect",
      "ray": {"origin": [0, 0, -5], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "material": {"diffuse": 0.5}}})",
                  "/object/material");
}

}  // namespace
}  // namespace raygrade
