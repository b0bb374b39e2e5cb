// The parts of a sketch that the kinds share: the ray, its origin and the hit points; a
// surface point seen edge-on with its normal, and rays arriving at it.
#pragma once

#include <vector>

#include "shapes/shape.h"
#include "shapes/sketch.h"

namespace raygrade {

// Draws the ray from its origin to a little past the farthest of the hits and the objects
// (or to t_max), labelled `ray_label` at its head, marks the origin (labelled `origin_label`),
// and sets the figure's left-to-right direction to the ray's.
void sketch_ray(Sketch& figure, const Ray& ray, const std::vector<const Shape*>& objects,
                const std::vector<Hit>& hits, const std::string& origin_label = "O",
                const std::string& ray_label = "");

// A hit point labelled with its t.
void sketch_hit(Sketch& figure, const Hit& hit, Ink ink, const std::string& prefix = "");

// A vector for a label: "(1, −2, 0)", with real minus signs as the worked solutions write them.
std::string sketch_vector(const Vec3d& v);

// A surface point seen edge-on: the surface's trace through `at` and its unit `normal` as an
// arrow labelled `normal_label`. The view puts the normal up and the part of `along` that runs
// along the surface (any direction along it, when `along` is parallel to the normal) to the
// right. Returns that right-pointing unit direction.
Vec3d sketch_surface(Sketch& figure, const Vec3d& at, const Vec3d& normal, const Vec3d& along,
                     const std::string& normal_label);

// A ray arriving at `at` along the unit `direction`, one unit long, with its arrowhead halfway
// so that its label stands clear of the point.
void sketch_incoming(Sketch& figure, const Vec3d& at, const Vec3d& direction,
                     const std::string& label);

}  // namespace raygrade
