// Plane-and-interior helpers shared by the flat primitives.
#include "shapes/flat.h"

#include <algorithm>
#include <cmath>

#include "math/robust.h"

namespace raygrade {
namespace {

struct UV {
  double u, v;
};

UV project(const Vec3d& p, int drop) {
  int i = (drop + 1) % 3, j = (drop + 2) % 3;
  return {p[i], p[j]};
}

double orient(UV a, UV b, UV c) { return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u); }

// Edge tolerance: relative to the squared size of the polygon, a few ulps of the products.
constexpr double kOnEdgeRelative = 64 * 2.220446049250313e-16;

// q on the segment ab: on its line, and between its ends ((a − q)·(b − q) ≤ 0), both within
// the tolerance (an exact bounding-box test would reject a point a rounding off an
// axis-aligned edge).
bool on_segment(UV a, UV b, UV q, double scale2) {
  if (std::abs(orient(a, b, q)) > kOnEdgeRelative * scale2) return false;
  return (a.u - q.u) * (b.u - q.u) + (a.v - q.v) * (b.v - q.v) <= kOnEdgeRelative * scale2;
}

// Rounding error bound of one sheared coordinate, in ulps of its terms' magnitudes: the shear
// factor, the product and the difference each round once.
constexpr double kShearUlps = 8 * 2.220446049250313e-16;

struct Sheared {
  double x, y, error;
};

}  // namespace

bool parallel_to_plane(const Vec3d& n, const Vec3d& direction) {
  return std::abs(dot(n, direction)) <= kParallelRelative * length(n) * length(direction);
}

bool in_plane(const Vec3d& n, const Vec3d& q, const Vec3d& p) {
  double scale = length(n) * (std::abs(q.x) + std::abs(q.y) + std::abs(q.z) + std::abs(p.x) +
                              std::abs(p.y) + std::abs(p.z));
  return std::abs(dot(n, p - q)) <= kParallelRelative * scale;
}

Vec3d newell_normal(const std::vector<Vec3d>& v) { return newell_normal_of(v); }

bool point_in_polygon(const Vec3d& q3, const std::vector<Vec3d>& vertices, const Vec3d& normal) {
  int drop = max_dimension(normal);
  UV q = project(q3, drop);
  double umin = q.u, umax = q.u, vmin = q.v, vmax = q.v;
  std::vector<UV> p;
  for (const auto& v : vertices) {
    p.push_back(project(v, drop));
    umin = std::min(umin, p.back().u);
    umax = std::max(umax, p.back().u);
    vmin = std::min(vmin, p.back().v);
    vmax = std::max(vmax, p.back().v);
  }
  double scale2 = std::max({umax - umin, vmax - vmin, 1e-300});
  scale2 *= scale2;
  bool inside = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    UV a = p[i], b = p[(i + 1) % p.size()];
    if (on_segment(a, b, q, scale2)) return true;  // closed: the boundary belongs to it
    if ((a.v > q.v) != (b.v > q.v)) {
      double u = a.u + (q.v - a.v) * (b.u - a.u) / (b.v - a.v);
      if (q.u < u) inside = !inside;
    }
  }
  return inside;
}

bool ray_pierces_polygon(const Ray& ray, const std::vector<Vec3d>& vertices) {
  const Vec3d& d = ray.direction;
  int kz = max_dimension(d), kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  double sx = d[kx] / d[kz], sy = d[ky] / d[kz];
  std::vector<Sheared> p;
  for (const auto& v : vertices) {
    Vec3d a = v - ray.origin;
    double error = kShearUlps * std::max(std::abs(a[kx]) + std::abs(sx * a[kz]),
                                         std::abs(a[ky]) + std::abs(sy * a[kz]));
    p.push_back({a[kx] - sx * a[kz], a[ky] - sy * a[kz], error});
  }
  // The edge function of (a, b) at the frame's origin, and whether the origin is on the edge.
  auto edge = [&](const Sheared& a, const Sheared& b, bool& on_edge) {
    double e = difference_of_products(a.x, b.y, a.y, b.x);
    double bound =
        a.error * (std::abs(b.x) + std::abs(b.y)) + b.error * (std::abs(a.x) + std::abs(a.y));
    double between = a.x * b.x + a.y * b.y;  // ≤ 0 when the origin lies between a and b
    double reach = a.error * std::hypot(b.x, b.y) + b.error * std::hypot(a.x, a.y);
    on_edge = std::abs(e) <= bound && between <= reach;
    return e;
  };
  bool inside = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Sheared& a = p[i];
    const Sheared& b = p[(i + 1) % p.size()];
    bool on_edge = false;
    double e = edge(a, b, on_edge);
    if (on_edge) return true;  // closed: the boundary belongs to it
    // Crossing number along +x: the edge crosses y = 0 at x = e / (b.y − a.y).
    if ((a.y > 0) != (b.y > 0) && (e > 0) == (b.y - a.y > 0)) inside = !inside;
  }
  return inside;
}

bool ray_in_plane_meets_polygon(const Ray& ray, const std::vector<Vec3d>& vertices,
                                const Vec3d& normal) {
  double t0 = ray.t_min, t1 = ray.t_max;
  if (std::isfinite(t0) && point_in_polygon(ray.at(t0), vertices, normal)) return true;
  int drop = max_dimension(normal);
  UV o = project(ray.origin, drop), d = project(ray.direction, drop);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    UV a = project(vertices[i], drop), b = project(vertices[(i + 1) % vertices.size()], drop);
    // Solve o + t d = a + s (b − a) for t and s.
    UV e{b.u - a.u, b.v - a.v};
    double den = d.u * e.v - d.v * e.u;
    UV w{a.u - o.u, a.v - o.v};
    if (den == 0) {
      // Parallel to this edge: it is met only if collinear; the other edges then decide.
      continue;
    }
    double t = (w.u * e.v - w.v * e.u) / den;
    double s = (w.u * d.v - w.v * d.u) / den;
    // Closed edges: an s a rounding outside [0, 1] still reaches the edge's end.
    if (s >= -kOnEdgeRelative && s <= 1 + kOnEdgeRelative && t >= t0 && t <= t1) return true;
  }
  return false;
}

}  // namespace raygrade
