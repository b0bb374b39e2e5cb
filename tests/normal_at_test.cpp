// The normal kind: normals at given points of plain and transformed objects against values
// worked by hand, points off the surface and on edges as errors, and the grading of a normal.
#include "kinds/normal_at.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "grading/grade.h"
#include "test_util.h"

namespace raygrade {
namespace {

Vec3d normal_of(const std::string& object, const std::string& point) {
  Problem p = testing::problem(R"({"id": "n", "kind": "normal", "object": )" + object +
                               R"(, "point": )" + point + "}");
  nlohmann::json n = p.task->answer()["normal"];
  return {n[0].get<double>(), n[1].get<double>(), n[2].get<double>()};
}

void expect_near(const Vec3d& got, const Vec3d& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12) << fmt::format("{}", got);
  EXPECT_NEAR(got.y, want.y, 1e-12) << fmt::format("{}", got);
  EXPECT_NEAR(got.z, want.z, 1e-12) << fmt::format("{}", got);
}

// P − C = (2, 1, 2), of length 3 = r.
TEST(NormalKind, SphereIsTheDirectionFromTheCentre) {
  expect_near(normal_of(R"({"type": "sphere", "center": [1, 1, 1], "radius": 3})", "[3, 2, 3]"),
              {2.0 / 3, 1.0 / 3, 2.0 / 3});
}

// x²/4 + y² = 1 at (√2, √2/2): the gradient (x/2, 2y) = (√2/2, √2) ∥ (1, 2).
TEST(NormalKind, EllipsoidNormalGoesBackByTheInverseTranspose) {
  expect_near(normal_of(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                            "transform": [{"scale": [2, 1, 1]}]})",
                        "[1.4142135623730951, 0.7071067811865476, 0]"),
              {1 / std::sqrt(5.0), 2 / std::sqrt(5.0), 0});
}

TEST(NormalKind, CylinderSideAndCaps) {
  const std::string can = R"({"type": "cylinder", "base": [0, 0, 0], "axis": [0, 2, 0],
    "radius": 2, "height": 3, "capped": true})";
  expect_near(normal_of(can, "[1.2, 1, 1.6]"), {0.6, 0, 0.8});
  expect_near(normal_of(can, "[0.5, 3, 0.5]"), {0, 1, 0});
  expect_near(normal_of(can, "[0.5, 0, -1]"), {0, -1, 0});
}

// The quarter turn about z takes the face x = 1 to y = 1 (then moved by 5 along x).
TEST(NormalKind, TurnedBoxFace) {
  expect_near(normal_of(R"({"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1],
    "transform": [{"rotate": {"axis": [0, 0, 1], "degrees": 90}}, {"translate": [5, 0, 0]}]})",
                        "[5, 1, 0.5]"),
              {0, 1, 0});
}

// (2, 0, 0) × (0, 2, 2) = (0, −4, 4); the plane's normal as given, normalized.
TEST(NormalKind, FlatObjects) {
  expect_near(normal_of(R"({"type": "triangle", "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 2]]})",
                        "[0.5, 0.5, 0.5]"),
              {0, -1 / std::sqrt(2.0), 1 / std::sqrt(2.0)});
  expect_near(
      normal_of(R"({"type": "plane", "point": [0, 2, 0], "normal": [0, 0, -3]})", "[7, 2, 0]"),
      {0, 0, -1});
  expect_near(normal_of(R"({"type": "polygon", "vertices": [[0, 0, 0], [2, 0, 0], [2, 2, 0],
                            [1, 1, 0], [0, 2, 0]]})",
                        "[0.5, 0.5, 0]"),
              {0, 0, 1});
}

std::string error_of(const std::string& object, const std::string& point) {
  try {
    testing::problem(R"({"id": "n", "kind": "normal", "object": )" + object + R"(, "point": )" +
                     point + "}");
  } catch (const Error& e) {
    return e.diagnostic().path + ": " + e.diagnostic().code + ": " + e.diagnostic().message;
  }
  return "no error";
}

