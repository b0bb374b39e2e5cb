// Transformed objects: rays taken into object space, t kept, normals by the inverse transpose;
// and spawned rays that never re-hit the surface they leave.
#include "shapes/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scenes/offset.h"
#include "scenes/optics.h"
#include "scenes/scene.h"
#include "test_util.h"

namespace raygrade {
namespace {

Scene scene_of(const std::string& objects) {
  auto f = testing::json_file(R"({"objects": )" + objects + "}");
  return read_scene(Cursor(f));
}

// The unit sphere scaled by (2, 1, 1) and moved to (10, 0, 0) is the ellipsoid
// ((x−10)/2)² + y² + z² = 1; the ray from the origin along x meets it at x = 8.
TEST(Transform, ScaledSphereKeepsTheWorldT) {
  Scene s = scene_of(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "transform": [{"scale": [2, 1, 1]}, {"translate": [10, 0, 0]}]}])");
  SceneHit h = nearest_hit(s, Ray{{0, 0, 0}, {1, 0, 0}, 0, kInfinity});
  ASSERT_EQ(h.object, 0);
  EXPECT_DOUBLE_EQ(h.hit.t, 8);
  EXPECT_EQ(h.hit.point, Vec3d(8, 0, 0));
  EXPECT_NEAR(h.hit.normal.x, -1, 1e-15);
}

// On the ellipsoid x²/4 + y² = 1 at (√2, 1/√2) the gradient (x/2, 2y) is (1/√2, √2), so the
// unit normal is (1, 2)/√5, not the scaled sphere normal.
TEST(Transform, NormalsGoBackByTheInverseTranspose) {
  Scene s = scene_of(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1,
      "transform": [{"scale": [2, 1, 1]}]}])");
  double x = std::sqrt(2.0);
  SceneHit h = nearest_hit(s, Ray{{x, 5, 0}, {0, -1, 0}, 0, kInfinity});
  ASSERT_EQ(h.object, 0);
  EXPECT_NEAR(h.hit.t, 5 - 1 / std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(h.hit.normal.x, 1 / std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(h.hit.normal.y, 2 / std::sqrt(5.0), 1e-15);
}

// The cube [−1, 1]³ turned 45° about z has an edge at x = −√2 facing a ray along +x.
TEST(Transform, RotatedBoxShowsItsEdge) {
  Scene s = scene_of(R"([{"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1],
      "transform": [{"rotate": {"axis": [0, 0, 1], "degrees": 45}}]}])");
  SceneHit h = nearest_hit(s, Ray{{-10, 0, 0}, {1, 0, 0}, 0, kInfinity});
  ASSERT_EQ(h.object, 0);
  EXPECT_NEAR(h.hit.t, 10 - std::sqrt(2.0), 1e-14);
}

TEST(Transform, ZeroScaleIsAnError) {
  try {
    scene_of(R"([{"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "transform": [{"translate": [1, 0, 0]}, {"scale": [1, 0, 1]}]}])");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().path, "/objects/0/transform/1/scale");
  }
}

// Quarter turns about z: (x, y) → (−y, x) for 90°, so (1, 0, 0) goes to (0, 1, 0) exactly,
// and to (−1, 0, 0) after 180°, (0, −1, 0) after 270° and −90°. From cos(π/2) in double the
// zeros would be 6.1e-17.
TEST(Transform, QuarterTurnsAreExact) {
  auto turned = [](const char* degrees) {
    auto f = testing::json_file(
        fmt::format(R"([{{"rotate": {{"axis": [0, 0, 1], "degrees": {}}}}}])", degrees));
    return read_transform(Cursor(f)).to_world.point({1, 0, 0});
  };
  EXPECT_EQ(turned("90"), Vec3d(0, 1, 0));
  EXPECT_EQ(turned("180"), Vec3d(-1, 0, 0));
  EXPECT_EQ(turned("270"), Vec3d(0, -1, 0));
  EXPECT_EQ(turned("-90"), Vec3d(0, -1, 0));
  EXPECT_EQ(turned("450"), Vec3d(0, 1, 0));
}

TEST(Transform, ComposesInTheOrderWritten) {
  // Scale by 2 then translate by (1, 0, 0): the point (1, 0, 0) goes to (3, 0, 0); the other
  // order would give (4, 0, 0).
  auto f = testing::json_file(R"([{"scale": 2}, {"translate": [1, 0, 0]}])");
  Transform t = read_transform(Cursor(f));
  EXPECT_EQ(t.to_world.point({1, 0, 0}), Vec3d(3, 0, 0));
  EXPECT_EQ(t.to_object.point({3, 0, 0}), Vec3d(1, 0, 0));
}

// Reflections off the outside of a convex solid can never meet it again. From the offset
// origin none does, for thousands of rays on far, large and transformed objects; from the
// raw hit point (a fixed epsilon of 0) some re-hit their own surface, so the check can fail.
TEST(Offset, ReflectedRaysNeverRehitTheirConvexSurface) {
  Scene s = scene_of(R"([
      {"type": "sphere", "center": [1000.3, -2000.7, 3000.1], "radius": 977.7},
      {"type": "sphere", "center": [0, 0, 0], "radius": 1,
       "transform": [{"scale": [3, 0.5, 1.7]}, {"rotate": {"axis": [1, 2, 3], "degrees": 33}},
                     {"translate": [-400.1, 7.3, 9000.9]}]},
      {"type": "box", "min": [-0.3, -0.7, -0.2], "max": [0.9, 0.4, 1.3],
       "transform": [{"rotate": {"axis": [3, -1, 2], "degrees": 71}},
                     {"translate": [55.5, -77.7, 12.25]}]}])");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int rehit_raw = 0, rehit_offset = 0, hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const SceneObject& target = s.objects[i % 3];
    Vec3d aim = target.transform.identity()
                    ? target.shape->center()
                    : target.transform.to_world.point(target.shape->center());
    Vec3d origin = aim + Vec3d{u(rng), u(rng), u(rng)} * 5000.0;
    Vec3d jitter = Vec3d{u(rng), u(rng), u(rng)} * (target.shape->extent() * 0.8);
    Ray ray{origin, aim + jitter - origin, 0, kInfinity};
    SceneHit h = nearest_hit(s, ray);
    // Only hits from outside: from inside, a reflection meets the surface again by right.
    if (h.object != i % 3 || dot(ray.direction, h.hit.normal) >= 0) continue;
    ++hits;
    Vec3d n = h.hit.normal;
    Vec3d r = reflect(normalized(ray.direction), n);
    Ray raw{h.hit.point, r, 0, kInfinity};
    Ray off{offset_ray_origin(h.hit.point, h.point_error, n, r), r, 0, kInfinity};
    if (nearest_hit(s, raw).object == h.object) ++rehit_raw;
    if (nearest_hit(s, off).object == h.object) ++rehit_offset;
  }
  RecordProperty("hits", hits);
  RecordProperty("rehit_raw", rehit_raw);
  EXPECT_GT(hits, 1500);
  EXPECT_EQ(rehit_offset, 0);
  EXPECT_GT(rehit_raw, 0);
}

}  // namespace
}  // namespace raygrade
