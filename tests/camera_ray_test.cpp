// camera-ray: seed 004's formula d_r = f·d + x_diff·(d × u) + y_diff·u in both conventions.
#include "kinds/camera_ray.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace raygrade {
namespace {

// Eye at the origin looking down −z with up +y: d × u = (0,0,−1) × (0,1,0) = (1, 0, 0).
// 640 × 480 pixels, focal length 1.
const Camera kCam{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1, 640, 480};

// Corner (seed 004): pixel (0, 0) has x_diff = −320, y_diff = −240: (−320, −240, −1).
TEST(CameraRay, CornerConventionLowerLeftPixel) {
  EXPECT_EQ(camera_ray_direction(kCam, 0, 0, PixelConvention::kCorner), Vec3d(-320, -240, -1));
  EXPECT_EQ(camera_ray_direction(kCam, 320, 240, PixelConvention::kCorner), Vec3d(0, 0, -1));
}

// Centre: half a pixel more: x_diff = −319.5, y_diff = −239.5.
TEST(CameraRay, CenterConventionAddsHalfAPixel) {
  EXPECT_EQ(camera_ray_direction(kCam, 0, 0, PixelConvention::kCenter), Vec3d(-319.5, -239.5, -1));
  EXPECT_EQ(camera_ray_direction(kCam, 639, 479, PixelConvention::kCenter),
            Vec3d(319.5, 239.5, -1));
}

// A focal length of 2 doubles only the f·d term.
TEST(CameraRay, FocalLengthScalesTheViewingDirection) {
  Camera c = kCam;
  c.focal_length = 2;
  EXPECT_EQ(camera_ray_direction(c, 320, 240, PixelConvention::kCorner), Vec3d(0, 0, -2));
}

constexpr const char* kProblem = R"({"id": "c", "kind": "camera-ray",
  "camera": {"eye": [1, 2, 3], "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 1,
             "resolution": [4, 2]},
  "pixel": [0, 0] CONVENTION})";

nlohmann::json answer(const std::string& convention) {
  std::string text = kProblem;
  text.replace(text.find("CONVENTION"), 10, convention);
  return testing::problem(text).task->answer();
}

// Through the problem format: 4 × 2 pixels, pixel (0, 0). Corner: x_diff = −2, y_diff = −1,
// d_r = (−2, −1, −1). Centre (the default): x_diff = −1.5, y_diff = −0.5.
TEST(CameraRay, ProblemNamesTheConventionAndDefaultsToCenter) {
  auto corner = answer(R"(, "convention": "corner")");
  EXPECT_EQ(corner["ray"]["origin"], nlohmann::json::array({1.0, 2.0, 3.0}));
  EXPECT_EQ(corner["ray"]["direction"], nlohmann::json::array({-2.0, -1.0, -1.0}));
  auto center = answer(R"(, "convention": "center")");
  EXPECT_EQ(center["ray"]["direction"], nlohmann::json::array({-1.5, -0.5, -1.0}));
  EXPECT_EQ(answer(""), center);
}

TEST(CameraRay, UnknownConventionAndParallelUpAreRejected) {
  EXPECT_THROW(answer(R"(, "convention": "middle")"), Error);
  EXPECT_THROW(testing::problem(R"({"id": "c", "kind": "camera-ray",
  "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 0, 2], "focal_length": 1,
             "resolution": [4, 2]}, "pixel": [0, 0]})"),
               Error);
}

}  // namespace
}  // namespace raygrade
