// Kind `camera-ray`: the primary ray a perspective camera shoots through a pixel (seed 004).
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"

namespace raygrade {

// The kind `camera-ray` (kinds/kind.h).
struct CameraRayKind {
  static constexpr std::string_view kName = "camera-ray";
  static constexpr std::string_view kSummary =
      "the ray a perspective camera shoots through a pixel";
  static constexpr GraderFamily kGrader = GraderFamily::kCamera;
  static std::vector<std::string> keys() { return {"camera", "pixel", "convention"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

// Where a pixel's ray passes. kCorner is seed 004's convention: offsets x − resX/2, so the
// ray of pixel (x, y) passes through the pixel's lower-left corner. kCenter adds half a pixel
// and passes through its centre. Pixel (0, 0) is at the lower left in both.
enum class PixelConvention { kCenter, kCorner };

struct Camera {
  Vec3d eye;
  Vec3d direction;  // the viewing direction d
  Vec3d up;         // u
  double focal_length = 1;
  int res_x = 0, res_y = 0;
};

// Reads a `camera` {eye, direction, up, focal_length, resolution}.
Camera read_camera(const Cursor& camera);
// Reads a problem's `convention` ("center", the default, or "corner").
PixelConvention read_pixel_convention(const Cursor& problem);

// d_r = f·d + x_diff·(d × u) + y_diff·u.
Vec3d camera_ray_direction(const Camera& cam, double x, double y, PixelConvention convention);

// The camera and its pixel (x, y) as the 3D view draws them (problems/scene_givens.h): the image
// plane is resX by resY pixels of size 1, at distance f along d.
GivenCamera given_camera(const Camera& cam, double x, double y);

class CameraRayTask final : public Task {
 public:
  CameraRayTask(Camera cam, double x, double y, PixelConvention convention)
      : cam_(cam), x_(x), y_(y), convention_(convention) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return CameraRayKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"image-plane"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

  const Camera& camera() const { return cam_; }
  PixelConvention convention() const { return convention_; }
  double pixel_x() const { return x_; }
  double pixel_y() const { return y_; }

 private:
  Camera cam_;
  double x_, y_;
  PixelConvention convention_;
};

}  // namespace raygrade
