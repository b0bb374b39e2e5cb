// Triangle: vertices a, b, c; watertight reference test; edge-test derivation.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "math/robust.h"
#include "sampling/outcome.h"
#include "shapes/filter_answer.h"
#include "shapes/plane.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

template <typename T>
struct TriangleHit {
  bool hit = false;
  T t{};
  std::array<T, 3> barycentric{};  // weights of a, b, c
  // For a hit the static filter decided: a bound on the relative errors of t's numerator and
  // denominator, summed (t = numerator/denominator); 0 from the sheared test.
  T t_quotient_error{};
};

// The sheared 2D coordinates of a vertex (x, y) and its unsheared ones (X, Y, Z).
template <typename T>
struct ShearedVertex {
  T x, y, X, Y, Z;
};

// Sets to zero the edge functions u, v, w that lie within their rounding error of zero. A
// sheared coordinate X − s·Z is exact up to kEdgeUlps of |X| + |s·Z| (the shear factor, the
// product and the difference each round once), and the error of an edge function
// p.x·q.y − p.y·q.x is that error times the other vertex's coordinates. Number types without
// a numeric_limits epsilon (the exact or multiple-precision ones) keep the exact test.
template <typename T>
void snap_edge_functions(T& u, T& v, T& w, const ShearedVertex<T>& a, const ShearedVertex<T>& b,
                         const ShearedVertex<T>& c, T sx, T sy) {
  using std::abs;
  constexpr int kEdgeUlps = 8;
  const T eps = std::numeric_limits<T>::epsilon();
  if (!(eps > T(0))) return;
  auto error = [&](const ShearedVertex<T>& p) {
    return std::max(abs(p.X) + abs(sx * p.Z), abs(p.Y) + abs(sy * p.Z)) * T(kEdgeUlps) * eps;
  };
  auto bound = [&](const ShearedVertex<T>& p, const ShearedVertex<T>& q) {
    return error(p) * (abs(q.x) + abs(q.y)) + error(q) * (abs(p.x) + abs(p.y));
  };
  if (abs(u) <= bound(c, b)) u = T(0);
  if (abs(v) <= bound(a, c)) v = T(0);
  if (abs(w) <= bound(b, a)) w = T(0);
}

// The two error bounds the triangle's filter tries, both derived in docs/precision.md. Each of
// its quantities is a triple product x·(y × z) of three of D and the rounded differences
// e₁ = b − a, e₂ = c − a, s = O − a, whose six terms x_i·y_j·z_k each carry at most 8 roundings
// (3 differences; the cross product's product and fused step; the dot product's product and two
// fused steps): its error is at most γ₈ < 8.001u times Σ|x_i||y_j||z_k|.
enum class TriangleBound {
  // 50u·X·Y·Z for all four, X the largest |x-coordinate| of D, e₁, e₂ and s (likewise Y, Z): each
  // term takes one coordinate of each axis, so Σ ≤ 6·X·Y·Z. Cheap, and tried first; but D's
  // scale enters it cubed where the quantities have it once, so it leaves rays whose direction
  // is far longer than the triangle to the second.
  kAxes,
  // 12u·‖D‖₁·M² for det, U and V and 12u·M³ for t's numerator, M the largest 1-norm of e₁, e₂
  // and s: Σ is at most the product of the three 1-norms.
  kNorms,
};
inline constexpr int kTriangleAxesUlps = 50, kTriangleNormsUlps = 12;

