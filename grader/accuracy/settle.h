// The adaptive answer inside the solver: how much precision a problem's hit-or-miss decision
// needed, and the decision itself when double could not make it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "shapes/accuracy_case.h"
#include "shapes/shape.h"

namespace raygrade {

// The case of the accuracy study for an object and a ray, when it has one: the ray's interval
// must be [0, ∞); planes given by a point, infinite cylinders and the other primitives qualify.
// Its direction is the ray's scaled into [1, 2) by a power of two, as intersect_rescaled does:
// its t is 2^direction_exponent times the ray's.
std::optional<AccuracyCase> accuracy_case_of(const Shape& object, const Ray& ray);

// The object of an accuracy case as the solver's Shape, the inverse of accuracy_case_of: an
// infinite cylinder, a plane given by a point.
std::unique_ptr<Shape> shape_of(const AccuracyCase& c);

// Runs the adaptive ladder on the nearest hit of `x` (the double reference's answer). Returns
// the level the decision needed ("double", "double-double", "mpfr", "exact-boundary"), or
// nothing when the problem is outside the study. When a higher level decided differently from
// double, `x` is corrected: a miss clears the hits; a hit double missed is added with its t and
// point (and the normal of the object's intersection at that t when it reports one).
std::optional<std::string> settle_nearest(const Shape& object, const Ray& ray, Intersection& x);

// The first hit among several objects, settled: each object's hit-or-miss decision as
// settle_nearest settles it (correcting `hits`, one Intersection per object), then the order of
// the nearest hits, compared at the first level whose certified enclosures of the two t values
// separate them (an exact tie when even 4096-bit MPFR cannot). Sets `index` (−1 when nothing is
// hit) and `tie` (another object is hit at exactly the same t; the first in the list keeps the
// name) and returns the highest level any of these decisions needed, or nothing (leaving `index`
// and `tie` alone) when some object is outside the study.
std::optional<std::string> settle_first(const std::vector<const Shape*>& objects, const Ray& ray,
                                        std::vector<Intersection>& hits, int& index, bool& tie);

}  // namespace raygrade
