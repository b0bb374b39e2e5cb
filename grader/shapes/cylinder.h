// Cylinder: base, axis, radius; infinite, or finite with an optional pair of caps.
#pragma once

#include <optional>

#include "derivation/mistake.h"
#include "sampling/outcome.h"
#include "shapes/filter_roots.h"
#include "shapes/sphere.h"
#include "shapes/surface_point.h"

namespace raygrade {

// Roots of the side's quadratic |f⊥ + t d⊥|² = r², where ⊥ removes the component along the
// unit axis. As for the sphere, the quarter discriminant is a·r² − ((f × d)·â)², which does
// not cancel, and the roots come from q = −(b + sign(b)√Δ). count 0 when the ray is parallel
// to the axis (a = 0).
// The compensated path of cylinder_side_roots (f = o − base, its part f⊥ across the axis,
// a = |d⊥|², b = f⊥·d⊥), out of line so that the fast path inlines where it is called.
template <typename T>
[[gnu::noinline]] Roots<T> cylinder_side_roots_accurate(const Vec3<T>& f, const Vec3<T>& d,
                                                        const Vec3<T>& fp, const Vec3<T>& axis, T a,
                                                        T b, T r) {
  using std::sqrt;
  Roots<T> out;
  T s = dot(cross_accurate(f, d), axis);
  T disc = a * (r * r) - s * s;
  if (disc < T(0)) return out;
  if (disc == T(0)) {
    out.count = 1;
    out.t0 = out.t1 = -b / a;
    return out;
  }
  T c = sum_of_squares_minus_square(fp, Vec3<T>{}, r);
  T q = -(b + sign_of(b) * sqrt(disc));
  T t0 = c / q, t1 = q / a;
  if (t1 < t0) std::swap(t0, t1);
  out.count = 2;
  out.t0 = t0;
  out.t1 = t1;
  return out;
}

// The rays the fast path below leaves undecided: the plain quadratic when the bound of
// s = (f × d)·â that follows the cross product's own cancellation certifies it, the compensated
// formulas otherwise. Out of line, so that the fast path stays short where it is inlined.
template <typename T>
[[gnu::noinline]] Roots<T> cylinder_side_roots_slow(const Vec3<T>& o, const Vec3<T>& d,
                                                    const Vec3<T>& base, const Vec3<T>& axis, T r) {
  using std::sqrt;
  if constexpr (ScalesByPowersOfTwo<T>) {
    if (int k = scale_exponent(d); k < -kRescaleExponent || k > kRescaleExponent) {
      return roots_scaled_back(
          cylinder_side_roots_slow(o, scaled_by_power_of_two(d, -k), base, axis, r), k);
    }
  }
  Vec3<T> f = o - base;
  Vec3<T> fp = f - dot(f, axis) * axis;
  Vec3<T> dp = d - dot(d, axis) * axis;
  T a = dot(dp, dp);
  Roots<T> out;
  if (a == T(0)) return out;
  T b = dot(fp, dp);
  if constexpr (kErrorFree<T>) {
    // Fast path: plain arithmetic, kept when the error bounds of s = (f × d)·â, of the quarter
    // discriminant and of c = |f⊥|² − r² show the decision certain and the roots within the
    // tolerance (docs/precision.md, "Fast paths"; the sphere's bounds, with s for |f × d|).
    using std::abs;
    constexpr T u = kUnitRoundoff<T>, tolerance = kFastPathTolerance<T>;
    T rr = r * r, ff = dot(fp, fp);
    bool in_range = in_fast_path_range(a) && in_fast_path_range(rr) && ff <= kFastPathRange<T> &&
                    dot(f, f) <= kFastPathRange<T>;
    T px = f.y * d.z, qx = f.z * d.y, py = f.z * d.x, qy = f.x * d.z, pz = f.x * d.y,
      qz = f.y * d.x;
    Vec3<T> fxd{px - qx, py - qy, pz - qz};
    T s = dot(fxd, axis);
    T s_error = T(3) * u *
                (abs(axis.x) * (abs(px) + abs(qx) + abs(fxd.x)) +
                 abs(axis.y) * (abs(py) + abs(qy) + abs(fxd.y)) +
                 abs(axis.z) * (abs(pz) + abs(qz) + abs(fxd.z)));
    T ar = a * rr, disc = ar - s * s, c = ff - rr;
    T e = T(7) * u * (ar + s * s) + T(2) * abs(s) * s_error + s_error * s_error;
    if (in_range && abs(c) * tolerance >= T(7) * u * (ff + rr) && abs(disc) > e) {
      if (disc < T(0)) return out;
      T root = sqrt(disc);
      if (e <= tolerance * (disc + abs(b) * root)) {
        T q = -(b + sign_of(b) * root);
        out.count = 2;
        out.t0 = c / q;
        out.t1 = q / a;
        if (out.t1 < out.t0) std::swap(out.t0, out.t1);
        return out;
      }
    }
  }
  return cylinder_side_roots_accurate(f, d, fp, axis, a, b, r);
}

// The constant of the cylinder's first test (docs/precision.md, "Fast paths"): the error of the
// quarter discriminant is at most 7u·a·r² + 25u·|f|²|d|², so |disc| ≥ kDisc(a·r² + |f|²|d|²)
// puts it within τ of disc; the test on c = |f⊥|² − r² is the sphere's.
template <typename T>
inline constexpr T kCylinderDisc = T(26) * kUnitRoundoff<T> / kFastPathTolerance<T>;

// The side's quadratic in plain arithmetic, kept when a first test on magnitudes at hand
// certifies the quarter discriminant a·r² − s², s = (f × d)·â, and c = |f⊥|² − r² within τ, as
// the sphere's fast path does (and shaped like it: the sign of disc first, the test's clauses
// without short circuits).
template <typename T>
[[gnu::always_inline]] inline FastPath cylinder_side_quadratic_fast(const Vec3<T>& o,
                                                                    const Vec3<T>& d,
                                                                    const Vec3<T>& base,
                                                                    const Vec3<T>& axis, T r,
                                                                    Quadratic<T>& out) {
  using std::abs;
  constexpr T lo = T(1) / kFastPathRange<T>, hi = kFastPathRange<T> * kFastPathRange<T>;
  Vec3<T> f = o - base;
  Vec3<T> fp = f - dot(f, axis) * axis;
  Vec3<T> dp = d - dot(d, axis) * axis;
  T a = dot(dp, dp), rr = r * r;
  T s = dot(cross(f, d), axis), ar = a * rr, disc = ar - s * s;
  T magnitude = ar + dot(f, f) * dot(d, d);
  // a and r² are normal numbers, and no product overflows (two comparisons, not a min: see
  // sphere_quadratic_fast).
  auto certain = [&] {
    return (a >= lo) & (rr >= lo) & (magnitude <= hi) & (abs(disc) >= kCylinderDisc<T> * magnitude);
  };
  if (disc < T(0)) return certain() ? FastPath::kMiss : FastPath::kUndecided;
  T ff = dot(fp, fp), c = ff - rr;
  if (!(certain() & (abs(c) >= kSphereC<T> * (ff + rr)))) return FastPath::kUndecided;
  out = Quadratic<T>{a, dot(fp, dp), c, disc};
  return FastPath::kRoots;
}

template <typename T>
[[gnu::noinline]] bool cylinder_side_nearest_slow(const Vec3<T>& o, const Vec3<T>& d,
                                                  const Vec3<T>& base, const Vec3<T>& axis, T r,
                                                  T& t) {
  return nearest_root(cylinder_side_roots_slow(o, d, base, axis, r), t);
}

template <typename T>
[[gnu::always_inline]] inline Roots<T> cylinder_side_roots(const Vec3<T>& o, const Vec3<T>& d,
                                                           const Vec3<T>& base, const Vec3<T>& axis,
                                                           T r) {
  using std::sqrt;
  if constexpr (kErrorFree<T>) {
    Quadratic<T> k;
    FastPath fast = cylinder_side_quadratic_fast(o, d, base, axis, r, k);
    if (fast == FastPath::kMiss) return Roots<T>{};
    if (fast == FastPath::kRoots) return both_roots(k, sqrt(k.disc));
  }
  return cylinder_side_roots_slow(o, d, base, axis, r);
}

// The nearest hit at t ≥ 0 on the side, dividing only for that root: true with it in `t`, false
// for a miss.
template <typename T>
[[gnu::always_inline]] inline bool cylinder_side_nearest(const Vec3<T>& o, const Vec3<T>& d,
                                                         const Vec3<T>& base, const Vec3<T>& axis,
                                                         T r, T& t) {
  using std::sqrt;
  if constexpr (kErrorFree<T>) {
    Quadratic<T> k;
    FastPath fast = cylinder_side_quadratic_fast(o, d, base, axis, r, k);
    if (fast == FastPath::kMiss) return false;
    if (fast == FastPath::kRoots) return nearest_root(k, sqrt(k.disc), t);
  }
  return cylinder_side_nearest_slow(o, d, base, axis, r, t);
}

// The side's quadratic for the static filter (docs/precision.md, "Static filters"), from an axis
// vector A of any length: with F = f × A, D = d × A and s = (f × d)·A, |(f + t d) × A|² = r²|A|²
// is a·t² + 2b·t + c = 0 with a = |D|², b = F·D, c = |F|² − r²|A|², and its quarter discriminant
// is |A|²·(r²a − s²) (as (F × D) = ((f × d)·A)·A): disc = r²a − s², which does not cancel for
// a far cylinder, and scale = |A|. Every quantity is a polynomial in the inputs, computed in
// double (dot_fused and cross_fused round no more often than the plain products), with the bound
// γ_n·(the same polynomial on magnitudes) on its error, n the most roundings on a path from an
// input to the result (Higham, Accuracy and Stability, 2nd ed., sec. 3.1). f = o − base counts one
// rounding, and so does A, which may itself be a rounded difference (the capsule's b − a): a has
// n = 9, b 10, c 12, disc 16; the bounds take (n + 1)·u, the extra u covering their own
// rounding. The magnitudes are bounded by 1-norms (filter_roots.h). |A| = √(A·A) is within 4u of
// the exact length. False when a vector's 1-norm or the radius lies beyond kFilterInputLimit.
[[gnu::always_inline]] inline bool cylinder_side_bounded(const Vec3d& o, const Vec3d& d,
                                                         const Vec3d& base, const Vec3d& axis,
                                                         double r, double bound_scale,
                                                         BoundedQuadratic& k) {
  constexpr double u = kUnitRoundoff<double>;
  Vec3d f = o - base;
  Vec3d dd = cross_fused(d, axis), ff = cross_fused(f, axis), fd = cross_fused(f, d);
  // Magnitudes: of D and F by 1-norms; of s = (f × d)·A component by component, since f and d
  // are nearly parallel for a ray aimed at the cylinder from afar, where the 1-norms would
  // overstate the discriminant's error most.
  Vec3d d_m = magnitudes(d), f_m = magnitudes(f), axis_m = magnitudes(axis);
  double n_d = norm1(d), n_f = norm1(f), n_axis = norm1(axis);
  if (!within_filter_limit(n_d, n_f, n_axis, r)) return false;
  double dd_m = n_d * n_axis, ff_m = n_f * n_axis;
  Vec3d fd_m{f_m.y * d_m.z + f_m.z * d_m.y, f_m.z * d_m.x + f_m.x * d_m.z,
             f_m.x * d_m.y + f_m.y * d_m.x};
  double s_m = dot_fused(fd_m, axis_m);
  double rr = r * r, aa = dot_fused(axis, axis), s = dot_fused(fd, axis);
  k.a = dot_fused(dd, dd);
  k.b = dot_fused(ff, dd);
  k.c = dot_fused(ff, ff) - rr * aa;
  k.disc = rr * k.a - s * s;
  k.scale = std::sqrt(aa);
  double slack = kFilterUnderflowSlack;
  k.a_error = (10 * u * (dd_m * dd_m) + slack) * bound_scale;
  k.b_error = (11 * u * (ff_m * dd_m) + slack) * bound_scale;
  k.c_error = (13 * u * (ff_m * ff_m + rr * aa) + slack) * bound_scale;
  k.disc_error = (17 * u * (rr * (dd_m * dd_m) + s_m * s_m) + slack) * bound_scale;
  return true;
}

class Cylinder final : public Shape {
 public:
  // What the accuracy study needs of a cylinder (shapes/ladder_primitives.h).
  struct Ladder;