// e₁ = b − a, e₂ = c − a, s = O − a, and the axes' largest magnitudes of D, e₁, e₂ and s (X, Y,
// Z): the first bound's inputs. In double on x86-64, each vector's x and y in one SSE2 register,
// which halves the differences, magnitudes and maxima of those two axes (and the loads of the
// inputs); the values are the same either way.
template <typename T>
[[gnu::always_inline]] inline Vec3<T> differences_and_axes(const Vec3<T>& o, const Vec3<T>& d,
                                                           const Vec3<T>& a, const Vec3<T>& b,
                                                           const Vec3<T>& c, Vec3<T>& e1,
                                                           Vec3<T>& e2, Vec3<T>& s) {
  using std::abs;
  auto larger = [](T x, T y) { return x > y ? x : y; };
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, double>) {
    static_assert(sizeof(Vec3<double>) == 3 * sizeof(double), "x, y, z contiguous");
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffff));
    auto xy = [](const Vec3<double>& v) { return _mm_loadu_pd(&v.x); };
    auto high = [](__m128d v) { return _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); };
    __m128d a_xy = xy(a), e1_xy = _mm_sub_pd(xy(b), a_xy), e2_xy = _mm_sub_pd(xy(c), a_xy),
            s_xy = _mm_sub_pd(xy(o), a_xy);
    e1 = {_mm_cvtsd_f64(e1_xy), high(e1_xy), b.z - a.z};
    e2 = {_mm_cvtsd_f64(e2_xy), high(e2_xy), c.z - a.z};
    s = {_mm_cvtsd_f64(s_xy), high(s_xy), o.z - a.z};
    __m128d axes =
        _mm_max_pd(_mm_max_pd(_mm_and_pd(xy(d), magnitude), _mm_and_pd(e1_xy, magnitude)),
                   _mm_max_pd(_mm_and_pd(e2_xy, magnitude), _mm_and_pd(s_xy, magnitude)));
    return {_mm_cvtsd_f64(axes), high(axes),
            larger(larger(abs(d.z), abs(e1.z)), larger(abs(e2.z), abs(s.z)))};
  }
#endif
  e1 = b - a, e2 = c - a, s = o - a;
  auto axis = [&](T dx, T x1, T x2, T sx) {
    return larger(larger(abs(dx), abs(x1)), larger(abs(x2), abs(sx)));
  };
  return {axis(d.x, e1.x, e2.x, s.x), axis(d.y, e1.y, e2.y, s.y), axis(d.z, e1.z, e2.z, s.z)};
}

// The triangle's static filter: Möller and Trumbore's formulation (JGT 2(1), 1997), with fused
// products, and a forward error bound on each quantity that decides. det = e₁·(D × e₂) (zero
// when the ray is parallel to the plane), the barycentric numerators U = s·(D × e₂),
// V = D·(s × e₁) and W = det − U − V (weights of b, c and a times det), and t's numerator
// e₂·(s × e₁). When det and every numerator the decision rests on lie farther from zero than
// their bounds, their signs are those of exact arithmetic on the same inputs, so the decision is
// exact: true with `out` set. t is kept when its relative error is within kFastPathTolerance.
// Otherwise false: the caller tries the other bound, then the sheared test. A decision it makes
// is never a miss of a closed triangle the ray meets exactly, so mixing the two keeps a mesh
// watertight (docs/precision.md). `bound_scale` multiplies every bound: 1 but in the test that
// shows a smaller bound is caught.
template <TriangleBound Kind, typename T>
[[gnu::always_inline]] inline bool filtered_triangle(const Vec3<T>& o, const Vec3<T>& d,
                                                     const Vec3<T>& a, const Vec3<T>& b,
                                                     const Vec3<T>& c, TriangleHit<T>& out,
                                                     T bound_scale = T(1)) {
  using std::abs;
  auto larger = [](T x, T y) { return x > y ? x : y; };
  Vec3<T> e1, e2, s;
  if constexpr (Kind == TriangleBound::kNorms) e1 = b - a, e2 = c - a, s = o - a;
  // B for det, U and V, and t's numerator's. Magnitudes at most kFastPathRange (2^254 in double)
  // keep every product of three finite. Both are at least kTiny (2^-762), which the absolute
  // errors of underflow (at most 2^-1074 an operation) cannot reach; a product that underflows on
  // the way to a bound leaves it below kTiny (no factor exceeds 2^254, and the constant comes
  // last), so the floor then holds it.
  constexpr T kHuge = kFastPathRange<T>, kTiny = T(1) / (kHuge * kHuge * kHuge);
  T bound, t_bound;
  if constexpr (Kind == TriangleBound::kAxes) {
    auto [x, y, z] = differences_and_axes(o, d, a, b, c, e1, e2, s);
    if (!(larger(larger(x, y), z) <= kHuge)) return false;
    bound = t_bound =
        larger(x * y * z * (T(kTriangleAxesUlps) * kUnitRoundoff<T> * bound_scale), kTiny);
  } else {
    T nd = norm1(d), m = larger(larger(norm1(e1), norm1(e2)), norm1(s));
    if (!(larger(nd, m) <= kHuge)) return false;
    const T k = T(kTriangleNormsUlps) * kUnitRoundoff<T> * bound_scale;
    bound = larger(nd * m * m * k, kTiny);
    t_bound = larger(m * m * m * k, kTiny);
  }
  // Decide the plane: det's sign, then every numerator taken with that sign (an exact flip).
  Vec3<T> p = cross_fused(d, e2);
  T det = dot_fused(e1, p);
  T abs_det = abs(det);
  if (!(abs_det > bound)) return false;
  // Edge tests: a numerator certainly of the other sign than det is an exact miss. (Written as a
  // choice on det's sign, which compiles to a branch that resolves as soon as det is known.)
  bool positive = det > T(0);
  T U = dot_fused(s, p);
  if (positive ? U < -bound : U > bound) return true;
  Vec3<T> q = cross_fused(s, e1);
  T V = dot_fused(d, q);
  if (positive ? V < -bound : V > bound) return true;
  // W's bound adds the two subtractions' rounding, 2.01u(|det| + |U| + |V|), less than B (at
  // most 36.3u·X·Y·Z, or 6.01u·‖D‖₁·M²), to the three bounds.
  T sign = std::copysign(T(1), det);
  T u = sign * U, v = sign * V, w = abs_det - u - v;
  if (w < T(-4) * bound) return true;
  if (!((u > bound) & (v > bound) & (w > T(4) * bound))) return false;
  // Compute t: e₂·(s × e₁)/det, kept when both are far from zero next to their bounds.
  T t_num = dot_fused(e2, q);
  constexpr T kTolerance = kFastPathTolerance<T>;
  if (!((abs(t_num) * kTolerance > t_bound) & (abs_det * kTolerance > bound))) return false;
  T inv = T(1) / abs_det;
  out.hit = true;
  out.t = sign * t_num * inv;
  out.barycentric = {w * inv, u * inv, v * inv};
  out.t_quotient_error = t_bound / abs(t_num) + bound / abs_det;
  return true;
}

