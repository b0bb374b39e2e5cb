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

// The disk of radius 2 around (0, 0, 5) with normal (0, 0, −2) as given: (0, 0, −1) at every
// point of it, its rim (2, 0, 5) included (flat: no edge between parts there). The point
// (3, 0, 5) is 1 beyond the rim, whose point (2, 0, 5) is the nearest.
TEST(NormalKind, DiskIsItsGivenNormalRimIncluded) {
  const std::string disk = R"({"type": "disk", "center": [0, 0, 5], "normal": [0, 0, -2],
    "radius": 2})";
  expect_near(normal_of(disk, "[1, 1, 5]"), {0, 0, -1});
  expect_near(normal_of(disk, "[2, 0, 5]"), {0, 0, -1});
  std::string e = error_of(disk, "[3, 0, 5]");
  EXPECT_NE(e.find("off-surface"), std::string::npos) << e;
  EXPECT_NE(e.find("it is 1 from the surface point (2, 0, 5)"), std::string::npos) << e;
}

// Radius 3, height 4 (slant 5): at height 2 the side's radius is 3·(4 − 2)/4 = 1.5, and its
// normal (h·ê + r·â)/5 = (4ê + 3â)/5: (0.8, 0, 0.6) at (1.5, 0, 2), (0, −0.8, 0.6) at
// (0, −1.5, 2). The apex (0, 0, 4) has â = (0, 0, 1) by convention; the cap −â; the rim
// (3, 0, 0) the side's normal, as the cone's hits there. (0, 0, 2), on the axis, is 1.2 from the
// side: the distance from the line 4x + 3z = 12 (in the plane y = 0) to (0, 2) is |6 − 12|/5.
TEST(NormalKind, ConeSideApexCapAndRim) {
  const std::string cone = R"({"type": "cone", "base": [0, 0, 0], "radius": 3, "height": 4,
    "capped": true})";
  expect_near(normal_of(cone, "[1.5, 0, 2]"), {0.8, 0, 0.6});
  expect_near(normal_of(cone, "[0, -1.5, 2]"), {0, -0.8, 0.6});
  expect_near(normal_of(cone, "[0, 0, 4]"), {0, 0, 1});
  expect_near(normal_of(cone, "[1, 1, 0]"), {0, 0, -1});
  expect_near(normal_of(cone, "[3, 0, 0]"), {0.8, 0, 0.6});
  std::string e = error_of(cone, "[0, 0, 2]");
  EXPECT_NE(e.find("it is 1.2 from the surface point"), std::string::npos) << e;
}

// Around the segment (0, 0, 0)–(0, 0, 4) with radius 2: on the side (2, 0, 1) the normal is
// from its foot (0, 0, 1), (1, 0, 0); on the end at b, (0, 1.2, 5.6) − (0, 0, 4) = (0, 1.2, 1.6)
// of length 2: (0, 0.6, 0.8); the end at a's pole (0, 0, −2): (0, 0, −1). The rims (2, 0, 4) and
// (0, −2, 0), where side and end meet smoothly, have the side's normal, with no error.
TEST(NormalKind, CapsuleSideEndsAndRims) {
  const std::string capsule = R"({"type": "capsule", "a": [0, 0, 0], "b": [0, 0, 4],
    "radius": 2})";
  expect_near(normal_of(capsule, "[2, 0, 1]"), {1, 0, 0});
  expect_near(normal_of(capsule, "[0, 1.2, 5.6]"), {0, 0.6, 0.8});
  expect_near(normal_of(capsule, "[0, 0, -2]"), {0, 0, -1});
  expect_near(normal_of(capsule, "[2, 0, 4]"), {1, 0, 0});
  expect_near(normal_of(capsule, "[0, -2, 0]"), {0, -1, 0});
  std::string e = error_of(capsule, "[3, 0, 1]");
  EXPECT_NE(e.find("it is 1 from the surface point (2, 0, 1)"), std::string::npos) << e;
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

// The cone and the capsule are closed too: their normal rule is inward-normal, so the opposite
// of (0, 0.8, 0.6) (the cone's side at (1, 1.5, 2), worked in normals.json) and of (0, 0, −1)
// (the capsule's side at (1, 0, −5)) keeps half the credit; a disk's opposite normal does not.
TEST(NormalKind, InwardNormalOfTheConeAndCapsuleIsNamed) {
  Problem cone = testing::problem(R"({"id": "n", "kind": "normal", "object": {"type": "cone",
    "base": [1, 0, 0], "radius": 3, "height": 4}, "point": [1, 1.5, 2]})");
  GradeResult right = grade_answer(cone, nlohmann::json::parse(R"({"normal": [0, 4, 3]})"));
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
  GradeResult inward = grade_answer(cone, nlohmann::json::parse(R"({"normal": [0, -4, -3]})"));
  EXPECT_TRUE(inward.has_mistake("inward-normal"));
  EXPECT_DOUBLE_EQ(inward.score, 0.5 * inward.max_score);
  Problem capsule = testing::problem(R"({"id": "n", "kind": "normal", "object": {"type":
    "capsule", "a": [0, 0, 0], "b": [4, 0, 0], "radius": 5}, "point": [1, 0, -5]})");
  inward = grade_answer(capsule, nlohmann::json::parse(R"({"normal": [0, 0, 1]})"));
  EXPECT_TRUE(inward.has_mistake("inward-normal"));
  Problem disk = testing::problem(R"({"id": "n", "kind": "normal", "object": {"type": "disk",
    "center": [0, 0, 5], "normal": [0, 0, -2], "radius": 2}, "point": [1, 1, 5]})");
  GradeResult flipped = grade_answer(disk, nlohmann::json::parse(R"({"normal": [0, 0, 1]})"));
  EXPECT_FALSE(flipped.has_mistake("inward-normal"));
  EXPECT_DOUBLE_EQ(flipped.score, 0);
}

}  // namespace
}  // namespace raygrade
