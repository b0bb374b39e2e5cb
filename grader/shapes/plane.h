// Plane: point and normal, or normal and d with n·p + d = 0.
#pragma once

#include <optional>

#include "math/robust.h"
#include "shapes/shape.h"

namespace raygrade {

// The parameter t where the ray meets the plane through p with normal n: n·(p − o) / (n·d),
// with p − o split exactly and both dot products compensated, so that a ray nearly parallel
// to the plane (n·d around 1e-12) keeps the digits of its denominator. No value when n·d = 0.
template <typename T>
std::optional<T> plane_t(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& n, const Vec3<T>& p) {
  if constexpr (kErrorFree<T>) {
    // Fast path: plain dot products when neither cancels (see kNoCancellation); p − o is then
    // only needed to rounding, since the numerator is large next to its terms.
    using std::abs;
    Vec3<T> f = p - o;
    T den = dot(n, d), num = dot(n, f);
    T den_size = abs(n.x * d.x) + abs(n.y * d.y) + abs(n.z * d.z);
    T num_size = abs(n.x) * (abs(p.x) + abs(o.x)) + abs(n.y) * (abs(p.y) + abs(o.y)) +
                 abs(n.z) * (abs(p.z) + abs(o.z));
    T k = T(kNoCancellation);
    if (abs(den) >= k * den_size && abs(num) >= k * num_size) return num / den;
  }
  T den = dot_accurate(n, d);
  if (den == T(0)) return std::nullopt;
  Vec3<T> f, f_lo;
  difference_exact(p, o, f, f_lo);
  T num = dot_accurate(n, f) + dot(n, f_lo);
  return num / den;
}

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