// Watertight ray-triangle test (Woop, Benthin and Wald, JCGT 2(1), 2013): the ray is sheared
// to the +z axis and the edge functions are evaluated in 2D, so that a ray through an edge or
// vertex shared by two triangles never misses both. Edge functions that come out exactly zero
// are recomputed with an FMA difference of products, whose sign is exact. Not inlined: it runs
// only on the rays the filter leaves (see watertight_triangle).
template <typename T>
[[gnu::noinline]] TriangleHit<T> sheared_triangle(const Vec3<T>& o, const Vec3<T>& d,
                                                  const Vec3<T>& a, const Vec3<T>& b,
                                                  const Vec3<T>& c) {
  TriangleHit<T> out;
  int kz = max_dimension(d);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (d[kz] < T(0)) std::swap(kx, ky);
  T sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = T(1) / d[kz];
  Vec3<T> A = a - o, B = b - o, C = c - o;
  T ax = A[kx] - sx * A[kz], ay = A[ky] - sy * A[kz];
  T bx = B[kx] - sx * B[kz], by = B[ky] - sy * B[kz];
  T cx = C[kx] - sx * C[kz], cy = C[ky] - sy * C[kz];
  T u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
  if (u == T(0) || v == T(0) || w == T(0)) {
    u = difference_of_products(cx, by, cy, bx);
    v = difference_of_products(ax, cy, ay, cx);
    w = difference_of_products(bx, ay, by, ax);
  }
  // Closed triangle: an edge function within its rounding error of zero is zero, so that a
  // ray through an edge or vertex hits, whatever the shear's rounding.
  snap_edge_functions(u, v, w, {ax, ay, A[kx], A[ky], A[kz]}, {bx, by, B[kx], B[ky], B[kz]},
                      {cx, cy, C[kx], C[ky], C[kz]}, sx, sy);
  // Signs combined without short circuits: one branch, which goes wrong as often as rays miss,
  // rather than up to six. (Each comparison named first: for a T whose comparison is a call,
  // clang warns of a bitwise | on its result.)
  bool u_negative = u < T(0), v_negative = v < T(0), w_negative = w < T(0);
  bool u_positive = u > T(0), v_positive = v > T(0), w_positive = w > T(0);
  bool negative = u_negative | v_negative | w_negative;
  bool positive = u_positive | v_positive | w_positive;
  if (negative & positive) return out;
  T det = u + v + w;
  if (det == T(0)) return out;
  out.hit = true;
  out.barycentric = {u / det, v / det, w / det};
  if constexpr (kErrorFree<T>) {
    // Fast path: the sheared t is as accurate as its edge functions, which lose nothing when
    // det = u + v + w is not small next to their products (see kNoCancellation). The six
    // products' magnitudes are bounded by one product of sums, (Σ|x|)(Σ|y|), which is cheaper.
    using std::abs;
    T size = (abs(ax) + abs(bx) + abs(cx)) * (abs(ay) + abs(by) + abs(cy));
    if (abs(det) >= T(kNoCancellation) * size) {
      T az = sz * A[kz], bz = sz * B[kz], cz = sz * C[kz];
      out.t = (u * az + v * bz + w * cz) / det;
      return out;
    }
  }
  // t from the plane, with compensated products: the sheared formula (u·az + v·bz + w·cz)/det
  // loses digits in proportion to how thin the triangle is (a needle's det is tiny), the
  // plane's does not. The sheared one remains for a plane the rounding makes parallel.
  Vec3<T> ab_hi, ab_lo, ac_hi, ac_lo;
  difference_exact(b, a, ab_hi, ab_lo);
  difference_exact(c, a, ac_hi, ac_lo);
  Vec3<T> n = cross_accurate(ab_hi, ac_hi) + (cross(ab_lo, ac_hi) + cross(ab_hi, ac_lo));
  T den = dot_accurate(n, d);
  if (den == T(0)) {
    T az = sz * A[kz], bz = sz * B[kz], cz = sz * C[kz];
    out.t = (u * az + v * bz + w * cz) / det;
  } else {
    Vec3<T> f, f_lo;
    difference_exact(a, o, f, f_lo);
    out.t = (dot_accurate(n, f) + dot(n, f_lo)) / den;
  }
  return out;
}

