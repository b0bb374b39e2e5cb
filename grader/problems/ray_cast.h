// A problem that casts one ray at objects, as a kind answers for it: the ray, the objects,
// and what meets what. The bank's checks (check/) and the hit grader probe such a problem
// through this, without knowing which kind it is.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shapes/ray.h"
#include "shapes/shape.h"

namespace raygrade {

// The nearest hit of each object and the first of them all.
struct FirstHit {
  int index = -1;  // into the objects; -1 when nothing is hit
  Hit hit;
  bool tie = false;                         // another object is hit at the same t
  std::vector<std::optional<Hit>> nearest;  // per object
  // The highest level of the adaptive ladder the decisions needed (docs/precision.md), when the
  // study covers every object.
  std::optional<std::string> level;
};

class RayCast {
 public:
  virtual ~RayCast() = default;
  virtual const Ray& cast_ray() const = 0;
  virtual std::size_t object_count() const = 0;
  virtual const Shape& object_at(std::size_t i) const = 0;
  // The name the answer gives an object (empty for the one object of a problem that asks
  // for every hit).
  virtual std::string_view object_name(std::size_t i) const = 0;
  // The answer is the object `cast_ray()` meets first, not every hit of one object.
  virtual bool asks_first_object() const = 0;
  // Which object `ray` meets first, by the kind's own rule (ties, the precision ladder).
  virtual FirstHit first_met(const Ray& ray) const = 0;
};

}  // namespace raygrade
