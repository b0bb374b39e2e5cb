// The look-at camera: basis, image plane, pixel conventions and projections against rays worked
// by hand, and a pixel outside the resolution as an error at its path.
#include "kinds/view_ray.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "grading/grade.h"
#include "kinds/ray_tree.h"
#include "test_util.h"

namespace raygrade {
namespace {

Problem view(const std::string& camera, const std::string& pixel,
             const std::string& convention = "center") {
  return testing::problem(R"({"id": "v", "kind": "view-ray", "camera": )" + camera +
                          R"(, "pixel": )" + pixel + R"(, "convention": ")" + convention + "\"}");
}

Vec3d vec(const nlohmann::json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

void expect_vec(const nlohmann::json& j, const Vec3d& want) {
  Vec3d got = vec(j);
  EXPECT_NEAR(got.x, want.x, 1e-14) << j;
  EXPECT_NEAR(got.y, want.y, 1e-14) << j;
  EXPECT_NEAR(got.z, want.z, 1e-14) << j;
}

const char* kBounds = R"({"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0],
  "bounds": [-2, 2, -1.5, 1.5], "resolution": [8, 6], "pixel_origin": ")";

// Pixels 0.5 square; pixel (2, 1): u_s = −2 + 0.5·2.5 = −0.75; v_s = −1.5 + 0.5·1.5 = −0.75
// from the bottom, 1.5 − 0.75 = 0.75 from the top; through the corner u_s = −1, v_s = −1.
TEST(ViewRay, PixelOriginAndCentreConventions) {
  expect_vec(view(std::string(kBounds) + "bottom-left\"}", "[2, 1]").task->answer()["direction"],
             {-0.75, -0.75, -1});
  expect_vec(view(std::string(kBounds) + "top-left\"}", "[2, 1]").task->answer()["direction"],
             {-0.75, 0.75, -1});
  expect_vec(
      view(std::string(kBounds) + "bottom-left\"}", "[2, 1]", "corner").task->answer()["direction"],
      {-1, -1, -1});
}

// From (4, 0, 0) toward the origin: w = (1, 0, 0), u = up × w = (0, 0, −1), v = (0, 1, 0);
// a vertical fov of 90° over 4 × 4 gives t = r = 1.
TEST(ViewRay, LookAtBasisAndFieldOfView) {
  Problem p = view(R"({"eye": [4, 0, 0], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 90,
    "fov_axis": "vertical", "resolution": [4, 4], "pixel_origin": "bottom-left"})",
                   "[3, 0]", "corner");
  nlohmann::json a = p.task->answer();
  expect_vec(a["w"], {1, 0, 0});
  expect_vec(a["u"], {0, 0, -1});
  expect_vec(a["v"], {0, 1, 0});
  EXPECT_NEAR(a["t"].get<double>(), 1, 1e-15);
  EXPECT_NEAR(a["pixel_width"].get<double>(), 0.5, 1e-15);
  expect_vec(a["direction"], {-1, -1, -0.5});
}

// A horizontal fov of 90° over 200 × 100: r = 1, t = 0.5, pixels 0.01.
TEST(ViewRay, HorizontalFieldOfViewGivesThePixelSize) {
  Problem p = view(R"({"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 90,
    "fov_axis": "horizontal", "resolution": [200, 100], "pixel_origin": "top-left"})",
                   "[0, 0]");
  nlohmann::json a = p.task->answer();
  EXPECT_NEAR(a["pixel_width"].get<double>(), 0.01, 1e-15);
  EXPECT_NEAR(a["pixel_height"].get<double>(), 0.01, 1e-15);
  expect_vec(a["direction"], {-0.995, 0.495, -1});
}

// Pixel (7, 5) of 8 × 6 unit pixels: u_s = 3.5, v_s = 2.5; the ray starts there, along −w.
TEST(ViewRay, OrthographicRayStartsAtThePixel) {
  Problem p = view(R"({"projection": "orthographic", "eye": [0, 0, 10], "direction": [0, 0, -1],
    "up": [0, 1, 0], "bounds": [-4, 4, -3, 3], "resolution": [8, 6],
    "pixel_origin": "bottom-left"})",
                   "[7, 5]");
  nlohmann::json a = p.task->answer();
  expect_vec(a["origin"], {3.5, 2.5, 10});
  expect_vec(a["direction"], {0, 0, -1});
  GradeResult right = grade_answer(
      p, nlohmann::json::parse(R"({"origin": [3.5, 2.5, 10], "direction": [0, 0, -2]})"));
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
  GradeResult eye =
      grade_answer(p, nlohmann::json::parse(R"({"origin": [0, 0, 10], "direction": [0, 0, -1]})"));
  EXPECT_DOUBLE_EQ(eye.score, eye.max_score / 2);
}

std::string error_of(const std::string& text) {
  try {
    testing::problem(text);
  } catch (const Error& e) {
    return e.diagnostic().path + ": " + e.diagnostic().message;
  }
  return "no error";
}

TEST(ViewRay, PixelOutsideTheResolutionIsAnErrorAtItsPath) {
  std::string camera = std::string(kBounds) + "top-left\"}";
  std::string e = error_of(R"({"id": "v", "kind": "view-ray", "convention": "center",
    "camera": )" + camera + R"(, "pixel": [8, 0]})");
  EXPECT_EQ(e, "/pixel/0: pixel column 8 is outside the resolution: 0 ≤ i < 8");
  e = error_of(R"({"id": "v", "kind": "view-ray", "convention": "center", "camera": )" + camera +
               R"(, "pixel": [0, -1]})");
  EXPECT_EQ(e, "/pixel/1: pixel row -1 is outside the resolution: 0 ≤ j < 6");
  // The focal-length camera checks its pixels too.
  e = error_of(R"({"id": "c", "kind": "camera-ray", "camera": {"eye": [0, 0, 0],
    "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 1, "resolution": [4, 4]},
    "pixel": [1, 4]})");
  EXPECT_EQ(e, "/pixel/1: pixel row 4 is outside the resolution: 0 ≤ j < 4");
}

TEST(ViewRay, ConventionsMustBeNamed) {
  std::string e = error_of(R"({"id": "v", "kind": "view-ray", "convention": "center",
    "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0],
    "bounds": [-1, 1, -1, 1], "resolution": [2, 2]}, "pixel": [0, 0]})");
  EXPECT_NE(e.find("pixel_origin"), std::string::npos) << e;
  e = error_of(R"({"id": "v", "kind": "view-ray", "camera": )" + std::string(kBounds) +
               R"(top-left"}, "pixel": [0, 0]})");
  EXPECT_NE(e.find("convention"), std::string::npos) << e;
}

// A ray tree's primary ray from a look-at camera: pixel (2, 1) of the bounds camera, bottom
// left, meets the plane z = −4 at t = 4, at (−3, −3, −4).
TEST(ViewRay, RayTreeTakesALookAtCamera) {
  Problem p = testing::problem(R"({"id": "r", "kind": "ray-tree", "ask": "hit",
    "camera": )" + std::string(kBounds) +
                               R"(bottom-left"}, "pixel": [2, 1], "convention": "center",
    "scene": {"objects": [{"name": "wall", "type": "plane", "point": [0, 0, -4],
      "normal": [0, 0, 1]}]}})");
  nlohmann::json a = p.task->answer();
  EXPECT_NEAR(a["hits"][0]["t"].get<double>(), 4, 1e-14);
  expect_vec(a["hits"][0]["point"], {-3, -3, -4});
}

}  // namespace
}  // namespace raygrade