// The static filter with the second bound where the first cannot decide, then the sheared
// watertight test: the reference test's path after its first bound (float and double). Not
// inlined, so that the first bound's path keeps no frame.
template <typename T>
[[gnu::noinline]] TriangleHit<T> triangle_after_axes(const Vec3<T>& o, const Vec3<T>& d,
                                                     const Vec3<T>& a, const Vec3<T>& b,
                                                     const Vec3<T>& c) {
  TriangleHit<T> out;
  if (filtered_triangle<TriangleBound::kNorms>(o, d, a, b, c, out)) return out;
  return sheared_triangle(o, d, a, b, c);
}

// The reference ray-triangle test: in float and double the static filter (filtered_triangle)
// answers, with its cheap bound and then its other, and the sheared watertight test runs on the
// few rays it cannot decide; other number types run the sheared test.
template <typename T>
[[gnu::always_inline]] inline TriangleHit<T> watertight_triangle(const Vec3<T>& o, const Vec3<T>& d,
                                                                 const Vec3<T>& a, const Vec3<T>& b,
                                                                 const Vec3<T>& c) {
  if constexpr (kErrorFree<T>) {
    TriangleHit<T> out;
    if (filtered_triangle<TriangleBound::kAxes>(o, d, a, b, c, out)) return out;
    return triangle_after_axes(o, d, a, b, c);
  }
  return sheared_triangle(o, d, a, b, c);
}

class Triangle final : public Shape {
 public:
  // What the accuracy study needs of a triangle (shapes/ladder_primitives.h).
  struct Ladder;

