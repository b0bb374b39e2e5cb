// Plane: point and normal, or normal and d with n·p + d = 0.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>

#include "derivation/mistake.h"
#include "math/robust.h"
#include "sampling/outcome.h"
#include "shapes/filter_answer.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

// The parameter t where the ray meets the plane through p with normal n: n·(p − o) / (n·d),
// with p − o split exactly and both dot products compensated, so that a ray nearly parallel
// to the plane (n·d around 1e-12) keeps the digits of its denominator. No value when n·d = 0.
// The compensated path of plane_t, kept out of line so that the fast path inlines where it
// is called: a call costs as much as the fast path's arithmetic.
template <typename T>
[[gnu::noinline]] std::optional<T> plane_t_accurate(const Vec3<T>& o, const Vec3<T>& d,
                                                    const Vec3<T>& n, const Vec3<T>& p) {
  T den = dot_accurate(n, d);
  if (den == T(0)) return std::nullopt;
  Vec3<T> f, f_lo;
  difference_exact(p, o, f, f_lo);
  T num = dot_accurate(n, f) + dot(n, f_lo);
  return num / den;
}

template <typename T>
inline std::optional<T> plane_t(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& n,
                                const Vec3<T>& p) {
  if constexpr (kErrorFree<T>) {
    // Fast path: plain dot products, kept when their error bounds show t = num/den within the
    // tolerance (docs/precision.md, "Fast paths"): |den − den*| ≤ 4u·Σ|n_i d_i| and, counting
    // the rounding of p − o, |num − num*| ≤ 5u·Σ|n_i f_i|.
    using std::abs;
    constexpr T u = kUnitRoundoff<T>;
    Vec3<T> f = p - o;
    T nd_x = n.x * d.x, nd_y = n.y * d.y, nd_z = n.z * d.z;
    T nf_x = n.x * f.x, nf_y = n.y * f.y, nf_z = n.z * f.z;
    T den = nd_x + nd_y + nd_z, num = nf_x + nf_y + nf_z;
    T den_error = T(4) * u * (abs(nd_x) + abs(nd_y) + abs(nd_z));
    T num_error = T(5) * u * (abs(nf_x) + abs(nf_y) + abs(nf_z));
    T size = abs(num) * abs(den);
    if (num_error * abs(den) + den_error * abs(num) < kFastPathTolerance<T> * size &&
        size >= T(1) / kFastPathRange<T>)
      return num / den;
    return plane_t_accurate(o, d, n, p);
  } else {
    return plane_t_accurate(o, d, n, p);
  }
}

// An upper bound on x/size, at most twice it, without dividing: x·2^-E where 2^E ≤ size <
// 2^(E+1) (E taken at most 1000, which only enlarges the bound), exact for a normal size in
// [2^-1022, ∞) when x·2^-E neither overflows nor underflows.
// (The bits go through memcpy, which compilers turn into a move: the WebAssembly toolchain's
// library has no std::bit_cast.)
inline double quotient_bound(double x, double size) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &size, sizeof bits);
  std::uint64_t exponent =
      std::min<std::uint64_t>(bits & 0x7ff0000000000000ull, std::uint64_t(1023 + 1000) << 52);
  bits = (std::uint64_t(2046) << 52) - exponent;
  double scale = 0;
  std::memcpy(&scale, &bits, sizeof scale);
  return x * scale;
}

// The plane's static filter: plane_t's fast path with its bounds (above),
// |den − den*| ≤ 4u·Σ|n_i d_i| and |num − num*| ≤ 5u·Σ|n_i f_i| (docs/precision.md), deciding
// only where the fast path keeps its t (within kFastPathTolerance), so that its t is the
// reference's own and the signs of num and den are certain. `bound_scale` multiplies the bounds
// (see filtered_double). The magnitudes must be at least kQuotientFloor, so that products that
// underflow (an absolute error of at most 2^-1075 each) stay far inside the bounds' slack; the
// test x < τ·size below already fails on every sum that is not finite (x is then infinite or
// NaN), and it shows e = x/size ≤ τ without dividing (τ·size is exact, and rounding is
// monotonic). `n_error`, when given, bounds per component how far n lies from the normal the
// decision is about (the rounding of a polygon's Newell normal): it adds Σ n_error_i·|d_i| to
// den's bound and Σ n_error_i·|f_i| (twice, for the rounding of f and of the bound) to num's,
// and the enlarged bounds, relative to |den| and |num| and summed, must still be within τ.
// True with num, den, and x = num_error·|den| + den_error·|num| and size = |num|·|den| (so
// that e = x/size bounds num's and den's relative errors, summed) in `q`.
struct PlaneQuotient {
  double num, den, x, size;
};
[[gnu::always_inline]] inline bool plane_quotient_filter(const Vec3d& o, const Vec3d& d,
                                                         const Vec3d& n, const Vec3d& p,
                                                         double bound_scale, PlaneQuotient& q,
                                                         const Vec3d* n_error = nullptr) {
  constexpr double u = kUnitRoundoff<double>, tau = kFastPathTolerance<double>;
  Vec3d f = p - o;
  double nd_x = n.x * d.x, nd_y = n.y * d.y, nd_z = n.z * d.z;
  double nf_x = n.x * f.x, nf_y = n.y * f.y, nf_z = n.z * f.z;
  double den = nd_x + nd_y + nd_z, num = nf_x + nf_y + nf_z;
  double den_size = std::abs(nd_x) + std::abs(nd_y) + std::abs(nd_z);
  double num_size = std::abs(nf_x) + std::abs(nf_y) + std::abs(nf_z);
  double den_error = 4 * u * den_size * bound_scale, num_error = 5 * u * num_size * bound_scale;
  double size = std::abs(num) * std::abs(den);
  double x = num_error * std::abs(den) + den_error * std::abs(num);
  // Decide as the fast path does, so that t is the reference's own (the clauses joined
  // without short circuits: each costs less than a branch).
  constexpr double kLeast = 1 / kFastPathRange<double>;
  bool decided = (x < tau * size) & (size >= kLeast) & (den_size >= kQuotientFloor) &
                 (num_size >= kQuotientFloor);
  if (n_error) {
    den_error +=
        (n_error->x * std::abs(d.x) + n_error->y * std::abs(d.y) + n_error->z * std::abs(d.z)) *
        bound_scale;
    num_error +=
        2 * (n_error->x * std::abs(f.x) + n_error->y * std::abs(f.y) + n_error->z * std::abs(f.z)) *
        bound_scale;
    x = num_error * std::abs(den) + den_error * std::abs(num);
    decided &= x < tau * size;
  }
  q = {num, den, x, size};
  return decided;
}