// (1, 1, 4.5) is 3.5 from the centre (1, 1, 1) of a sphere of radius 3: 0.5 outside, and the
// nearest surface point is (1, 1, 4). Scaled by 2, the unit sphere has radius 2: (0, 0, 3) is 1
// off, the nearest point (0, 0, 2).
TEST(NormalKind, PointOffTheSurfaceSaysHowFar) {
  std::string e =
      error_of(R"({"type": "sphere", "center": [1, 1, 1], "radius": 3})", "[1, 1, 4.5]");
  EXPECT_NE(e.find("/point: off-surface:"), std::string::npos) << e;
  EXPECT_NE(e.find("it is 0.5 from the surface point (1, 1, 4)"), std::string::npos) << e;
  e = error_of(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                   "transform": [{"scale": 2}]})",
               "[0, 0, 3]");
  EXPECT_NE(e.find("it is 1 from the surface point (0, 0, 2)"), std::string::npos) << e;
  // Inside a triangle's plane but outside the triangle: 1 from its edge x + y = 2... the
  // point (2, 1, 0) is √2/2 from the hypotenuse of (0,0,0), (2,0,0), (0,2,0).
  e = error_of(R"({"type": "triangle", "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]]})",
               "[1.5, 1.5, 0]");
  EXPECT_NE(e.find("it is 0.7071 from the surface point (1, 1, 0)"), std::string::npos) << e;
}

// A primitive the normal kind does not take is the problem's fault, named at its type, not
// an internal error.
TEST(NormalKind, APrimitiveItDoesNotTakeIsAnErrorAtItsType) {
  std::string e = error_of(
      R"({"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1})", "[0.5, 0, 0]");
  EXPECT_NE(e.find("/object/type: unknown-type: the normal kind takes a sphere, plane"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("not a disk"), std::string::npos) << e;
}

TEST(NormalKind, EdgesAndRimsHaveNoNormal) {
  std::string e =
      error_of(R"({"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]})", "[1, 1, 0]");
  EXPECT_NE(e.find("degenerate"), std::string::npos) << e;
  EXPECT_NE(e.find("face x = 1 meets its face y = 1"), std::string::npos) << e;
  e = error_of(R"({"type": "cylinder", "base": [0, 0, 0], "axis": [0, 1, 0], "radius": 2,
                   "height": 3, "capped": true})",
               "[2, 3, 0]");
  EXPECT_NE(e.find("side meets its top cap"), std::string::npos) << e;
}

// The ellipsoid of EllipsoidNormalGoesBackByTheInverseTranspose: N' = (√2/2, √2/2, 0) taken
// by A = diag(2, 1, 1) is (√2, √2/2, 0) ∥ (2, 1, 0), not (1, 2, 0).
TEST(NormalKind, NormalByTheMatrixIsNamed) {
  Problem p = testing::problem(R"({"id": "n", "kind": "normal",
    "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1,
               "transform": [{"scale": [2, 1, 1]}]},
    "point": [1.4142135623730951, 0.7071067811865476, 0]})");
  GradeResult right = grade_answer(p, nlohmann::json::parse(R"({"normal": [1, 2, 0]})"));
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
  GradeResult by_a = grade_answer(p, nlohmann::json::parse(R"({"normal": [2, 1, 0]})"));
  EXPECT_DOUBLE_EQ(by_a.score, 0);
  EXPECT_TRUE(by_a.has_mistake("normal-not-inverse-transpose"));
}

TEST(NormalKind, InwardNormalIsGradedWrong) {
  Problem p = testing::problem(R"({"id": "n", "kind": "normal",
    "object": {"type": "sphere", "center": [1, 1, 1], "radius": 3}, "point": [3, 2, 3]})");
  GradeResult right = grade_answer(p, nlohmann::json::parse(R"({"normal": [2, 1, 2]})"));
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
  GradeResult inward = grade_answer(p, nlohmann::json::parse(R"({"normal": [-2, -1, -2]})"));
  // The inward-normal mistake keeps half the credit (grading/mistakes.cpp).
  EXPECT_DOUBLE_EQ(inward.score, 0.5 * inward.max_score);
  EXPECT_TRUE(inward.has_mistake("inward-normal"));
  ASSERT_FALSE(inward.parts.empty());
  EXPECT_NE(inward.parts[0].feedback[0].find("points into the object"), std::string::npos);
}

}  // namespace
}  // namespace raygrade