  Triangle(Vec3d a, Vec3d b, Vec3d c) : v_{a, b, c} {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "triangle";
  static constexpr std::string_view kSummary = "vertices [a, b, c]";
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator: the outcomes it can build, and a problem for one of them (a random one when none
  // is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // Its hits carry barycentric weights (w_a, w_b, w_c), which answer forms ask for
  // (hits_have_barycentric, shapes/primitives.h).
  static constexpr bool kBarycentric = true;
  // The normal kind: the part of its surface nearest to the object-space point p, with the outward
  // normal there (`tie`: how near two parts must both be for p to lie where they meet), and the
  // steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
  // A normal the other way is the cross product's factors swapped.
  static constexpr std::string_view kNormalMistake = "cross-order";
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"edge-tests"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return (v_[0] + v_[1] + v_[2]) / 3.0; }
  double extent() const override;
  void sketch(Sketch& figure, const std::string& label) const override;

  const std::array<Vec3d, 3>& vertices() const { return v_; }

 private:
  std::array<Vec3d, 3> v_;
};

// The case's points: {a, b, c}; no radius.
struct Triangle::Ladder {
  static constexpr std::size_t kPoints = 3;
  static constexpr bool kMorePoints = false, kRadius = false;
  static constexpr int kDirectionPoint = -1;

  // watertight_triangle: the filter's first bound, and the rest (its second bound, then the
  // sheared test) a call of its own at the end, so that the first bound's path keeps no frame.
  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& /*r*/,
                                               T& t) {
    if constexpr (kErrorFree<T>) {
      TriangleHit<T> h;
      if (filtered_triangle<TriangleBound::kAxes>(o, d, p[0], p[1], p[2], h)) {
        if (!h.hit || !(h.t >= T(0))) return false;
        t = h.t;
        return true;
      }
    }
    return reference_after_axes(o, d, p, t);
  }
  template <typename T>
  [[gnu::noinline]] static bool reference_after_axes(const Vec3<T>& o, const Vec3<T>& d,
                                                     const std::vector<Vec3<T>>& p, T& t) {
    TriangleHit<T> h;
    if constexpr (kErrorFree<T>) {
      h = triangle_after_axes(o, d, p[0], p[1], p[2]);
    } else {
      h = sheared_triangle(o, d, p[0], p[1], p[2]);
    }
    if (!h.hit || !(h.t >= T(0))) return false;
    t = h.t;
    return true;
  }

  // The static filter: filtered_triangle's exact decision, and its t (the reference's own)
  // enclosed; a decided hit behind the origin (t < 0, a certain sign) is a miss.
  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double /*r*/,
                                            FilterAnswer& out, double bound_scale) {
    TriangleHit<double> h;
    if (!filtered_triangle<TriangleBound::kAxes>(o, d, p[0], p[1], p[2], h, bound_scale) &&
        !filtered_triangle<TriangleBound::kNorms>(o, d, p[0], p[1], p[2], h, bound_scale)) {
      return false;
    }
    out = {};
    if (!h.hit || h.t < 0) return true;
    out.hit = true;
    return enclose_quotient(h.t, h.t_quotient_error, 2, out);
  }

  // Hit the plane, then test the point against each edge (≥ 0 is inside).
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& /*r*/) {
    const Vec3<T>&a = p[0], &b = p[1], &c = p[2];
    Vec3<T> n = cross(b - a, c - a);
    std::optional<T> t = naive_plane_t(o, d, n, a);
    if (!t) return std::nullopt;
    Vec3<T> q = o + *t * d;
    if (dot(cross(b - a, q - a), n) < T(0)) return std::nullopt;
    if (dot(cross(c - b, q - b), n) < T(0)) return std::nullopt;
    if (dot(cross(a - c, q - c), n) < T(0)) return std::nullopt;
    return *t;
  }

  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                   const T& /*r*/, Add&& add) {
    TriangleHit<T> h = watertight_triangle(o, d, p[0], p[1], p[2]);
    if (h.hit) add(h.t, cross(p[1] - p[0], p[2] - p[0]));
  }

  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double /*r*/,
                                           const Vec3d& /*point*/) {
    return normalized(cross(p[1] - p[0], p[2] - p[0]));
  }

  static bool case_of(const Triangle& tri, std::vector<Vec3d>& points, double& /*radius*/) {
    points.assign(tri.v_.begin(), tri.v_.end());
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double /*r*/) {
    return std::make_unique<Triangle>(p[0], p[1], p[2]);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Round 3: triangles sharing an edge or a vertex, the ray through it; 4: needles.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
