// Capsule: the segment ab swept by a sphere of radius r (a cylinder with two hemispherical ends).
#pragma once

#include "generate/outcome.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

// The hits are the side's (the cylinder of radius r around ab, where the height s along the
// axis from a lies in [0, h], h = |b − a|) and the end spheres' (around a where s ≤ 0, around b
// where s ≥ h). A hit on the rim between the side and an end is found by both and listed once.
class Capsule final : public Shape {
 public:
  Capsule(Vec3d a, Vec3d b, double radius);
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "capsule";
  static constexpr std::string_view kSummary = "segment ends a and b, radius";
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator (shapes/capsule_generate.cpp): the outcomes it can build, and a problem for
  // one of them (a random one when none is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // The normal kind (shapes/capsule_normal.cpp): the part of its surface nearest to the
  // object-space point p, with the outward normal there (`tie`: how near two parts must both be
  // for p to lie where they meet), and the steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"side-and-ends"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return 0.5 * (a_ + b_); }
  double extent() const override { return height_ / 2 + radius_; }
  void sketch(Sketch& figure, const std::string& label) const override;
  bool solid() const override { return true; }
  NormalRule normal_rule() const override;
  std::optional<QuadraticSteps> quadratic() const override { return QuadraticSteps{}; }

 private:
  Vec3d a_, b_;
  double radius_;
  Vec3d axis_;     // unit, from a to b
  double height_;  // |b − a|
};

}  // namespace raygrade
