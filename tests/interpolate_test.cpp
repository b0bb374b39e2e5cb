// The interpolate kind against values worked by hand: barycentric weights, the blended and
// renormalised vertex normals, texture coordinates; points off the triangle as errors; the
// grading of a normal left unnormalised; the answer form.
#include "kinds/interpolate.h"

#include <gtest/gtest.h>

#include "assignments/answer_form.h"
#include "core/error.h"
#include "grading/grade.h"
#include "test_util.h"

namespace raygrade {
// Named rather than anonymous: a unity batch of tests shares one anonymous namespace.
namespace interpolate_test {

// A = (0, 0, 0), B = (4, 0, 0), C = (0, 4, 0); the vertex normals lean out of the corners.
const std::string kTriangle = R"("vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]],
  "normals": [[0, 0, 1], [0.6, 0, 0.8], [0, 0.6, 0.8]])";

Problem interpolate(const std::string& point, const std::string& more = "",
                    const std::string& triangle = kTriangle) {
  return testing::problem(R"({"id": "i", "kind": "interpolate", )" + triangle + R"(, "point": )" +
                          point + more + "}");
}

void expect_vector(const nlohmann::json& got, double x, double y, double z) {
  ASSERT_TRUE(got.is_array()) << got;
  EXPECT_NEAR(got[0].get<double>(), x, 1e-12) << got;
  EXPECT_NEAR(got[1].get<double>(), y, 1e-12) << got;
  EXPECT_NEAR(got[2].get<double>(), z, 1e-12) << got;
}

// P = (1, 1, 0) = A + ¼(B − A) + ¼(C − A): w = (½, ¼, ¼). ½(0, 0, 1) + ¼(0.6, 0, 0.8) +
// ¼(0, 0.6, 0.8) = (0.15, 0.15, 0.9), of length √0.855. With (0.5, 0), (1, 0.5), (0, 1) at
// the corners: u = ½·0.5 + ¼·1 = 0.5, v = ¼·0.5 + ¼·1 = 0.375.
TEST(InterpolateKind, WeightsNormalAndTexcoordByHand) {
  Problem p = interpolate("[1, 1, 0]", R"(, "texcoords": [[0.5, 0], [1, 0.5], [0, 1]])");
  nlohmann::json a = p.task->answer();
  expect_vector(a["barycentric"], 0.5, 0.25, 0.25);
  double len = std::sqrt(0.855);
  expect_vector(a["normal"], 0.15 / len, 0.15 / len, 0.9 / len);
  EXPECT_NEAR(a["u"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(a["v"].get<double>(), 0.375, 1e-12);
}

// At a corner the weights are that corner's alone and the normal is its own; halfway along
// B–C, (2, 2, 0), the weights are (0, ½, ½) and the normal (0.3, 0.3, 0.8)/√0.82. Without
// texture coordinates the answer has no u or v.
TEST(InterpolateKind, CornersAndEdges) {
  nlohmann::json a = interpolate("[4, 0, 0]").task->answer();
  expect_vector(a["barycentric"], 0, 1, 0);
  expect_vector(a["normal"], 0.6, 0, 0.8);
  EXPECT_FALSE(a.contains("u"));
  a = interpolate("[2, 2, 0]").task->answer();
  expect_vector(a["barycentric"], 0, 0.5, 0.5);
  double len = std::sqrt(0.82);
  expect_vector(a["normal"], 0.3 / len, 0.3 / len, 0.8 / len);
}

// Vertex normals given longer than 1 are made unit before they are blended: (0, 0, 5) and
// (3, 0, 4) and (0, 6, 8) are the same normals as above, and so is the answer.
TEST(InterpolateKind, VertexNormalsAreMadeUnitFirst) {
  nlohmann::json a = interpolate("[1, 1, 0]", "",
                                 R"("vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]],
                                    "normals": [[0, 0, 5], [3, 0, 4], [0, 6, 8]])")
                         .task->answer();
  double len = std::sqrt(0.855);
  expect_vector(a["normal"], 0.15 / len, 0.15 / len, 0.9 / len);
}

std::string error_of(const std::string& point, const std::string& more = "",
                     const std::string& triangle = kTriangle) {
  try {
    interpolate(point, more, triangle);
  } catch (const Error& e) {
    return e.diagnostic().path + ": " + e.diagnostic().message;
  }
  return "no error";
}

