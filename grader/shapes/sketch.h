// Sketch: what a worked solution's sketch shows, as primitives in world coordinates. A task
// fills one (Task::figure); the renderers choose the view and draw it (reports/svg_figure.h).
#pragma once

#include <string>
#include <vector>

#include "math/vec3.h"

namespace raygrade {

// What a primitive stands for; each output picks its colours and dashes from this.
enum class Ink {
  kObject,  // an object of the problem
  kGuide,   // a construction line or an auxiliary object (the image plane, an axis)
  kRay,     // the ray
  kHit,     // a hit point
  kMiss,    // a rejected candidate (behind the origin, outside the height, ...)
  kPoint,   // a named point that is neither (the ray's origin, the eye)
};

struct SketchItem {
  enum class Type {
    kPath,      // a polyline through `points`, closed when `closed`
    kCircle,    // a sphere's outline: centre points[0], radius `radius` (a circle in any view)
    kLine,      // an infinite line through points[0] along points[1], clipped to the frame
    kArrow,     // from points[0] to points[1]
    kPoint,     // a marker at points[0]
    kPlane,     // a plane through points[0] with normal points[1]: drawn as its trace in the view
    kCylinder,  // axis from points[0] along the unit points[1], `radius`; `height` 0: infinite
    kText,      // a label alone, at points[0] (a medium's name, a note beside a construction)
  };
  Type type = Type::kPath;
  std::vector<Vec3d> points;
  double radius = 0;
  double height = 0;
  bool closed = false;
  Ink ink = Ink::kObject;
  std::string label;  // user text allowed: renderers escape it
};

struct Sketch {
  std::vector<SketchItem> items;
  // The direction drawn left to right (the ray's, or the camera's viewing direction); zero
  // when the renderer may choose. The up direction is the one along which the figure is
  // widest, so the view is the plane that shows it best.
  Vec3d across{};
  std::string across_name;  // what `across` is, for the caption: "the ray's direction"
  // The direction drawn bottom to top (a surface's normal); zero, or parallel to `across`,
  // when the renderer may choose.
  Vec3d up{};
  std::string up_name;  // what `up` is, for the caption: "the normal"
  // The ray drawn is what the problem asks (a camera's ray through a pixel): a statement's
  // figure leaves it out and keeps the camera's frame (the guides) instead.
  bool ray_is_answer = false;

  bool empty() const { return items.empty(); }
  void path(std::vector<Vec3d> points, bool closed, Ink ink, std::string label = "") {
    items.push_back(
        {SketchItem::Type::kPath, std::move(points), 0, 0, closed, ink, std::move(label)});
  }
  void circle(const Vec3d& center, double radius, Ink ink, std::string label = "") {
    items.push_back({SketchItem::Type::kCircle, {center}, radius, 0, true, ink, std::move(label)});
  }
  void line(const Vec3d& point, const Vec3d& direction, Ink ink, std::string label = "") {
    items.push_back(
        {SketchItem::Type::kLine, {point, direction}, 0, 0, false, ink, std::move(label)});
  }
  void arrow(const Vec3d& from, const Vec3d& to, Ink ink, std::string label = "") {
    items.push_back({SketchItem::Type::kArrow, {from, to}, 0, 0, false, ink, std::move(label)});
  }
  void plane(const Vec3d& point, const Vec3d& normal, Ink ink, std::string label = "") {
    items.push_back(
        {SketchItem::Type::kPlane, {point, normal}, 0, 0, false, ink, std::move(label)});
  }
  void cylinder(const Vec3d& base, const Vec3d& unit_axis, double radius, double height, Ink ink,
                std::string label = "") {
    items.push_back({SketchItem::Type::kCylinder,
                     {base, unit_axis},
                     radius,
                     height,
                     false,
                     ink,
                     std::move(label)});
  }
  void point(const Vec3d& at, Ink ink, std::string label = "") {
    items.push_back({SketchItem::Type::kPoint, {at}, 0, 0, false, ink, std::move(label)});
  }
  void text(const Vec3d& at, Ink ink, std::string label) {
    items.push_back({SketchItem::Type::kText, {at}, 0, 0, false, ink, std::move(label)});
  }
};

}  // namespace raygrade