  Cylinder(Vec3d base, Vec3d axis, double radius, std::optional<double> height, bool capped);
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "cylinder";
  static constexpr std::string_view kSummary = "base, axis, radius, optional height and caps";
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator: the outcomes it can build, and a problem for one of them (a random one when none
  // is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // Its own formula mistake (grading adds it to the catalogue): b without the origin's terms.
  static const std::vector<PrimitiveMistake>& mistakes();
  // The normal kind: the part of its surface nearest to the object-space point p, with the outward
  // normal there (`tie`: how near two parts must both be for p to lie where they meet), and the
  // steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
  // Closed when it has a height and both caps.
  bool solid() const override { return height_.has_value() && capped_; }
  static constexpr std::string_view kNormalMistake = "inward-normal";
  static constexpr std::string_view kNormalSentence =
      " A cylinder's side has the outward normal (P − Q)/r, Q the nearest point of the axis; "
      "a cap's is the axis direction, away from the cylinder.";
  static constexpr std::string_view kContainedLine =
      "The ray runs along the cylinder's side (its distance from the axis is r and it is "
      "parallel to the axis): it meets the side along a whole line";
  std::optional<QuadraticSteps> quadratic() const override { return QuadraticSteps{}; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"quadratic"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override;
  double extent() const override;
  void sketch(Sketch& figure, const std::string& label) const override;
  void sketch_symbols(Sketch& figure, const Ray& ray,
                      const std::vector<std::string>& symbols) const override;

 private:
  Vec3d base_;
  Vec3d axis_given_;
  Vec3d axis_;  // unit
  double radius_;
  std::optional<double> height_;
  bool capped_;
};

// The case's points: {base, axis} of an infinite side (the axis need not be unit: it is
// normalized at the precision of the computation); its radius. A cylinder with a height has no
// case.
struct Cylinder::Ladder {
  static constexpr std::size_t kPoints = 2;
  static constexpr bool kMorePoints = false, kRadius = true;
  static constexpr int kDirectionPoint = 1;

  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& r, T& t) {
    using std::sqrt;
    Vec3<T> axis = p[1] / sqrt(dot(p[1], p[1]));
    return cylinder_side_nearest(o, d, p[0], axis, r, t);
  }

  // The static filter: cylinder_side_bounded's quadratic, its roots enclosed (enclose_roots),
  // the nearest at t > 0. Its t is its own, not the reference's (which normalizes the axis).
  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double r,
                                            FilterAnswer& out, double bound_scale) {
    BoundedQuadratic k;
    EnclosedRoots roots;
    if (!cylinder_side_bounded(o, d, p[0], p[1], r, bound_scale, k) || !enclose_roots(k, roots))
      return false;
    NearestKept nearest;
    for (int i = 0; i < roots.count; ++i) {
      if (!nearest.keep(roots.root[i])) return false;
    }
    out = nearest.nearest;
    return true;
  }

