// Polygon: planar vertices, convex or not (a simple polygon).
#pragma once

#include "shapes/shape.h"

namespace raygrade {

class Polygon final : public Shape {
 public:
  explicit Polygon(std::vector<Vec3d> vertices);
  static std::unique_ptr<Shape> read(const Cursor& object);

  std::string_view type() const override { return "polygon"; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override;
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override;
  double extent() const override;
  void sketch(Sketch& figure, const std::string& label) const override;

  bool convex() const { return convex_; }

 private:
  std::vector<Vec3d> v_;
  Vec3d normal_;  // Newell's normal, by vertex order
  bool convex_;
};

}  // namespace raygrade
