// Box: axis-aligned, between corners min and max; the slab method.
#pragma once

#include "generate/outcome.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

// The interval of t inside the closed box, and the axes whose slabs bound it. A direction
// component of exactly zero is handled without dividing (no NaN when the origin lies on a
// slab plane): the slab then holds all t or none.
template <typename T>
struct SlabInterval {
  bool hit = false;
  T t_enter{}, t_exit{};
  int enter_axis = -1, exit_axis = -1;  // -1: unbounded along the ray
};

// Inlined where it is called: returned through memory from a call, the interval costs about as
// much as the slabs' arithmetic.
template <typename T>
[[gnu::always_inline]] inline SlabInterval<T> slab_interval(const Vec3<T>& o, const Vec3<T>& d,
                                                            const Vec3<T>& lo, const Vec3<T>& hi) {
  SlabInterval<T> s;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == T(0)) {
      if (o[i] < lo[i] || o[i] > hi[i]) return s;
      continue;
    }
    // Selections rather than branches: the signs of d and the order of the slabs are as
    // random as the rays, and a mispredicted branch costs more than the arithmetic.
    T t_low = (lo[i] - o[i]) / d[i], t_high = (hi[i] - o[i]) / d[i];
    bool backward = d[i] < T(0);
    T t_near = backward ? t_high : t_low, t_far = backward ? t_low : t_high;
    bool later = s.enter_axis < 0 || t_near > s.t_enter;
    bool sooner = s.exit_axis < 0 || t_far < s.t_exit;
    s.t_enter = later ? t_near : s.t_enter;
    s.enter_axis = later ? i : s.enter_axis;
    s.t_exit = sooner ? t_far : s.t_exit;
    s.exit_axis = sooner ? i : s.exit_axis;
  }
  s.hit = s.t_enter <= s.t_exit;
  return s;
}

class Box final : public Shape {
 public:
  Box(Vec3d lo, Vec3d hi) : lo_(lo), hi_(hi) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "box";
  static constexpr std::string_view kSummary = "axis-aligned, min and max corners";
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator (shapes/box_generate.cpp): the outcomes it can build, and a problem for one
  // of them (a random one when none is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // The normal kind (shapes/box_normal.cpp): the part of its surface nearest to the
  // object-space point p, with the outward normal there (`tie`: how near two parts must both be
  // for p to lie where they meet), and the steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
  bool solid() const override { return true; }
  NormalRule normal_rule() const override {
    return {"inward-normal",
            " A box's outward normal is the axis of the slab hit, pointing away from the box's "
            "centre."};
  }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"slab"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return (lo_ + hi_) / 2.0; }
  double extent() const override { return length(hi_ - lo_) / 2; }
  void sketch(Sketch& figure, const std::string& label) const override;

 private:
  Vec3d lo_, hi_;
};

}  // namespace raygrade
