// Box: axis-aligned, between corners min and max; the slab method.
#pragma once

#include "shapes/shape.h"

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

template <typename T>
SlabInterval<T> slab_interval(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& lo,
                              const Vec3<T>& hi) {
  SlabInterval<T> s;
  bool bounded_low = false, bounded_high = false;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == T(0)) {
      if (o[i] < lo[i] || o[i] > hi[i]) return s;
      continue;
    }
    T t_low = (lo[i] - o[i]) / d[i], t_high = (hi[i] - o[i]) / d[i];
    if (d[i] < T(0)) std::swap(t_low, t_high);
    if (!bounded_low || t_low > s.t_enter) {
      s.t_enter = t_low;
      s.enter_axis = i;
      bounded_low = true;
    }
    if (!bounded_high || t_high < s.t_exit) {
      s.t_exit = t_high;
      s.exit_axis = i;
      bounded_high = true;
    }
  }
  s.hit = s.t_enter <= s.t_exit;
  return s;
}

class Box final : public Shape {
 public:
  Box(Vec3d lo, Vec3d hi) : lo_(lo), hi_(hi) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  std::string_view type() const override { return "box"; }
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
