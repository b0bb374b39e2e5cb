// The parts of a sketch that the kinds share: the ray, its origin and the hit points.
#pragma once

#include <vector>

#include "shapes/shape.h"
#include "shapes/sketch.h"

namespace raygrade {

// Draws the ray from its origin to a little past the farthest of the hits and the objects
// (or to t_max), marks the origin, and sets the figure's left-to-right direction to the ray's.
void sketch_ray(Sketch& figure, const Ray& ray, const std::vector<const Shape*>& objects,
                const std::vector<Hit>& hits);

// A hit point labelled with its t.
void sketch_hit(Sketch& figure, const Hit& hit, Ink ink, const std::string& prefix = "");

}  // namespace raygrade
