// Sphere: parameters, reading, the stable reference intersection and its derivations.
#pragma once

#include <cmath>
#include <optional>

#include "math/robust.h"
#include "sampling/outcome.h"
#include "shapes/filter_answer.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

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

// Is the quarter discriminant disc = a·r² − s2, with s2 = |f × d|² as rounded in plain
// arithmetic, within kFastPathTolerance τ of its exact value, by the bound that follows the
// cross product's own cancellation (docs/precision.md, "Fast paths")? Each component
// x_i = p_i − q_i of the cross product is within 3u(|p_i| + |q_i|) of the exact one, counting
// the rounding of f, so a ray aimed near the centre (x small) keeps a small bound. The second
// test, for the few rays the first (in sphere_quadratic_fast) leaves undecided.
template <typename T>
bool discriminant_certain(const Vec3<T>& f, const Vec3<T>& d, T a, T ff, T rr, T s2, T disc) {
  using std::abs;
  constexpr T u = kUnitRoundoff<T>, tolerance = kFastPathTolerance<T>;
  // The bound's products neither overflow nor underflow in range.
  if (!(in_fast_path_range(a) && in_fast_path_range(rr) && ff <= kFastPathRange<T>)) return false;
  T px = f.y * d.z, qx = f.z * d.y, py = f.z * d.x, qy = f.x * d.z, pz = f.x * d.y, qz = f.y * d.x;
  T spread = abs(px - qx) * (abs(px) + abs(qx)) + abs(py - qy) * (abs(py) + abs(qy)) +
             abs(pz - qz) * (abs(pz) + abs(qz));
  T e = T(7) * u * (a * rr + s2) + T(6) * u * spread + T(32) * u * u * (ff * a);
  return abs(disc) * tolerance >= e;
}

// The constants of the sphere's first test (docs/precision.md, "Fast paths"): |disc| ≥ kDisc·a·m
// and |c| ≥ kC·m, with m = ff + r², put the errors of disc and of c within τ of them.
template <typename T>
inline constexpr T kSphereDisc = T(33) * kUnitRoundoff<T> / kFastPathTolerance<T>;
template <typename T>
inline constexpr T kSphereC = T(8) * kUnitRoundoff<T> / kFastPathTolerance<T>;

// A ray's quadratic a·t² + 2b·t + c = 0 (b is half the textbook b) with its quarter
// discriminant disc = b² − a·c, as a fast path leaves it.
template <typename T>
struct Quadratic {
  T a{}, b{}, c{}, disc{};
};

// q = −(b + sign(b)·√disc), from which the roots are c/q and q/a: neither subtracts nearly
// equal numbers.
template <typename T>
T stable_q(const Quadratic<T>& k, T root) {
  return -(k.b + sign_of(k.b) * root);
}

// Both roots of a quadratic with disc > 0, ascending, root = √disc.
template <typename T>
[[gnu::always_inline]] inline Roots<T> both_roots(const Quadratic<T>& k, T root) {
  T q = stable_q(k, root);
  Roots<T> out;
  out.count = 2;
  out.t0 = k.c / q;
  out.t1 = q / k.a;
  if (out.t1 < out.t0) std::swap(out.t0, out.t1);
  return out;
}

// The nearest root at t ≥ 0 of a quadratic with disc > 0 and c ≠ 0, in one division: the signs
// of b and c say which root it is. For b < 0, q > 0 and c/q ≤ q/a; for b ≥ 0, q < 0 and
// q/a < 0. When c < 0 (the origin inside) the roots have opposite signs and the positive one is
// q/a or c/q; when c > 0 they have the sign of −b. False when both roots are negative.
template <typename T>
[[gnu::always_inline]] inline bool nearest_root(const Quadratic<T>& k, T root, T& t) {
  bool approaching = k.b < T(0);
  if (k.c > T(0) && !approaching) return false;
  T q = stable_q(k, root);
  t = approaching == (k.c < T(0)) ? q / k.a : k.c / q;
  return true;
}

// The nearest root at t ≥ 0 of ascending roots: true with it in `t`, false if there is none.
template <typename T>
bool nearest_root(const Roots<T>& r, T& t) {
  if (r.count == 0) return false;
  if (r.t0 >= T(0)) {
    t = r.t0;
    return true;
  }
  if (r.t1 >= T(0)) {
    t = r.t1;
    return true;
  }
  return false;
}

// What a fast path found: a certain miss, a quadratic whose roots decide hit or miss, and which
// root is nearest, as exact arithmetic would, or nothing certain (the compensated formulas run).
enum class FastPath { kUndecided, kMiss, kRoots };

