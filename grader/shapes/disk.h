// Disk: the closed flat disk of a centre, a normal and a radius.
#pragma once

#include "generate/outcome.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

// The plan of the flat primitives: the ray meets the disk's plane at t, then the point P is
// inside when |P − C|² ≤ r², the rim included (the disk is closed).
class Disk final : public Shape {
 public:
  Disk(Vec3d center, Vec3d normal, double radius)
      : center_(center), normal_(normal), radius_(radius) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "disk";
  static constexpr std::string_view kSummary = "center, normal, radius; the rim included";
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator (shapes/disk_generate.cpp): the outcomes it can build, and a problem for one
  // of them (a random one when none is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // The normal kind (shapes/disk_normal.cpp): the part of its surface nearest to the
  // object-space point p, with the outward normal there (`tie`: how near two parts must both be
  // for p to lie where they meet), and the steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"plane-then-distance"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return center_; }
  double extent() const override { return radius_; }
  void sketch(Sketch& figure, const std::string& label) const override;

 private:
  // Is the point P of the disk's plane inside the closed disk?
  bool inside(const Vec3d& point) const;

  Vec3d center_;
  Vec3d normal_;  // as given, not normalized
  double radius_;
};

}  // namespace raygrade
