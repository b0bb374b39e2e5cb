// Plane: point and normal, or normal and d with n·p + d = 0.
#pragma once

#include <optional>

#include "shapes/shape.h"

namespace raygrade {

class Plane final : public Shape {
 public:
  // Exactly one of `point` and `d` is set.
  Plane(Vec3d normal, std::optional<Vec3d> point, std::optional<double> d)
      : normal_(normal), point_(point), d_(d) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  std::string_view type() const override { return "plane"; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override;
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override;
  double extent() const override { return 1; }
  void sketch(Sketch& figure, const std::string& label) const override;

 private:
  // A point of the plane (the given one, or the one closest to the world origin).
  Vec3d some_point() const;

  Vec3d normal_;
  std::optional<Vec3d> point_;
  std::optional<double> d_;
};

}  // namespace raygrade
