// Triangle: vertices a, b, c; watertight reference test; edge-test derivation.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "math/robust.h"
#include "sampling/outcome.h"
#include "shapes/plane.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

template <typename T>
struct TriangleHit {
  bool hit = false;
  T t{};
  std::array<T, 3> barycentric{};  // weights of a, b, c
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

// Watertight ray-triangle test (Woop, Benthin and Wald, JCGT 2(1), 2013): the ray is sheared
// to the +z axis and the edge functions are evaluated in 2D, so that a ray through an edge or
// vertex shared by two triangles never misses both. Edge functions that come out exactly zero
// are recomputed with an FMA difference of products, whose sign is exact.
template <typename T>
TriangleHit<T> watertight_triangle(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& a,
                                   const Vec3<T>& b, const Vec3<T>& c) {
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
  // rather than up to six.
  bool negative = (u < T(0)) | (v < T(0)) | (w < T(0));
  bool positive = (u > T(0)) | (v > T(0)) | (w > T(0));
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

  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& /*r*/,
                                               T& t) {
    TriangleHit<T> h = watertight_triangle(o, d, p[0], p[1], p[2]);
    if (!h.hit || !(h.t >= T(0))) return false;
    t = h.t;
    return true;
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