// The sphere's quadratic in plain arithmetic (dot and cross products fused, dot_fused and
// cross_fused), kept when the a-posteriori error bounds of the
// quarter discriminant a·r² − |f × d|² (which does not cancel for far spheres) and of
// c = f·f − r² are within kFastPathTolerance τ of them (docs/precision.md, "Fast paths").
// (The textbook b² − a·c would be cheaper, but near a tangent its error grows faster than the
// condition number of t: the hard cases catch it.) This first test takes a few operations on
// magnitudes at hand, and its clauses are joined without short circuits: a branch per clause
// costs more than the clause. The rays it leaves undecided (grazing ones, far spheres) go to
// sphere_roots_slow. The sign of disc, hit or miss, is tested before it: that branch
// goes wrong about as often as rays miss, and the earlier it comes in the instruction stream,
// the sooner the processor recovers.
template <typename T>
[[gnu::always_inline]] inline FastPath sphere_quadratic_fast(const Vec3<T>& o, const Vec3<T>& d,
                                                             const Vec3<T>& center, T r,
                                                             Quadratic<T>& out) {
  using std::abs;
  constexpr T lo = T(1) / kFastPathRange<T>, hi = kFastPathRange<T> * kFastPathRange<T>;
  Vec3<T> f = o - center;
  T a = dot_fused(d, d), ff = dot_fused(f, f), rr = r * r;
  Vec3<T> x = cross_fused(f, d);
  T s2 = dot_fused(x, x), disc = a * rr - s2;
  T m = ff + rr, am = a * m;
  // a and r² are normal numbers, and no product overflows. (Two comparisons rather than
  // min(a, r²) ≥ lo: then the compiler evaluates the test once, beside the discriminant,
  // before the branch on its sign; with the min it evaluated it after the branch, on each
  // side, and the sphere cost about 1.7 times as much on ordinary rays.)
  auto certain = [&] {
    return (a >= lo) & (rr >= lo) & (am <= hi) & (abs(disc) >= kSphereDisc<T> * am);
  };
  if (disc < T(0)) return certain() ? FastPath::kMiss : FastPath::kUndecided;
  T b = dot_fused(f, d), c = ff - rr;
  if (!(certain() & (abs(c) >= kSphereC<T> * m))) return FastPath::kUndecided;
  out = Quadratic<T>{a, b, c, disc};
  return FastPath::kRoots;
}

// The stable reference: roots of |o + t d − c|² = r² (Ray Tracing Gems, ch. 7). The quarter
// discriminant is a·r² − |f × d|², which does not cancel for far spheres; the roots are
// q/a and c/q with q = −(b + sign(b)√Δ), which never subtracts nearly equal numbers. The plain
// computation is kept when its error bounds allow (sphere_quadratic_fast); otherwise f = o − c is
// split exactly and the cross product and c are compensated.
template <typename T>
[[gnu::noinline]] Roots<T> sphere_roots_accurate(const Vec3<T>& o, const Vec3<T>& d,
                                                 const Vec3<T>& center, T r);

// The rays the fast path leaves undecided: its plain quadratic when the second test, with the
// bound that follows the cross product's cancellation, certifies it; the compensated formulas
// otherwise. Out of line, so that the fast path stays short where it is inlined.
template <typename T>
[[gnu::noinline]] Roots<T> sphere_roots_slow(const Vec3<T>& o, const Vec3<T>& d,
                                             const Vec3<T>& center, T r) {
  using std::abs, std::sqrt;
  if constexpr (ScalesByPowersOfTwo<T>) {
    if (int k = scale_exponent(d); k < -kRescaleExponent || k > kRescaleExponent)
      return roots_scaled_back(sphere_roots_slow(o, scaled_by_power_of_two(d, -k), center, r), k);
  }
  if constexpr (kErrorFree<T>) {
    Vec3<T> f = o - center;
    T a = dot(d, d), ff = dot(f, f), rr = r * r;
    T s2 = length_squared(cross(f, d)), disc = a * rr - s2;
    if (discriminant_certain(f, d, a, ff, rr, s2, disc)) {
      if (disc < T(0)) return Roots<T>{};
      T b = dot(f, d), c = ff - rr;
      if (abs(c) >= kSphereC<T> * (ff + rr))
        return both_roots(Quadratic<T>{a, b, c, disc}, sqrt(disc));
    }
  }
  return sphere_roots_accurate(o, d, center, r);
}

template <typename T>
[[gnu::noinline]] bool sphere_nearest_slow(const Vec3<T>& o, const Vec3<T>& d,
                                           const Vec3<T>& center, T r, T& t) {
  return nearest_root(sphere_roots_slow(o, d, center, r), t);
}

template <typename T>
[[gnu::always_inline]] inline Roots<T> sphere_roots(const Vec3<T>& o, const Vec3<T>& d,
                                                    const Vec3<T>& center, T r) {
  using std::sqrt;
  if constexpr (kErrorFree<T>) {
    Quadratic<T> k;
    FastPath fast = sphere_quadratic_fast(o, d, center, r, k);
    if (fast == FastPath::kMiss) return Roots<T>{};
    if (fast == FastPath::kRoots) return both_roots(k, sqrt(k.disc));
  }
  return sphere_roots_slow(o, d, center, r);
}

