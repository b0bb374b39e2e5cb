// Cone: the circle of `radius` at `base` and the apex at base + height·â, open or with its
// base cap.
#pragma once

#include "generate/outcome.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

// A point P is on the side when, with q = P − B, s = q·â its height and q⊥ = q − s·â, it has
// 0 ≤ s ≤ h and h·|q⊥| = r·(h − s). On the ray, with f = O − B, w = h − f·â, that is the
// quadratic a t² + b t + c = 0 with (multiplied through by h², so that whole numbers stay
// whole)
//   a = h²|D⊥|² − r²(D·â)²,  b = 2(h² f⊥·D⊥ + r² w (D·â)),  c = h²|f⊥|² − r² w²,
// whose roots outside 0 ≤ s ≤ h lie on the other nappe or below the base. The outward normal
// is (h·ê + r·â)/√(h² + r²), ê the unit vector across the axis towards P; at the apex, where
// ê is undefined, it is â (documented in docs/problem-format.md). The cap's is −â.
class Cone final : public Shape {
 public:
  Cone(Vec3d base, Vec3d axis, double radius, double height, bool capped);
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "cone";
  static constexpr std::string_view kSummary = "base, axis, radius, height, optional base cap";
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator: the outcomes it can build, and a problem for one of them (a random one when none
  // is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // The normal kind: the part of its surface nearest to the object-space point p, with the outward
  // normal there (`tie`: how near two parts must both be for p to lie where they meet), and the
  // steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"quadratic"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return base_ + (height_ / 2) * axis_; }
  double extent() const override { return std::max(radius_, height_ / 2); }
  void sketch(Sketch& figure, const std::string& label) const override;
  // Closed with its cap.
  bool solid() const override { return capped_; }
  NormalRule normal_rule() const override;
  std::string contained_line() const override;
  std::optional<QuadraticSteps> quadratic() const override { return QuadraticSteps{}; }

 private:
  Vec3d base_;
  Vec3d axis_given_;
  Vec3d axis_;  // unit
  double radius_;
  double height_;
  bool capped_;
};

}  // namespace raygrade
