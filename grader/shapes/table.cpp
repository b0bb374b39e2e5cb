// The table of primitives: adding one is one line here plus its own file pair.
#include "shapes/box.h"
#include "shapes/cylinder.h"
#include "shapes/plane.h"
#include "shapes/polygon.h"
#include "shapes/shape.h"
#include "shapes/sphere.h"
#include "shapes/triangle.h"

namespace raygrade {

const std::vector<ShapeEntry>& shape_table() {
  static const std::vector<ShapeEntry> table = {
      {"sphere", "center, radius", &Sphere::read},
      {"plane", "point and normal, or normal and d (n·p + d = 0)", &Plane::read},
      {"triangle", "vertices [a, b, c]", &Triangle::read},
      {"polygon", "planar vertices, convex or not", &Polygon::read},
      {"cylinder", "base, axis, radius, optional height and caps", &Cylinder::read},
      {"box", "axis-aligned, min and max corners", &Box::read},
  };
  return table;
}

}  // namespace raygrade
