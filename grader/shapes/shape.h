// Shape: what every primitive provides, and the table of primitives.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "derivation/derivation.h"
#include "json/cursor.h"
#include "shapes/ray.h"
#include "shapes/sketch.h"

namespace raygrade {

class Shape {
 public:
  virtual ~Shape() = default;

  virtual std::string_view type() const = 0;

  // The reference answer: every hit of the closed object in [t_min, t_max], ascending.
  virtual Intersection intersect(const Ray& ray) const = 0;

  // The methods a course teaches for this primitive; the first is the default.
  virtual std::vector<std::string> methods() const = 0;

  // The worked derivation by `method` (empty for the default). `overrides` replaces step
  // values or formulas, for error carried forward and mistake diagnosis.
  virtual Derivation derive(const Ray& ray, std::string_view method,
                            const Overrides* overrides = nullptr) const = 0;

  // The parameters, in the problem format.
  virtual nlohmann::json to_json() const = 0;

  // A point and size that frame the object in a figure.
  virtual Vec3d center() const = 0;
  virtual double extent() const = 0;

  // Draws the object into a worked solution's sketch. The default, for a primitive that
  // has no drawing of its own, is a dashed circle that frames it.
  virtual void sketch(Sketch& figure, const std::string& label) const {
    figure.circle(center(), extent(), Ink::kGuide, label);
  }

  // Labels, in a sketch where `ray` meets the object, the parameters that formula answers
  // name by their symbols (`symbols`: the derivation's scalar givens they use, "r", "cx").
  // The default, for a primitive whose derivation has no such symbols, labels nothing.
  virtual void sketch_symbols(Sketch& /*figure*/, const Ray& /*ray*/,
                              const std::vector<std::string>& /*symbols*/) const {}

  // Whether the object encloses a volume (a ray inside it leaves through its surface): a scene
  // tells entering from leaving by it. The default, for a surface that encloses nothing, is no.
  virtual bool solid() const { return false; }

  // The steps of the quadratic a t² + b t + c = 0 whose roots are the hits, and the method that
  // derives them (empty: the default method): grading widens the tolerance of t near a tangent
  // from them. None for a primitive solved without a quadratic.
  struct QuadraticSteps {
    std::string method;
    std::string a = "a", b = "b", c = "c";
  };
  virtual std::optional<QuadraticSteps> quadratic() const { return std::nullopt; }
};

// One row of the table of primitives: the `type` key in problem files, its reader and its
// fragment of the problem schema. The rows are derived from the list `Primitives`
// (shapes/primitives.h).
struct ShapeEntry {
  std::string_view type;
  std::string_view summary;
  std::unique_ptr<Shape> (*read)(const Cursor& object);
  nlohmann::ordered_json (*schema)();
};

// Every primitive, in the order of the list (the order the docs list them).
const std::vector<ShapeEntry>& shape_table();

// Reads a primitive by its `type`; unknown types get a "did you mean" error. Its `material`
// and `transform` are left to the caller (a scene keeps them beside the primitive).
std::unique_ptr<Shape> read_primitive(const Cursor& object);

// Reads an object of the kinds outside scenes: the primitive placed by its `transform` (a
// TransformedShape). A `material` is an error: nothing outside a scene uses one.
std::unique_ptr<Shape> read_shape(const Cursor& object);

// The keys every object may carry beside its type's own parameters.
const std::vector<std::string>& common_object_keys();

// Every primitive's intersect starts here: when the largest component of the ray's direction
// is outside [1, 2), the shape is intersected with the direction scaled into it by a power of
// two 2^-k (exactly) and the hits' t scaled back by 2^-k. The answer is then the same at every
// scale of the direction where a double holds t (1e-165 as well as 1e+165): no product of the
// direction's components overflows or underflows, and finish_hits merges hits on the scale of
// the object, not of t. Nothing when the direction is in [1, 2) already (or zero, or not
// finite): the shape goes on with the ray as it is.
std::optional<Intersection> intersect_rescaled(const Shape& shape, const Ray& ray);

// The exponent k of intersect_rescaled: ilogb of the direction's largest component, 0 when that
// is zero or not finite.
int direction_exponent(const Vec3d& direction);

// Sorts hits by t and merges those that are the same point of the surface (a seam: a
// cylinder's rim, a box's edge), keeping the first: hits whose t agree within a few ulps, or
// whose points lie within `seam_distance` of each other.
void finish_hits(std::vector<Hit>& hits, double seam_distance = 0);

}  // namespace raygrade