// (1, 1, 0.5) is 0.5 above the plane z = 0; (3, 3, 0) is past the edge B–C, where
// w_a = 1 − ¾ − ¾ = −½.
TEST(InterpolateKind, PointOffTheTriangleIsAnError) {
  std::string e = error_of("[1, 1, 0.5]");
  EXPECT_NE(e.find("/point: the point is 0.5 off the triangle's plane"), std::string::npos) << e;
  e = error_of("[3, 3, 0]");
  EXPECT_NE(e.find("/point: the point is outside the triangle: its weight w_a is -0.5"),
            std::string::npos)
      << e;
  e = error_of("[1, 1, 0]", "",
               R"("vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]],
                  "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1]])");
  EXPECT_NE(e.find("/vertices: the three vertices lie on one line"), std::string::npos) << e;
  e = error_of("[1, 1, 0]", R"(, "texcoords": [[0, 0], [1, 0, 0], [0, 1]])");
  EXPECT_NE(e.find("/texcoords/1: a texture coordinate is two numbers"), std::string::npos) << e;
  e = error_of("[1, 1, 0]", "", R"("vertices": [[0, 0, 0], [4, 0, 0]],
                                   "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 1]])");
  EXPECT_NE(e.find("/vertices: a triangle has 3 vertices, not 2"), std::string::npos) << e;
}

std::string code_of(const std::string& point, const std::string& triangle) {
  try {
    interpolate(point, "", triangle);
  } catch (const Error& e) {
    return e.diagnostic().code + " at " + e.diagnostic().path;
  }
  return "no error";
}

// The normals (1, 0, 0) at A and (−1, 0, 0) at B cancel halfway along A–B, at (1, 0, 0),
// where w = (½, ½, 0): the blend is the zero vector and has no direction. Nearly so,
// (1, 1e-17, 0) at B, leaves (0, 5e-18, 0), a direction decided by rounding alone. A vertex
// normal of length 1e-200 is not zero, but its length squared, 1e-400, underflows to 0.
TEST(InterpolateKind, AnUndefinedNormalIsAnError) {
  const std::string opposite = R"("vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]],
                                  "normals": [[1, 0, 0], [-1, 0, 0], [0, 0, 1]])";
  EXPECT_EQ(code_of("[1, 0, 0]", opposite), "undefined-normal at /normals");
  const std::string nearly = R"("vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]],
                                "normals": [[1, 0, 0], [-1, 1e-17, 0], [0, 0, 1]])";
  EXPECT_EQ(code_of("[1, 0, 0]", nearly), "undefined-normal at /normals");
  // Away from the cancelling point the same normals blend to a direction: at (0.5, 0, 0),
  // w = (¾, ¼, 0) and the blend is (½, 0, 0).
  expect_vector(interpolate("[0.5, 0, 0]", "", opposite).task->answer()["normal"], 1, 0, 0);
  const std::string tiny = R"("vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0]],
                             "normals": [[0, 0, 1e-200], [0, 0, 1], [0, 0, 1]])";
  EXPECT_EQ(code_of("[0.5, 0.5, 0]", tiny), "undefined-normal at /normals/0");
}

// The blend (0.15, 0.15, 0.9) left unnormalised points the right way at length √0.855 ≈ 0.9247:
// no credit for the normal, which is asked as a unit vector, and the feedback says so.
TEST(InterpolateKind, GradingAnUnnormalisedNormal) {
  Problem p = interpolate("[1, 1, 0]");
  double len = std::sqrt(0.855);
  GradeResult right = grade_answer(
      p, {{"normal", {0.15 / len, 0.15 / len, 0.9 / len}}, {"barycentric", {0.5, 0.25, 0.25}}});
  EXPECT_DOUBLE_EQ(right.score, 3);
  GradeResult blend =
      grade_answer(p, {{"normal", {0.15, 0.15, 0.9}}, {"barycentric", {0.5, 0.25, 0.25}}});
  EXPECT_DOUBLE_EQ(blend.score, 1);
  const PartResult* normal = testing::part(blend, "normal");
  ASSERT_NE(normal, nullptr);
  ASSERT_FALSE(normal->feedback.empty());
  EXPECT_NE(normal->feedback[0].find("has length 0.9247"), std::string::npos)
      << normal->feedback[0];
  // The weights in the wrong order, (¼, ¼, ½): the barycentric part is wrong.
  GradeResult swapped = grade_answer(
      p, {{"normal", {0.15 / len, 0.15 / len, 0.9 / len}}, {"barycentric", {0.25, 0.25, 0.5}}});
  EXPECT_DOUBLE_EQ(swapped.score, 2);
}

// The form asks for what carries points: the normal and the weights by default, u and v when
// the problem gives them points.
TEST(InterpolateKind, AnswerFormAsksWhatCarriesPoints) {
  auto keys = [](const nlohmann::json& form) {
    std::vector<std::string> out;
    for (const auto& f : form["fields"]) out.push_back(f["key"]);
    return out;
  };
  EXPECT_EQ(keys(answer_form(interpolate("[1, 1, 0]"))),
            (std::vector<std::string>{"normal", "barycentric"}));
  EXPECT_EQ(
      keys(answer_form(interpolate("[1, 1, 0]", R"(, "texcoords": [[0.5, 0], [1, 0.5], [0, 1]],
                               "points": {"normal": 2, "barycentric": 1, "u": 1, "v": 1})"))),
      (std::vector<std::string>{"normal", "barycentric", "u", "v"}));
}

}  // namespace interpolate_test
}  // namespace raygrade
