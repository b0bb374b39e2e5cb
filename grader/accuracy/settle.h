// The adaptive answer inside the solver: how much precision a problem's hit-or-miss decision
// needed, and the decision itself when double could not make it.
#pragma once

#include <optional>
#include <string>

#include "accuracy/accuracy_case.h"
#include "shapes/shape.h"

namespace raygrade {

// The case of the accuracy study for an object and a ray, when it has one: the ray's interval
// must be [0, ∞); planes given by a point, infinite cylinders and the other primitives qualify.
std::optional<AccuracyCase> accuracy_case_of(const Shape& object, const Ray& ray);

// Runs the adaptive ladder on the nearest hit of `x` (the double reference's answer). Returns
// the level the decision needed ("double", "double-double", "mpfr", "exact-boundary"), or
// nothing when the problem is outside the study. When a higher level decided differently from
// double, `x` is corrected: a miss clears the hits; a hit double missed is added with its t and
// point (and the normal of the object's intersection at that t when it reports one).
std::optional<std::string> settle_nearest(const Shape& object, const Ray& ray, Intersection& x);

}  // namespace raygrade
