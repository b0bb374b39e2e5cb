// What a problem's 3D view draws of its givens, as its kind answers for it (Task::scene_givens):
// the objects, the lights, the ray, the camera and its pixel, the point P, or the surface at a
// point of a problem that names no objects. The kind fills it in from the task it has read; the
// view (reports/scene_view.h) decides how each is drawn.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "shapes/ray.h"
#include "shapes/shape.h"
#include "shapes/transform.h"

namespace raygrade {

// One object, as the task holds it (the task owns the shape and the transform).
struct GivenObject {
  std::string name;  // empty for the one object of a problem: the view names it by its type
  const Shape* shape = nullptr;
  const Transform* transform = nullptr;  // what places `shape` in the world, when one does
};

// A point light at `position`, or a directional light whose light travels along `direction`.
struct GivenLight {
  std::string name;
  bool directional = false;
  Vec3d position{};
  Vec3d direction{};
};

// A camera and the pixel a problem names: the eye, the direction the camera looks, the image
// plane as a rectangle (its centre and half-sides) and the pixel on it, a rectangle around the
// point its centre's ray crosses the image plane at (whatever convention the problem follows).
struct GivenCamera {
  Vec3d eye, look;
  bool orthographic = false;
  Vec3d plane_center, plane_half_x, plane_half_y;
  Vec3d pixel_center, pixel_half_x, pixel_half_y;
};

// The surface at the point P of a problem that has a point on a surface but no objects: its
// normal there, or the triangle P lies on with the normals at its vertices; the direction that
// arrives at P and the eye, when the problem gives them.
struct GivenSurface {
  std::optional<Vec3d> normal;                   // as given (any length)
  std::optional<std::array<Vec3d, 3>> vertices;  // a triangle, with `vertex_normals`
  std::array<Vec3d, 3> vertex_normals{};
  std::optional<Vec3d> incoming;
  std::optional<Vec3d> eye;
};

struct SceneGivens {
  std::vector<GivenObject> objects;
  std::vector<GivenLight> lights;
  std::optional<Ray> ray;
  std::optional<GivenCamera> camera;
  std::optional<Vec3d> point;  // P, when the problem gives one
  // Only for a problem without objects; P is at the origin when `point` is empty.
  std::optional<GivenSurface> surface;

  // The surface at a point the problem does not place (the view puts it at the origin), with
  // its normal and the direction that arrives there: a reflection's, a refraction's.
  static SceneGivens surface_at_origin(const Vec3d& normal, const Vec3d& incoming) {
    SceneGivens g;
    g.surface.emplace();
    g.surface->normal = normal;
    g.surface->incoming = incoming;
    return g;
  }
};

}  // namespace raygrade
