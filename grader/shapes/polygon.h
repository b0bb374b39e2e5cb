// Polygon: planar vertices, convex or not (a simple polygon).
#pragma once

#include <array>

#include "math/robust.h"
#include "sampling/outcome.h"
#include "shapes/filter_answer.h"
#include "shapes/flat.h"
#include "shapes/plane.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

// Does the ray pass through the closed polygon? The watertight test of the triangle, for any
// simple polygon: the vertices are sheared so that the ray runs along +z through (0, 0), and
// (0, 0) is tested against the projected polygon by crossing number, where each edge's
// crossing is decided by the sign of its edge function alone (no division). An edge shared
// by two polygons gets the same edge function up to sign, so a ray through it never misses
// both. A zero edge function with the origin between the edge's ends is on the boundary: hit.
template <typename T>
bool watertight_polygon(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& v) {
  int kz = max_dimension(d);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (d[kz] < T(0)) std::swap(kx, ky);
  T sx = d[kx] / d[kz], sy = d[ky] / d[kz];
  // Each vertex is sheared once, as the second end of one edge and the first of the next.
  auto sheared = [&](const Vec3<T>& vertex) {
    Vec3<T> w = vertex - o;
    return std::array<T, 2>{w[kx] - sx * w[kz], w[ky] - sy * w[kz]};
  };
  const std::array<T, 2> first = sheared(v[0]);
  std::array<T, 2> a = first;
  bool inside = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::array<T, 2> b = i + 1 < v.size() ? sheared(v[i + 1]) : first;
    T e = a[0] * b[1] - a[1] * b[0];
    if (e == T(0)) e = difference_of_products(a[0], b[1], a[1], b[0]);
    if (e == T(0)) {
      // (0, 0) is on the edge's line: on the edge itself when between its ends.
      bool between_x = (a[0] <= T(0) && T(0) <= b[0]) || (b[0] <= T(0) && T(0) <= a[0]);
      bool between_y = (a[1] <= T(0) && T(0) <= b[1]) || (b[1] <= T(0) && T(0) <= a[1]);
      if (between_x && between_y) return true;
    } else {
      // The edge crosses the x axis at e / (b_y − a_y): on the +x side when the signs agree.
      // (Without a branch: whether an edge crosses is as unpredictable as the ray.)
      bool a_up = a[1] > T(0), b_up = b[1] > T(0);
      inside ^= (a_up != b_up) & ((e > T(0)) == b_up);
    }
    a = b;
  }
  return inside;
}

// The polygon's static filter: plane_filter's decision and enclosure of t with the rounding of
// Newell's normal added to its bounds, then watertight_polygon's crossing count from the exact
// signs of every sheared vertex's y and every edge function, each taken from a product of the
// direction with the vertices' offsets from the origin whose bound it exceeds
// (docs/precision.md). True with the exact decision and t (the reference's own) enclosed in
// `out`. `bound_scale` multiplies the bounds (see filtered_double).
bool polygon_filter(const Vec3d& o, const Vec3d& d, const std::vector<Vec3d>& v, FilterAnswer& out,
                    double bound_scale);

class Polygon final : public Shape {
 public:
  // What the accuracy study needs of a polygon (shapes/ladder_primitives.h).
  struct Ladder;

  explicit Polygon(std::vector<Vec3d> vertices);
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "polygon";
  static constexpr std::string_view kSummary = "planar vertices, convex or not";
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
  // A normal the other way is the cross product's factors swapped.
  static constexpr std::string_view kNormalMistake = "cross-order";
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override;
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override;
  double extent() const override;
  void sketch(Sketch& figure, const std::string& label) const override;

  bool convex() const { return convex_; }

 private:
  std::vector<Vec3d> v_;
  // Newell's normal, by vertex order, computed in double-double and rounded once: far from
  // the origin (coordinates of 1e8) its sum of products cancels in double.
  Vec3d normal_;
  Vec3d unit_normal_;  // the same, normalized
  bool convex_;
};

// The case's points: its vertices (3 or more); no radius.
struct Polygon::Ladder {
  static constexpr std::size_t kPoints = 3;
  static constexpr bool kMorePoints = true, kRadius = false;
  static constexpr int kDirectionPoint = -1;

  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& /*r*/,
                                               T& t) {
    std::optional<T> x = plane_t(o, d, newell_normal_of(p), p[0]);
    if (!x || !(*x >= T(0)) || !watertight_polygon(o, d, p)) return false;
    t = *x;
    return true;
  }

  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double /*r*/,
                                            FilterAnswer& out, double bound_scale) {
    return polygon_filter(o, d, p, out, bound_scale);
  }

  // Hit the plane of the first three vertices, then count crossings of a ray along +u in the
  // projection that drops the normal's largest component.
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& v,
                                const T& /*r*/) {
    Vec3<T> n = cross(v[1] - v[0], v[2] - v[0]);
    std::optional<T> t = naive_plane_t(o, d, n, v[0]);
    if (!t) return std::nullopt;
    Vec3<T> q = o + *t * d;
    int drop = max_dimension(n), iu = (drop + 1) % 3, iv = (drop + 2) % 3;
    bool inside = false;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Vec3<T>& a = v[i];
      const Vec3<T>& b = v[(i + 1) % v.size()];
      if ((a[iv] > q[iv]) != (b[iv] > q[iv])) {
        T u = a[iu] + (q[iv] - a[iv]) * (b[iu] - a[iu]) / (b[iv] - a[iv]);
        if (q[iu] < u) inside = !inside;
      }
    }
    if (!inside) return std::nullopt;
    return *t;
  }

  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                   const T& /*r*/, Add&& add) {
    Vec3<T> n = newell_normal_of(p);
    std::optional<T> t = plane_t(o, d, n, p[0]);
    if (t && watertight_polygon(o, d, p)) add(*t, n);
  }

  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double /*r*/,
                                           const Vec3d& /*point*/) {
    return normalized(newell_normal(p));
  }

  static bool case_of(const Polygon& polygon, std::vector<Vec3d>& points, double& /*radius*/) {
    points = polygon.v_;
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double /*r*/) {
    return std::make_unique<Polygon>(p);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Round 3: a pentagon and a quad sharing an edge, the ray through it.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
