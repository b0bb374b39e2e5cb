// Sphere: parameters, reading, the stable reference intersection and its derivations.
#pragma once

#include <cmath>
#include <optional>

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

// The quarter discriminant a·r² − |f × d|² in plain arithmetic, when its a-posteriori error
// bound e (docs/precision.md, "Fast paths") is within kFastPathTolerance of it; 0 otherwise.
// Each component x_i = p_i − q_i of the cross product is within 3u(|p_i| + |q_i|) of the exact
// one, counting the rounding of f, so a ray aimed near the centre (x small) keeps a small bound.
template <typename T>
[[gnu::always_inline]] inline T cross_product_discriminant(const Vec3<T>& f, const Vec3<T>& d, T a,
                                                           T ff, T rr) {
  using std::abs;
  constexpr T u = kUnitRoundoff<T>, tolerance = kFastPathTolerance<T>;
  T px = f.y * d.z, qx = f.z * d.y, py = f.z * d.x, qy = f.x * d.z, pz = f.x * d.y, qz = f.y * d.x;
  Vec3<T> x{px - qx, py - qy, pz - qz};
  T s2 = dot(x, x), ar = a * rr, disc = ar - s2;
  // First a bound from magnitudes at hand, enough for nearly every ordinary ray: the spread
  // below is at most 2|f||d|·√3|f||d| < 4·ff·a, so e ≤ 7u(a·rr + s2) + 25u·ff·a.
  T slack = abs(disc) * tolerance - T(7) * u * (ar + s2);
  if (slack >= T(25) * u * (ff * a)) return disc;
  T spread = abs(x.x) * (abs(px) + abs(qx)) + abs(x.y) * (abs(py) + abs(qy)) +
             abs(x.z) * (abs(pz) + abs(qz));
  return slack >= T(6) * u * spread + T(32) * u * u * (ff * a) ? disc : T(0);
}

// The roots of the sphere's quadratic in plain arithmetic, when their a-posteriori error bounds
// (docs/precision.md, "Fast paths") show that they decide hit or miss, and which root is nearest,
// as exact arithmetic would, and that c = f·f − r² and the quarter discriminant are within
// kFastPathTolerance τ of their exact values: then true, with the roots in `out`. False
// otherwise: the compensated formulas then run. (An out-parameter rather than a std::optional,
// whose copy through memory costs GCC 12 a store-forwarding stall.)
template <typename T>
[[gnu::always_inline]] inline bool sphere_roots_fast(const Vec3<T>& o, const Vec3<T>& d,
                                                     const Vec3<T>& center, T r, Roots<T>& out) {
  using std::abs, std::sqrt;
  constexpr T u = kUnitRoundoff<T>, tolerance = kFastPathTolerance<T>;
  Vec3<T> f = o - center;
  T a = dot(d, d), ff = dot(f, f), rr = r * r, b = dot(f, d), c = ff - rr;
  // |c − c*| ≤ 7u(ff + rr); the bounds' products neither overflow nor underflow in range.
  bool in_range = in_fast_path_range(a) && in_fast_path_range(rr) && ff <= kFastPathRange<T>;
  if (!(in_range && abs(c) * tolerance >= T(7) * u * (ff + rr))) return false;
  // The quarter discriminant a·r² − |f × d|², which does not cancel for far spheres. Its bound
  // e ≤ τ·|disc| makes its sign certain and keeps the error it brings into √disc, and so into
  // q = −(b + sign(b)√disc), within τ. (The textbook b² − a·c would be cheaper, but near a
  // tangent its error grows faster than the condition number of t: the hard cases catch it.)
  T disc = cross_product_discriminant(f, d, a, ff, rr);
  if (disc == T(0)) return false;
  out = Roots<T>{};
  if (disc < T(0)) return true;
  T q = -(b + sign_of(b) * sqrt(disc));
  out.count = 2;
  out.t0 = c / q;
  out.t1 = q / a;
  if (out.t1 < out.t0) std::swap(out.t0, out.t1);
  return true;
}

// The stable reference: roots of |o + t d − c|² = r² (Ray Tracing Gems, ch. 7). The quarter
// discriminant is a·r² − |f × d|², which does not cancel for far spheres; the roots are
// q/a and c/q with q = −(b + sign(b)√Δ), which never subtracts nearly equal numbers. The plain
// computation is kept when its error bounds allow (sphere_roots_fast); otherwise f = o − c is
// split exactly and the cross product and c are compensated.
template <typename T>
[[gnu::noinline]] Roots<T> sphere_roots_accurate(const Vec3<T>& o, const Vec3<T>& d,
                                                 const Vec3<T>& center, T r);

template <typename T>
[[gnu::always_inline]] inline Roots<T> sphere_roots(const Vec3<T>& o, const Vec3<T>& d,
                                                    const Vec3<T>& center, T r) {
  if constexpr (kErrorFree<T>) {
    Roots<T> fast;
    if (sphere_roots_fast(o, d, center, r, fast)) return fast;
  }
  return sphere_roots_accurate(o, d, center, r);
}

// The compensated path, out of line so that the fast path inlines where it is called.
template <typename T>
Roots<T> sphere_roots_accurate(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& center, T r) {
  using std::sqrt;
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