  // The sphere's quadratic on the components across the unit axis.
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& r) {
    using std::sqrt;
    Vec3<T> axis = p[1] / sqrt(dot(p[1], p[1]));
    Vec3<T> f = o - p[0];
    Vec3<T> fp = f - dot(f, axis) * axis, dp = d - dot(d, axis) * axis;
    T a = dot(dp, dp), b = T(2) * dot(fp, dp), c = dot(fp, fp) - r * r;
    if (a == T(0)) return std::nullopt;
    return naive_quadratic_nearest(a, b, c);
  }

  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p, const T& r,
                   Add&& add) {
    using std::sqrt;
    Vec3<T> axis = p[1] / sqrt(dot(p[1], p[1]));
    add_roots(cylinder_side_roots(o, d, p[0], axis, r), add, [&](const T& t) {
      Vec3<T> v = o + t * d - p[0];
      return v - dot(v, axis) * axis;
    });
  }

  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double /*r*/,
                                           const Vec3d& point) {
    Vec3d axis = normalized(p[1]), v = point - p[0];
    return normalized(v - dot(v, axis) * axis);
  }

  static bool case_of(const Cylinder& c, std::vector<Vec3d>& points, double& radius) {
    if (c.height_) return false;
    points = {c.base_, c.axis_given_};
    radius = c.radius_;
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double r) {
    return std::make_unique<Cylinder>(p[0], p[1], r, std::nullopt, false);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Round 0: grazing rays; 1: exact tangents; 2: an origin on the surface; 6: rays along the
  // axis; 8: thin far cylinders.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
