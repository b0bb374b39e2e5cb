// TransformedShape: a primitive placed in the world by its `transform`, for the kinds that read
// one object or a list of them (scenes keep the primitive and its transform side by side).
#pragma once

#include <memory>

#include "shapes/primitives.h"
#include "shapes/shape.h"
#include "shapes/transform.h"

namespace raygrade {

// The ray goes into object space (O' = M⁻¹O, D' = A⁻¹D, not normalized, so that t is the world
// ray's t), the primitive is intersected there, and each hit comes back: P = O + tD, the
// normal by the inverse transpose (A⁻¹)ᵀ, normalized.
class TransformedShape final : public Shape {
 public:
  TransformedShape(std::unique_ptr<Shape> object, Transform transform)
      : object_(std::move(object)), transform_(std::move(transform)) {}

  // The primitive's type: messages and mistakes that name the shape still apply.
  std::string_view type() const override { return object_->type(); }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return object_->methods(); }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides = nullptr) const override;
  // The primitive's parameters with its `transform`.
  nlohmann::json to_json() const override;
  Vec3d center() const override;
  double extent() const override;
  bool solid() const override { return object_->solid(); }
  std::optional<QuadraticSteps> quadratic() const override { return object_->quadratic(); }

  const Shape& object() const { return *object_; }
  const Transform& transform() const { return transform_; }

 private:
  std::unique_ptr<Shape> object_;
  Transform transform_;
};

// The normal rule of a shape's primitive (shapes/primitives.h); a transformed object's sentence
// on the outward normal says how it is taken to the world.
NormalRule normal_rule_of(const Shape& shape);

}  // namespace raygrade