// The nearest hit at t ≥ 0 by the same formulas, dividing only for that root: true with it in
// `t`, false for a miss.
template <typename T>
[[gnu::always_inline]] inline bool sphere_nearest(const Vec3<T>& o, const Vec3<T>& d,
                                                  const Vec3<T>& center, T r, T& t) {
  using std::sqrt;
  if constexpr (kErrorFree<T>) {
    Quadratic<T> k;
    FastPath fast = sphere_quadratic_fast(o, d, center, r, k);
    if (fast == FastPath::kMiss) return false;
    if (fast == FastPath::kRoots) return nearest_root(k, sqrt(k.disc), t);
  }
  return sphere_nearest_slow(o, d, center, r, t);
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

struct AccuracyCase;
class SplitMix;

// The nearest root at t ≥ 0 of t0 ≤ t1 as a textbook takes it, if any.
template <typename T>
std::optional<T> naive_nearest_root(T t0, T t1) {
  if (t0 >= T(0)) return t0;
  if (t1 >= T(0)) return t1;
  return std::nullopt;
}

// The nearest root at t ≥ 0 of a t² + b t + c = 0 as a textbook takes it: discriminant
// b² − 4ac, roots (−b ± √Δ)/2a.
template <typename T>
std::optional<T> naive_quadratic_nearest(T a, T b, T c) {
  using std::sqrt;
  T disc = b * b - T(4) * a * c;
  if (disc < T(0)) return std::nullopt;
  T s = sqrt(disc);
  return naive_nearest_root((-b - s) / (T(2) * a), (-b + s) / (T(2) * a));
}

// Calls add(t, normal_at(t)) for each root.
template <typename T, typename Add, typename Normal>
void add_roots(const Roots<T>& k, Add&& add, Normal&& normal_at) {
  if (k.count >= 1) add(k.t0, normal_at(k.t0));
  if (k.count == 2) add(k.t1, normal_at(k.t1));
}

class Sphere final : public Shape {
 public:
  // What the accuracy study needs of a sphere (shapes/ladder_primitives.h).
  struct Ladder;

  Sphere(Vec3d center, double radius) : center_(center), radius_(radius) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "sphere";
  static constexpr std::string_view kSummary = "center, radius";
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
  bool solid() const override { return true; }
  static constexpr std::string_view kNormalMistake = "inward-normal";
  static constexpr std::string_view kNormalSentence = " A sphere's outward normal is (P − C)/r.";
  std::optional<QuadraticSteps> quadratic() const override { return QuadraticSteps{"algebraic"}; }
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

// The case's points: {center}; its radius.
struct Sphere::Ladder {
  static constexpr std::size_t kPoints = 1;
  static constexpr bool kMorePoints = false, kRadius = true;
  static constexpr int kDirectionPoint = -1;

  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& r, T& t) {
    return sphere_nearest(o, d, p[0], r, t);
  }

  // The static filter: the first test of the fast path (sphere_quadratic_fast), whose bounds
  // make the sign of disc, of c and of b certain. Its t is the reference's own, q/a or c/q:
  // c is within τ of c*, and q = −(b + sign(b)√disc) within τ + 2^-44 of q* (√disc within τ, b
  // within 4u|f||d| ≤ 2^-44·|q| since √disc ≥ √(33u/τ)·|f||d|), a within 3u: a quotient error
  // of at most 2.2τ (docs/precision.md). Its bounds are fixed (`bound_scale` is not applied).
  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double r,
                                            FilterAnswer& out, double /*bound_scale*/) {
    Quadratic<double> k;
    FastPath fast = sphere_quadratic_fast(o, d, p[0], r, k);
    if (fast == FastPath::kUndecided) return false;
    out = {};
    double t = 0;
    if (fast == FastPath::kMiss || !nearest_root(k, std::sqrt(k.disc), t)) return true;
    out.hit = true;
    return enclose_quotient(t, kFilterError, 1, out);
  }
  // The relative error of either quotient of the fast path's quadratic, q/a or c/q (above).
  static constexpr double kFilterError = 2.2 * kFastPathTolerance<double>;

  // a t² + b t + c = 0 with b = 2 d·(o − c), discriminant b² − 4ac, roots (−b ± √Δ)/2a.
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& r) {
    Vec3<T> f = o - p[0];
    return naive_quadratic_nearest(dot(d, d), T(2) * dot(f, d), dot(f, f) - r * r);
  }

  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p, const T& r,
                   Add&& add) {
    add_roots(sphere_roots(o, d, p[0], r), add, [&](const T& t) { return o + t * d - p[0]; });
  }

  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double r,
                                           const Vec3d& point) {
    return (point - p[0]) / r;
  }

  static bool case_of(const Sphere& s, std::vector<Vec3d>& points, double& radius) {
    points = {s.center_};
    radius = s.radius_;
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double r) {
    return std::make_unique<Sphere>(p[0], r);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Round 0: far and huge spheres, grazing rays; 1: exact tangents; 2: beyond double-double,
  // origins on the surface; 3: more origins on the surface; 7: extreme direction scales;
  // 8: small far spheres.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
