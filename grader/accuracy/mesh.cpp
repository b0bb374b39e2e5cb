// The subdivided sphere and the edge-ray and spawned-ray stress tests.
#include "accuracy/mesh.h"

#include <cmath>
#include <map>

#include "accuracy/corpus.h"
#include "scenes/offset.h"
#include "shapes/triangle.h"

namespace raygrade {

TriangleMesh subdivided_sphere(int levels) {
  double p = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh m;
  m.vertices = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
  for (auto& v : m.vertices) v = normalized(v);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      m.vertices.push_back(normalized(m.vertices[a] + m.vertices[b]));
      int index = static_cast<int>(m.vertices.size()) - 1;
      middle[key] = index;
      return index;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : m.triangles) {
      int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    m.triangles = std::move(next);
  }
  return m;
}

namespace {

struct MeshHit {
  bool hit = false;
  double t = 0;
  int triangle = -1;
  std::array<double, 3> barycentric{};
};

// The nearest hit with t > t_min over all triangles. Triangles whose bounding sphere the
// ray's line passes farther from than its radius (with a generous relative margin) are
// skipped: a conservative cull, it never skips a triangle the line touches.
MeshHit nearest(const TriangleMesh& m, const std::vector<std::pair<Vec3d, double>>& bounds,
                const Vec3d& o, const Vec3d& d, double t_min) {
  constexpr double kCullMargin = 1e-6;  // relative; rounding is 1e-16
  MeshHit best;
  double dd = dot(d, d);
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    Vec3d f = bounds[i].first - o;
    Vec3d perp = f - (dot(f, d) / dd) * d;
    double r = bounds[i].second * (1 + kCullMargin);
    if (length_squared(perp) > r * r) continue;
    const auto& t = m.triangles[i];
    auto h = watertight_triangle(o, d, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    if (!h.hit || h.t <= t_min) continue;
    if (!best.hit || h.t < best.t) best = {true, h.t, static_cast<int>(i), h.barycentric};
  }
  return best;
}

std::vector<std::pair<Vec3d, double>> bounding_spheres(const TriangleMesh& m) {
  std::vector<std::pair<Vec3d, double>> out;
  for (const auto& t : m.triangles) {
    Vec3d c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
    double r = 0;
    for (int k : t) r = std::max(r, length(m.vertices[k] - c));
    out.emplace_back(c, r);
  }
  return out;
}

}  // namespace

StressResult stress_edge_rays(const TriangleMesh& mesh, long long rays, std::uint64_t seed,
                              const std::function<void(double)>& progress) {
  SplitMix rng(seed);
  auto bounds = bounding_spheres(mesh);
  StressResult out;
  for (long long i = 0; i < rays; ++i) {
    const auto& tri = mesh.triangles[rng.next() % mesh.triangles.size()];
    int k = rng.integer(0, 2);
    const Vec3d &a = mesh.vertices[tri[k]], &b = mesh.vertices[tri[(k + 1) % 3]];
    Vec3d target = i % 3 == 0 ? a : a + rng.uniform() * (b - a);
    // From the side the surface faces, at a random slant.
    Vec3d slant = rng.unit_vector();
    double distance = rng.uniform(0.5, 4);
    Vec3d o = target + distance * normalized(normalized(target) + 0.6 * slant);
    if (dot(o - target, target) <= 0) o = target + 2.0 * target;
    ++out.rays;
    if (!nearest(mesh, bounds, o, target - o, -kInfinity).hit) ++out.failures;
    if (progress && i % 4096 == 0) progress(static_cast<double>(i) / static_cast<double>(rays));
  }
  return out;
}

StressResult stress_spawned_rays(const TriangleMesh& mesh, long long rays, std::uint64_t seed) {
  // The rounding of a point from barycentric weights: γ(7)·Σ|w_i p_i| (pbrt-v4, sec. 6.8.5).
  const double gamma7 = gamma_bound(7);
  SplitMix rng(seed);
  auto bounds = bounding_spheres(mesh);
  StressResult out;
  for (long long i = 0; i < rays; ++i) {
    Vec3d o = 3.0 * rng.unit_vector();
    Vec3d d = 0.9 * rng.unit_vector() - o;
    MeshHit h = nearest(mesh, bounds, o, d, 0);
    if (!h.hit) continue;
    const auto& t = mesh.triangles[h.triangle];
    const Vec3d &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const auto& w = h.barycentric;
    Vec3d p = w[0] * a + w[1] * b + w[2] * c;
    Vec3d abs_sum;
    for (int k = 0; k < 3; ++k) {
      abs_sum[k] = std::abs(w[0] * a[k]) + std::abs(w[1] * b[k]) + std::abs(w[2] * c[k]);
    }
    Vec3d error = gamma7 * abs_sum;
    Vec3d n = normalized(cross(b - a, c - a));
    for (int side = 0; side < 2; ++side) {
      Vec3d dir = rng.unit_vector();
      if ((dot(dir, n) > 0) != (side == 0)) dir = -dir;
      Vec3d origin = offset_ray_origin(p, error, n, dir);
      MeshHit again = nearest(mesh, bounds, origin, dir, 0);
      ++out.rays;
      // Outward, nothing lies ahead of a convex mesh; inward, the ray must leave through
      // another triangle (from inside a closed mesh it cannot miss).
      bool outward = side == 0;
      if (outward ? again.hit : (!again.hit || again.triangle == h.triangle)) ++out.failures;
    }
  }
  return out;
}

}  // namespace raygrade
