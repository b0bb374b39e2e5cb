// Sphere: parameters, reading, the stable reference intersection and its derivations.
#pragma once

#include <cmath>

#include "math/robust.h"
#include "shapes/shape.h"

namespace raygrade {

// The real roots of a quadratic, ascending: count is 0, 1 (tangent) or 2.
template <typename T>
struct Roots {
  int count = 0;
  T t0{}, t1{};
};

// f·f − r² with one final rounding for floating types: the squares are split exactly by FMA
// and summed with Neumaier's compensation, so that an origin just above a huge sphere keeps
// the digits of its (small) distance to the surface.
template <typename T>
T sum_of_squares_minus_square(const Vec3<T>& f_hi, const Vec3<T>& f_lo, T r) {
  if constexpr (kErrorFree<T>) {
    T sum = 0, compensation = 0;
    auto add = [&](T x) {
      T s = sum + x;
      using std::abs;
      compensation += abs(sum) >= abs(x) ? (sum - s) + x : (x - s) + sum;
      sum = s;
    };
    for (int i = 0; i < 3; ++i) {
      T p = f_hi[i] * f_hi[i];
      add(p);
      add(std::fma(f_hi[i], f_hi[i], -p));
      add(2 * f_hi[i] * f_lo[i]);
    }
    T rr = r * r;
    add(-rr);
    add(-std::fma(r, r, -rr));
    return sum + compensation;
  } else {
    Vec3<T> f = f_hi + f_lo;
    return dot(f, f) - r * r;
  }
}

// The stable reference: roots of |o + t d − c|² = r² (Ray Tracing Gems, ch. 7). The quarter
// discriminant is a·r² − |f × d|², which does not cancel for far spheres; the roots are
// q/a and c/q with q = −(b + sign(b)√Δ), which never subtracts nearly equal numbers.
template <typename T>
Roots<T> sphere_roots(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& center, T r) {
  using std::sqrt;
  if constexpr (kErrorFree<T>) {
    // Fast path: the same formulas in plain arithmetic, taken only when neither the cross
    // product, nor the discriminant, nor c = f·f − r² cancels (see kNoCancellation).
    using std::abs;
    Vec3<T> f = o - center;
    T a = dot(d, d), ff = dot(f, f), rr = r * r;
    Vec3<T> fxd = cross(f, d);
    T s2 = dot(fxd, fxd), disc = a * rr - s2, c = ff - rr;
    T k = T(kNoCancellation);
    if (s2 >= k * ff * a && abs(disc) >= k * (a * rr + s2) && abs(c) >= k * (ff + rr)) {
      Roots<T> out;
      if (disc < T(0)) return out;
      T b = dot(f, d);
      T q = -(b + sign_of(b) * sqrt(disc));
      out.count = 2;
      out.t0 = c / q;
      out.t1 = q / a;
      if (out.t1 < out.t0) std::swap(out.t0, out.t1);
      return out;
    }
  }
  Vec3<T> f, f_lo;
  difference_exact(o, center, f, f_lo);
  T a = dot(d, d);
  T b = dot(f, d) + dot(f_lo, d);  // half of the textbook b
  Vec3<T> fxd = cross_accurate(f, d) + cross(f_lo, d);
  T disc = a * (r * r) - dot(fxd, fxd);  // b² − a·c
  Roots<T> out;
  if (disc < T(0)) return out;
  if (disc == T(0)) {
    out.count = 1;
    out.t0 = out.t1 = -b / a;
    return out;
  }
  T c = sum_of_squares_minus_square(f, f_lo, r);
  T q = -(b + sign_of(b) * sqrt(disc));
  T t0 = c / q, t1 = q / a;
  if (t1 < t0) std::swap(t0, t1);
  out.count = 2;
  out.t0 = t0;
  out.t1 = t1;
  return out;
}

class Sphere final : public Shape {
 public:
  Sphere(Vec3d center, double radius) : center_(center), radius_(radius) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  std::string_view type() const override { return "sphere"; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"geometric", "algebraic"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return center_; }
  double extent() const override { return radius_; }
  void sketch(Sketch& figure, const std::string& label) const override;

  double radius() const { return radius_; }

 private:
  Derivation derive_geometric(const Ray& ray, const Overrides* overrides) const;
  Derivation derive_algebraic(const Ray& ray, const Overrides* overrides) const;

  Vec3d center_;
  double radius_;
};

}  // namespace raygrade
