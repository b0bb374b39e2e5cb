// Kind `view-ray`: the ray through a pixel of a look-at camera as Shirley and Marschner teach
// it: the basis u, v, w from the eye, the view direction (or a target) and up; the image plane
// by its bounds l, r, b, t or by a field of view; perspective or orthographic; the pixel's
// origin (top-left or bottom-left) and centre convention named in the problem.
#pragma once

#include "kinds/camera_ray.h"
#include "problems/kind.h"
#include "problems/problem.h"

namespace raygrade {

// The kind `view-ray` (kinds/kind.h).
struct ViewRayKind {
  static constexpr std::string_view kName = "view-ray";
  static constexpr std::string_view kSummary =
      "the ray through a pixel of a look-at camera: u, v, w, the image plane (bounds or field "
      "of view), perspective or orthographic";
  static constexpr GraderFamily kGrader = GraderFamily::kFields;
  static std::vector<std::string> keys() { return {"camera", "pixel", "convention"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

enum class Projection { kPerspective, kOrthographic };
enum class PixelOrigin { kBottomLeft, kTopLeft };

struct ViewCamera {
  Projection projection = Projection::kPerspective;
  Vec3d eye, view, up;  // view: the direction the camera looks (target − eye for a look-at)
  std::optional<Vec3d> target;
  bool left_handed = false;   // u = w × up instead of up × w (The Ray Tracer Challenge's axes)
  std::optional<double> fov;  // degrees, along fov_axis
  bool fov_vertical = false;
  double focal_length = 1;  // d: the image plane's distance along −w
  double l = 0, r = 0, b = 0, t = 0;
  int nx = 0, ny = 0;
  PixelOrigin origin = PixelOrigin::kBottomLeft;
  Vec3d u, v, w;
};

// A `camera` is a look-at camera when it has any of these keys (the focal-length camera of
// seed 004 has none of them).
bool is_view_camera(const Cursor& camera);
// Reads a look-at `camera`; the bounds come from `bounds` or from `fov`.
ViewCamera read_view_camera(const Cursor& camera);
// Reads a `pixel` [i, j] and checks it lies in the resolution (an error at /pixel/0 or /1).
std::pair<double, double> read_pixel(const Cursor& problem, int nx, int ny);
// The ray through pixel (i, j).
Ray view_ray(const ViewCamera& cam, double i, double j, PixelConvention convention);
// The camera and its pixel (i, j) as the 3D view draws them (problems/scene_givens.h).
GivenCamera given_camera(const ViewCamera& cam, double i, double j);

class ViewRayTask final : public Task {
 public:
  ViewRayTask(ViewCamera cam, double i, double j, PixelConvention convention)
      : cam_(cam), i_(i), j_(j), convention_(convention) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return ViewRayKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"uvw"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

 private:
  ViewCamera cam_;
  double i_, j_;
  PixelConvention convention_;
};

}  // namespace raygrade