// True with the exact decision and t enclosed in `out`, where plane_quotient_filter decides. The
// decision does not wait for e's division: e ≤ τ is known (above), and only the enclosure's
// width takes e = x/size (its rounding, a few u of e, is inside the slack of enclose_quotient's
// 1.25 against 8/7).
[[gnu::always_inline]] inline bool plane_filter(const Vec3d& o, const Vec3d& d, const Vec3d& n,
                                                const Vec3d& p, FilterAnswer& out,
                                                double bound_scale,
                                                const Vec3d* n_error = nullptr) {
  PlaneQuotient q;
  if (!plane_quotient_filter(o, d, n, p, bound_scale, q, n_error)) return false;
  out = {};
  if ((q.num < 0) != (q.den < 0)) return true;  // t < 0, a certain sign: a miss
  out.hit = true;
  return enclose_quotient_within_limit(q.num / q.den, q.x / q.size, 1, out);
}

struct AccuracyCase;
class SplitMix;

// The textbook plane through p with normal n: t = n·(p − o) / n·d, at t ≥ 0.
template <typename T>
std::optional<T> naive_plane_t(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& n,
                               const Vec3<T>& p) {
  T den = dot(n, d);
  if (den == T(0)) return std::nullopt;
  T t = dot(n, p - o) / den;
  if (t < T(0)) return std::nullopt;
  return t;
}

class Plane final : public Shape {
 public:
  // What the accuracy study needs of a plane (shapes/ladder_primitives.h).
  struct Ladder;

  // Exactly one of `point` and `d` is set.
  Plane(Vec3d normal, std::optional<Vec3d> point, std::optional<double> d)
      : normal_(normal), point_(point), d_(d) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "plane";
  static constexpr std::string_view kSummary = "point and normal, or normal and d (n·p + d = 0)";
  // An unbounded flat surface splits space in two: in a scene it may bound a half-space.
  static constexpr bool kHalfSpace = true;
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator: the outcomes it can build, and a problem for one of them (a random one when none
  // is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // Its own formula mistake (grading adds it to the catalogue): D = +N·V0 in N·P + D = 0.
  static const std::vector<PrimitiveMistake>& mistakes();
  // The normal kind: the part of its surface nearest to the object-space point p, with the outward
  // normal there (`tie`: how near two parts must both be for p to lie where they meet), and the
  // steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
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

// The case's points: {normal, point}; no radius. A plane given by d has no case.
struct Plane::Ladder {
  static constexpr std::size_t kPoints = 2;
  static constexpr bool kMorePoints = false, kRadius = false;
  static constexpr int kDirectionPoint = 0;

  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& /*r*/,
                                               T& t) {
    std::optional<T> x = plane_t(o, d, p[0], p[1]);
    if (!x || !(*x >= T(0))) return false;
    t = *x;
    return true;
  }

  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double /*r*/,
                                            FilterAnswer& out, double bound_scale) {
    return plane_filter(o, d, p[0], p[1], out, bound_scale);
  }

  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& /*r*/) {
    return naive_plane_t(o, d, p[0], p[1]);
  }

  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                   const T& /*r*/, Add&& add) {
    if (std::optional<T> t = plane_t(o, d, p[0], p[1])) add(*t, p[0]);
  }

  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double /*r*/,
                                           const Vec3d& /*point*/) {
    return normalized(p[0]);
  }

  static bool case_of(const Plane& plane, std::vector<Vec3d>& points, double& /*radius*/) {
    if (!plane.point_) return false;
    points = {plane.normal_, *plane.point_};
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double /*r*/) {
    return std::make_unique<Plane>(p[0], p[1], std::nullopt);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Round 3: rays nearly parallel to the plane.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
