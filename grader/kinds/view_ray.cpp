// The view-ray kind: Shirley and Marschner's camera.
#include "kinds/view_ray.h"

#include <cmath>
#include <numbers>

#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/part_names.h"

namespace raygrade {
namespace {

const std::vector<std::string> kViewKeys = {"projection", "target", "handedness",  "fov",
                                            "fov_axis",   "bounds", "pixel_origin"};

// The basis: w points back from the view direction, u to the image's right, v up in it.
void make_basis(ViewCamera& c, const Cursor& camera) {
  c.w = -normalized(c.view);
  Vec3d side = c.left_handed ? cross(c.w, c.up) : cross(c.up, c.w);
  if (length_squared(side) == 0) {
    camera.at("up").fail("the up vector is parallel to the viewing direction", "degenerate");
  }
  c.u = normalized(side);
  c.v = c.left_handed ? cross(c.u, c.w) : cross(c.w, c.u);
}

void read_bounds(ViewCamera& c, const Cursor& camera) {
  if (camera.has("fov") == camera.has("bounds")) {
    camera.fail("give the image plane either by its bounds [l, r, b, t] or by a fov", "invalid");
  }
  if (camera.has("bounds")) {
    auto b = camera.at("bounds").items();
    if (b.size() != 4) camera.at("bounds").fail("expected [l, r, b, t]", "type");
    c.l = b[0].number(), c.r = b[1].number(), c.b = b[2].number(), c.t = b[3].number();
    if (!(c.l < c.r) || !(c.b < c.t)) {
      camera.at("bounds").fail("the bounds need l < r and b < t", "degenerate");
    }
    return;
  }
  if (c.projection == Projection::kOrthographic) {
    camera.at("fov").fail("an orthographic camera has no field of view: give its bounds",
                          "invalid");
  }
  double fov = camera.at("fov").number();
  if (!(fov > 0 && fov < 180))
    camera.at("fov").fail("the fov is between 0 and 180 degrees", "range");
  if (!camera.has("fov_axis")) {
    camera.fail("a fov needs its fov_axis: \"horizontal\" or \"vertical\"", "missing-key");
  }
  std::string axis = camera.at("fov_axis").string();
  if (axis != "horizontal" && axis != "vertical") {
    camera.at("fov_axis").fail("expected \"horizontal\" or \"vertical\"", "invalid");
  }
  c.fov = fov;
  c.fov_vertical = axis == "vertical";
  // Square pixels: the other half-size follows from the resolution.
  double half = c.focal_length * std::tan(fov / 2 * std::numbers::pi / 180);
  double half_x = c.fov_vertical ? half * c.nx / c.ny : half;
  double half_y = c.fov_vertical ? half : half * c.ny / c.nx;
  c.l = -half_x, c.r = half_x, c.b = -half_y, c.t = half_y;
}

}  // namespace

bool is_view_camera(const Cursor& camera) {
  for (const auto& k : kViewKeys) {
    if (camera.has(k)) return true;
  }
  return false;
}

ViewCamera read_view_camera(const Cursor& camera) {
  std::vector<std::string> keys = kViewKeys;
  keys.insert(keys.end(), {"eye", "direction", "up", "focal_length", "resolution"});
  camera.allow_only(keys);
  ViewCamera c;
  std::string proj = camera.string_or("projection", "perspective");
  if (proj != "perspective" && proj != "orthographic") {
    camera.at("projection").fail("expected \"perspective\" or \"orthographic\"", "invalid");
  }
  c.projection = proj == "orthographic" ? Projection::kOrthographic : Projection::kPerspective;
  c.eye = camera.at("eye").vec3();
  if (camera.has("target") == camera.has("direction")) {
    camera.fail("give either a target to look at or a view direction", "invalid");
  }
  if (camera.has("target")) {
    c.target = camera.at("target").vec3();
    c.view = *c.target - c.eye;
    if (length_squared(c.view) == 0)
      camera.at("target").fail("the target is the eye", "degenerate");
  } else {
    c.view = camera.at("direction").nonzero_vec3();
  }
  c.up = camera.at("up").nonzero_vec3();
  std::string hand = camera.string_or("handedness", "right");
  if (hand != "right" && hand != "left") {
    camera.at("handedness").fail("expected \"right\" or \"left\"", "invalid");
  }
  c.left_handed = hand == "left";
  if (camera.has("focal_length")) c.focal_length = camera.at("focal_length").positive_number();
  auto res = camera.at("resolution").items();
  if (res.size() != 2) camera.at("resolution").fail("expected [nx, ny]", "type");
  c.nx = res[0].integer();
  c.ny = res[1].integer();
  if (c.nx <= 0 || c.ny <= 0)
    camera.at("resolution").fail("the resolution must be positive", "degenerate");
  if (!camera.has("pixel_origin")) {
    camera.fail("name the pixel origin: \"pixel_origin\": \"top-left\" or \"bottom-left\"",
                "missing-key");
  }
  std::string origin = camera.at("pixel_origin").string();
  if (origin != "top-left" && origin != "bottom-left") {
    camera.at("pixel_origin").fail("expected \"top-left\" or \"bottom-left\"", "invalid");
  }
  c.origin = origin == "top-left" ? PixelOrigin::kTopLeft : PixelOrigin::kBottomLeft;
  make_basis(c, camera);
  read_bounds(c, camera);
  return c;
}

std::pair<double, double> read_pixel(const Cursor& problem, int nx, int ny) {
  auto pixel = problem.at("pixel").items();
  if (pixel.size() != 2) problem.at("pixel").fail("expected [i, j]", "type");
  double i = pixel[0].number(), j = pixel[1].number();
  if (!(i >= 0 && i < nx)) {
    pixel[0].fail(
        fmt::format("pixel column {} is outside the resolution: 0 ≤ i < {}", format_number(i), nx),
        "range");
  }
  if (!(j >= 0 && j < ny)) {
    pixel[1].fail(
        fmt::format("pixel row {} is outside the resolution: 0 ≤ j < {}", format_number(j), ny),
        "range");
  }
  return {i, j};
}

namespace {

// The pixel's position (u_s, v_s) on the image plane.
std::pair<double, double> image_position(const ViewCamera& c, double i, double j,
                                         PixelConvention conv) {
  double s = conv == PixelConvention::kCenter ? 0.5 : 0.0;
  double us = c.l + (c.r - c.l) * (i + s) / c.nx;
  double vs = c.origin == PixelOrigin::kBottomLeft ? c.b + (c.t - c.b) * (j + s) / c.ny
                                                   : c.t - (c.t - c.b) * (j + s) / c.ny;
  return {us, vs};
}

}  // namespace

Ray view_ray(const ViewCamera& c, double i, double j, PixelConvention conv) {
  auto [us, vs] = image_position(c, i, j, conv);
  if (c.projection == Projection::kOrthographic) {
    return Ray{c.eye + us * c.u + vs * c.v, -c.w, 0, kInfinity};
  }
  return Ray{c.eye, -c.focal_length * c.w + us * c.u + vs * c.v, 0, kInfinity};
}

GivenCamera given_camera(const ViewCamera& cam, double i, double j) {
  GivenCamera g;
  g.eye = cam.eye;
  g.look = -cam.w;
  g.orthographic = cam.projection == Projection::kOrthographic;
  // The image plane: through the eye for an orthographic camera, at d along −w otherwise.
  Vec3d plane = g.orthographic ? cam.eye : cam.eye - cam.focal_length * cam.w;
  g.plane_center = plane + (0.5 * (cam.l + cam.r)) * cam.u + (0.5 * (cam.b + cam.t)) * cam.v;
  g.plane_half_x = (0.5 * (cam.r - cam.l)) * cam.u;
  g.plane_half_y = (0.5 * (cam.t - cam.b)) * cam.v;
  // Where the ray through the pixel's centre crosses the image plane.
  Ray through = view_ray(cam, i, j, PixelConvention::kCenter);
  g.pixel_center = through.origin;
  if (!g.orthographic) {
    g.pixel_center =
        through.origin + (cam.focal_length / dot(through.direction, -cam.w)) * through.direction;
  }
  g.pixel_half_x = (0.5 * (cam.r - cam.l) / cam.nx) * cam.u;
  g.pixel_half_y = (0.5 * (cam.t - cam.b) / cam.ny) * cam.v;
  return g;
}

std::unique_ptr<Task> ViewRayTask::read(const Cursor& problem) {
  ViewCamera cam = read_view_camera(problem.at("camera"));
  auto [i, j] = read_pixel(problem, cam.nx, cam.ny);
  if (!problem.has("convention")) {
    problem.fail("name the pixel-centre convention: \"convention\": \"center\" or \"corner\"",
                 "missing-key");
  }
  return std::make_unique<ViewRayTask>(cam, i, j, read_pixel_convention(problem));
}

nlohmann::json ViewRayTask::answer() const {
  Ray ray = view_ray(cam_, i_, j_, convention_);
  auto [us, vs] = image_position(cam_, i_, j_, convention_);
  return {{"origin", vec_json(ray.origin)},
          {"direction", vec_json(ray.direction)},
          {"unit_direction", vec_json(normalized(ray.direction))},
          {"u", vec_json(cam_.u)},
          {"v", vec_json(cam_.v)},
          {"w", vec_json(cam_.w)},
          {"l", cam_.l},
          {"r", cam_.r},
          {"b", cam_.b},
          {"t", cam_.t},
          {"pixel_width", (cam_.r - cam_.l) / cam_.nx},
          {"pixel_height", (cam_.t - cam_.b) / cam_.ny},
          {"u_s", us},
          {"v_s", vs}};
}

std::vector<SolutionPart> ViewRayTask::derive(std::string_view /*method*/,
                                              const Overrides* overrides) const {
  const ViewCamera& c = cam_;
  Deriver d("uvw", "The camera's basis, its image plane and the ray through the pixel", overrides);
  E e = d.given("e", "e", c.eye, "the eye");
  E view;
  if (c.target) {
    E target = d.given("target", "target", *c.target, "the point the camera looks at");
    d.step("view", "g", target - e, "the view direction: target − e");
    view = d.sym("view");
  } else {
    view = d.given("view", "g", c.view, "the view direction");
  }
  E up = d.given("up", "t_up", c.up, "the up vector");
  d.step("w", "w", -view / norm(view), "w points back, away from what the camera sees");
  if (c.left_handed) {
    d.step("u", "u", cross(d.sym("w"), up) / norm(cross(d.sym("w"), up)),
           "left-handed axes: u = w × up, normalized (the image's right)");
    d.step("v", "v", cross(d.sym("u"), d.sym("w")), "v = u × w (the image's up)");
  } else {
    d.step("u", "u", cross(up, d.sym("w")) / norm(cross(up, d.sym("w"))),
           "u = up × w, normalized: the image's right");
    d.step("v", "v", cross(d.sym("w"), d.sym("u")), "v = w × u: the image's up");
  }
  E nx = d.given("nx", "n_x", c.nx, "columns");
  E ny = d.given("ny", "n_y", c.ny, "rows");
  E dist = d.given("d", "d", c.focal_length, "the image plane's distance along −w");
  if (c.fov) {
    E fov = d.given("fov", "θ", *c.fov,
                    fmt::format("the {} field of view, in degrees",
                                c.fov_vertical ? "vertical" : "horizontal"));
    d.step("fov_rad", "θ_rad", fov * pi() / 180, "the field of view in radians");
    d.step("tan_half", "tan(θ/2)", tan(d.sym("fov_rad") / 2), "half the field of view's tangent");
    E tan_half = d.sym("tan_half");
    if (c.fov_vertical) {
      d.step("t", "t", dist * tan_half, "the top edge: d·tan(θ/2)");
      d.step("b", "b", -d.sym("t"));
      d.step("r", "r", d.sym("t") * nx / ny, "square pixels: t·n_x/n_y");
      d.step("l", "l", -d.sym("r"));
    } else {
      d.step("r", "r", dist * tan_half, "the right edge: d·tan(θ/2)");
      d.step("l", "l", -d.sym("r"));
      d.step("t", "t", d.sym("r") * ny / nx, "square pixels: r·n_y/n_x");
      d.step("b", "b", -d.sym("t"));
    }
  } else {
    d.given("l", "l", c.l, "the image plane's left edge");
    d.given("r", "r", c.r, "right edge");
    d.given("b", "b", c.b, "bottom edge");
    d.given("t", "t", c.t, "top edge");
  }
  d.step("pixel_width", "Δu", (d.sym("r") - d.sym("l")) / nx, "a pixel's width");
  d.step("pixel_height", "Δv", (d.sym("t") - d.sym("b")) / ny, "a pixel's height");
  E i = d.given("i", "i", i_, "the pixel's column, 0 at the left");
  E j = d.given("j", "j", j_,
                c.origin == PixelOrigin::kTopLeft ? "the pixel's row, 0 at the top"
                                                  : "the pixel's row, 0 at the bottom");
  bool centre = convention_ == PixelConvention::kCenter;
  E di = centre ? i + 0.5 : i;
  E dj = centre ? j + 0.5 : j;
  std::string where = centre ? "through the pixel's centre (+ ½)" : "through the pixel's corner";
  d.step("u_s", "u_s", d.sym("l") + d.sym("pixel_width") * di, where);
  if (c.origin == PixelOrigin::kTopLeft) {
    d.step("v_s", "v_s", d.sym("t") - d.sym("pixel_height") * dj, "rows count down from the top");
  } else {
    d.step("v_s", "v_s", d.sym("b") + d.sym("pixel_height") * dj, "rows count up from the bottom");
  }
  E us = d.sym("u_s"), vs = d.sym("v_s");
  Value o, dir;
  if (c.projection == Projection::kOrthographic) {
    o = d.step("origin", "o", e + us * d.sym("u") + vs * d.sym("v"),
               "orthographic: the ray starts on the image plane at the pixel");
    dir = d.step("direction", "D", -d.sym("w"), "every ray looks along −w");
  } else {
    o = d.step("origin", "o", e, "perspective: every ray starts at the eye");
    dir = d.step("direction", "D", -dist * d.sym("w") + us * d.sym("u") + vs * d.sym("v"),
                 "to the pixel on the image plane: −d·w + u_s·u + v_s·v");
  }
  d.step("unit_direction", "D_hat", d.sym("direction") / norm(d.sym("direction")),
         "the direction as a unit vector");
  d.conclude(Sentence(fmt::format("The ray through pixel ({}, {}) starts at ", format_number(i_),
                                  format_number(j_)))
                 .value(o)
                 .text(" with direction ")
                 .value(dir)
                 .text("."));
  return {SolutionPart{"", std::move(d).finish()}};
}

// The eye, the image plane's rectangle (l..r by b..t at distance d along −w) and the ray.
Sketch ViewRayTask::sketch() const {
  Sketch f;
  const ViewCamera& c = cam_;
  f.across = -c.w;
  f.across_name = "the view direction −w";
  f.up = c.v;
  f.up_name = "the camera's v";
  Vec3d centre = c.projection == Projection::kOrthographic ? c.eye : c.eye - c.focal_length * c.w;
  f.path({centre + c.l * c.u + c.b * c.v, centre + c.r * c.u + c.b * c.v,
          centre + c.r * c.u + c.t * c.v, centre + c.l * c.u + c.t * c.v},
         true, Ink::kGuide, "image plane");
  Ray ray = view_ray(c, i_, j_, convention_);
  double len = c.projection == Projection::kOrthographic ? c.focal_length + 1 : 1.3;
  f.arrow(ray.origin, ray.origin + len * ray.direction, Ink::kRay);
  f.ray_is_answer = true;
  f.point(c.eye, Ink::kPoint, "eye");
  f.point(c.projection == Projection::kOrthographic ? ray.origin : ray.origin + ray.direction,
          Ink::kHit, fmt::format("pixel ({}, {})", format_number(i_), format_number(j_)));
  return f;
}

std::optional<SceneGivens> ViewRayTask::scene_givens() const {
  SceneGivens g;
  g.camera = given_camera(cam_, i_, j_);
  return g;
}

std::unique_ptr<Task> ViewRayKind::read(const Cursor& problem) {
  return ViewRayTask::read(problem);
}

std::vector<PartSpec> ViewRayKind::parts() {
  using C = Comparison;
  PartSpec direction{part_names::kDirection, "the ray's direction (any positive multiple)", 1,
                     C::kDirection};
  direction.aliases = {part_names::kUnitDirection};  // a unit direction is a direction
  return {{part_names::kOrigin,
           "where the ray starts (the eye; the pixel itself when orthographic)", 1, C::kPoint},
          direction,
          {part_names::kUnitDirection, "the direction as a unit vector", 0, C::kUnitDirection},
          {"u", "the camera's u (the image's right)", 0, C::kDirection},
          {"v", "the camera's v (the image's up)", 0, C::kDirection},
          {"w", "the camera's w (pointing back)", 0, C::kDirection},
          {"l", "the image plane's left edge", 0, C::kScalar},
          {"r", "right edge", 0, C::kScalar},
          {"b", "bottom edge", 0, C::kScalar},
          {part_names::kT, "top edge", 0, C::kScalar},
          {"pixel_width", "a pixel's width (r − l)/n_x", 0, C::kScalar},
          {"pixel_height", "a pixel's height (t − b)/n_y", 0, C::kScalar},
          {"u_s", "the pixel's position along u", 0, C::kScalar},
          {"v_s", "the pixel's position along v", 0, C::kScalar}};
}

nlohmann::json ViewRayKind::answer_form(const Problem& /*p*/) {
  return form::fields({form::field<field_types::Vector>("origin", "Where the ray starts"),
                       form::field<field_types::Vector>("direction", "The ray's direction")});
}

std::string_view ViewRayKind::schema() {
  return R"json({
  "required": [
    "camera",
    "pixel",
    "convention"
  ],
  "properties": {
    "camera": {
      "$ref": "#/$defs/view_camera"
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
