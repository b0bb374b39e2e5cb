// The 3D view's data: drawn from what the problem's task answers (Task::scene_givens), checked
// against corners, points and arrows worked by hand.
#include "reports/scene_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_util.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

json point(double x, double y, double z) { return json::array({x, y, z}); }

void expect_near(const json& a, const Vec3d& b) {
  ASSERT_TRUE(a.is_array() && a.size() == 3) << a.dump();
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k].get<double>(), b[k], 1e-12) << a.dump();
}

// Eye (1, 2, 3) looking down −z with up +y, f = 1, 4 × 2 pixels: d × u = (1, 0, 0), so the
// image plane is centred at (1, 2, 2) with half-sides (2, 0, 0) and (0, 1, 0). Pixel (0, 0)'s
// centre ray d = (−1.5, −0.5, −1) meets it at (−0.5, 1.5, 2), the centre of a unit square,
// though the problem follows the corner convention.
TEST(SceneView, CameraIsDrawnFromTheTaskNotFromTheProblemAsWritten) {
  Problem p = testing::problem(R"({"id": "c", "kind": "camera-ray",
    "camera": {"eye": [1, 2, 3], "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 1,
               "resolution": [4, 2]},
    "pixel": [0, 0], "convention": "corner"})");
  // The view reads nothing of the problem as written.
  p.source = json();
  std::optional<SceneView> view = scene_view(p, true);
  ASSERT_TRUE(view);
  const json& camera = view->data["camera"];
  EXPECT_EQ(camera["eye"], point(1, 2, 3));
  EXPECT_EQ(camera["look"], point(0, 0, -1));
  EXPECT_EQ(camera["orthographic"], false);
  EXPECT_EQ(camera["corners"],
            json::array({point(-1, 1, 2), point(3, 1, 2), point(3, 3, 2), point(-1, 3, 2)}));
  EXPECT_EQ(camera["pixel"],
            json::array({point(-1, 1, 2), point(0, 1, 2), point(0, 2, 2), point(-1, 2, 2)}));
  // A page of givens leaves out where the pixel lies.
  std::optional<SceneView> givens = scene_view(p, false);
  ASSERT_TRUE(givens);
  EXPECT_FALSE(givens->data["camera"].contains("pixel"));
}

// Fresnel by an angle of 30°: the surface y = 0 through P at the origin, its normal (0, 1, 0)
// drawn half a unit long (nothing farther than 1 is given), and the incoming direction
// (sin 30°, −cos 30°, 0) arriving at P from 0.8 back along it.
TEST(SceneView, FresnelByAngleDrawsTheSurfaceYZero) {
  Problem p = testing::problem(R"({"id": "f", "kind": "fresnel", "n1": 1, "n2": 1.5,
    "angle": 30})");
  std::optional<SceneView> view = scene_view(p, false);
  ASSERT_TRUE(view);
  const json& d = view->data;
  ASSERT_EQ(d["points"].size(), 1u);
  EXPECT_EQ(d["points"][0]["label"], "P");
  EXPECT_EQ(d["points"][0]["at"], point(0, 0, 0));
  ASSERT_EQ(d["arrows"].size(), 2u);
  EXPECT_EQ(d["arrows"][0]["role"], "normal");
  expect_near(d["arrows"][0]["to"], {0, 0.5, 0});
  EXPECT_EQ(d["arrows"][1]["role"], "ray");
  expect_near(d["arrows"][1]["from"], {-0.4, 0.4 * std::sqrt(3.0), 0});
  EXPECT_EQ(d["arrows"][1]["to"], point(0, 0, 0));
  EXPECT_EQ(d["objects"][0]["label"], "surface");
}

// A shade problem's lights are the kind's: a light without a name is L1, as the answer's rows
// name it, and the size of the drawing is the distance to the farthest of eye and lights (5 to
// the light at (3, 4, 0)): the surface's disk has radius 0.6 · 5 = 3.
TEST(SceneView, ShadeDrawsTheKindsLightsAndEye) {
  Problem p = testing::problem(R"({"id": "s", "kind": "shade",
    "point": [0, 0, 0], "normal": [0, 2, 0], "eye": [0, 1, 0],
    "material": {"ambient": 0.1, "diffuse": 0.6, "specular": 0.3, "shininess": 10},
    "lights": [{"position": [3, 4, 0]}]})");
  std::optional<SceneView> view = scene_view(p, false);
  ASSERT_TRUE(view);
  const json& d = view->data;
  ASSERT_EQ(d["lights"].size(), 1u);
  EXPECT_EQ(d["lights"][0]["label"], "L1");
  EXPECT_EQ(d["lights"][0]["position"], point(3, 4, 0));
  ASSERT_EQ(d["points"].size(), 2u);
  EXPECT_EQ(d["points"][1]["label"], "eye");
  EXPECT_EQ(d["objects"][0]["shape"]["radius"], 3.0);
  expect_near(d["arrows"][0]["to"], {0, 2.5, 0});
  EXPECT_NE(view->description.find("the light L1"), std::string::npos) << view->description;
}

}  // namespace
}  // namespace raygrade
