// The camera-ray kind.
#include "kinds/camera_ray.h"

#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/part_names.h"
#include "kinds/view_ray.h"

namespace raygrade {

Vec3d camera_ray_direction(const Camera& cam, double x, double y, PixelConvention convention) {
  double shift = convention == PixelConvention::kCenter ? 0.5 : 0.0;
  double x_diff = x + shift - cam.res_x / 2.0;
  double y_diff = y + shift - cam.res_y / 2.0;
  return cam.focal_length * cam.direction + x_diff * cross(cam.direction, cam.up) + y_diff * cam.up;
}

GivenCamera given_camera(const Camera& cam, double x, double y) {
  Vec3d right = cross(cam.direction, cam.up);
  GivenCamera g;
  g.eye = cam.eye;
  g.look = cam.direction;
  g.plane_center = cam.eye + cam.focal_length * cam.direction;
  g.plane_half_x = (0.5 * cam.res_x) * right;
  g.plane_half_y = (0.5 * cam.res_y) * cam.up;
  g.pixel_center = cam.eye + camera_ray_direction(cam, x, y, PixelConvention::kCenter);
  g.pixel_half_x = 0.5 * right;
  g.pixel_half_y = 0.5 * cam.up;
  return g;
}

Camera read_camera(const Cursor& c) {
  c.allow_only({"eye", "direction", "up", "focal_length", "resolution"});
  Camera cam;
  cam.eye = c.at("eye").vec3();
  cam.direction = c.at("direction").nonzero_vec3();
  cam.up = c.at("up").nonzero_vec3();
  cam.focal_length = c.at("focal_length").positive_number();
  auto res = c.at("resolution").items();
  if (res.size() != 2) c.at("resolution").fail("expected [resX, resY]", "type");
  cam.res_x = res[0].integer();
  cam.res_y = res[1].integer();
  if (cam.res_x <= 0 || cam.res_y <= 0)
    c.at("resolution").fail("the resolution must be positive", "degenerate");
  if (length_squared(cross(cam.direction, cam.up)) == 0) {
    c.at("up").fail("the up vector is parallel to the viewing direction", "degenerate");
  }
  return cam;
}

PixelConvention read_pixel_convention(const Cursor& problem) {
  std::string conv = problem.string_or("convention", "center");
  if (conv != "center" && conv != "corner") {
    problem.at("convention")
        .fail(fmt::format("unknown convention '{}' (known: center, corner)", conv), "invalid");
  }
  return conv == "corner" ? PixelConvention::kCorner : PixelConvention::kCenter;
}

std::unique_ptr<Task> CameraRayTask::read(const Cursor& problem) {
  Camera cam = read_camera(problem.at("camera"));
  auto [x, y] = read_pixel(problem, cam.res_x, cam.res_y);
  return std::make_unique<CameraRayTask>(cam, x, y, read_pixel_convention(problem));
}

nlohmann::json CameraRayTask::answer() const {
  Vec3d d = camera_ray_direction(cam_, x_, y_, convention_);
  return {{"ray", {{"origin", vec_json(cam_.eye)}, {"direction", vec_json(d)}}},
          {"unit_direction", vec_json(normalized(d))}};
}

std::vector<SolutionPart> CameraRayTask::derive(std::string_view /*method*/,
                                                const Overrides* overrides) const {
  bool corner = convention_ == PixelConvention::kCorner;
  Deriver d("image-plane", "Camera ray through a pixel", overrides);
  E e = d.given("e", "e", cam_.eye, "the eye");
  E dir = d.given("d", "d", cam_.direction, "the viewing direction");
  E u = d.given("u", "u", cam_.up, "the up vector");
  E f = d.given("f", "f", cam_.focal_length, "the focal length");
  E rx = d.given("resX", "res_X", cam_.res_x);
  E ry = d.given("resY", "res_Y", cam_.res_y);
  E x = d.given("x", "x", x_, "the pixel's column (0 at the left)");
  E y = d.given("y", "y", y_, "the pixel's row (0 at the bottom)");
  d.step("v", "v", cross_written_out(dir, u),
         "the image plane's x direction, perpendicular to d and u");
  if (corner) {
    d.step("x_diff", "x_diff", x - rx / 2, "seed 004's convention: no half-pixel shift");
    d.step("y_diff", "y_diff", y - ry / 2);
  } else {
    d.step("x_diff", "x_diff", x + 0.5 - rx / 2, "through the pixel's centre: half a pixel more");
    d.step("y_diff", "y_diff", y + 0.5 - ry / 2);
  }
  Value dr = d.step("d_r", "d_r", f * dir + d.sym("x_diff") * d.sym("v") + d.sym("y_diff") * u,
                    "f·d reaches the image plane's centre; then move across and up");
  d.step("d_r_hat", "d_r_hat", d.sym("d_r") / norm(d.sym("d_r")), "the direction as a unit vector");
  d.conclude(Sentence(fmt::format("The ray through pixel ({}, {}) starts at the eye ",
                                  format_number(x_), format_number(y_)))
                 .value(cam_.eye)
                 .text(" with direction ")
                 .value(dr.vector)
                 .text(corner ? " (seed 004's convention: offsets from the pixel's corner)."
                              : " (through the pixel's centre)."));
  (void)e;
  return {SolutionPart{"", std::move(d).finish()}};
}

// The eye, the image plane (resX by resY pixels of size 1, at distance f along d), the pixel
// the ray passes through, and the ray itself, drawn a little past the image plane.
Sketch CameraRayTask::sketch() const {
  Sketch f;
  f.across = cam_.direction;
  f.across_name = "the viewing direction d";
  Vec3d v = cross(cam_.direction, cam_.up);
  Vec3d center = cam_.eye + cam_.focal_length * cam_.direction;
  double hx = cam_.res_x / 2.0, hy = cam_.res_y / 2.0;
  f.path({center - hx * v - hy * cam_.up, center + hx * v - hy * cam_.up,
          center + hx * v + hy * cam_.up, center - hx * v + hy * cam_.up},
         true, Ink::kGuide, "image plane");
  f.path({cam_.eye, center}, false, Ink::kGuide, "f·d");
  Vec3d dr = camera_ray_direction(cam_, x_, y_, convention_);
  f.arrow(cam_.eye, cam_.eye + 1.3 * dr, Ink::kRay);
  f.ray_is_answer = true;
  f.point(cam_.eye, Ink::kPoint, "eye");
  f.point(cam_.eye + dr, Ink::kHit,
          fmt::format("pixel ({}, {})", format_number(x_), format_number(y_)));
  return f;
}

std::optional<SceneGivens> CameraRayTask::scene_givens() const {
  SceneGivens g;
  g.camera = given_camera(cam_, x_, y_);
  return g;
}

std::unique_ptr<Task> CameraRayKind::read(const Cursor& problem) {
  return CameraRayTask::read(problem);
}

std::vector<PartSpec> CameraRayKind::parts() {
  using C = Comparison;
  return {{part_names::kRay,
           "the ray through the pixel: the eye and the direction (any positive multiple)", 1,
           C::kDirection},
          {part_names::kSteps, "the derivation's named steps", 0, C::kSteps}};
}

nlohmann::json CameraRayKind::answer_form(const Problem& /*p*/) {
  return form::fields(
      {form::field<field_types::Vector>("ray/origin", "The ray's origin"),
       form::field<field_types::Vector>("ray/direction", "The ray's direction"),
       form::field<field_types::Vector>("unit_direction", "The direction as a unit vector")});
}

std::string_view CameraRayKind::schema() {
  return R"json({
  "required": [
    "camera",
    "pixel"
  ],
  "properties": {
    "camera": {
      "$ref": "#/$defs/camera"
    },
    "pixel": {
      "$ref": "#/$defs/pixel"
    },
    "convention": {
      "enum": [
        "center",
        "corner"
      ],
      "default": "center"
    }
  }
})json";
}

}  // namespace raygrade
