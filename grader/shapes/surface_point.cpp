// The nearest of a surface's parts, and the small geometry the primitives' normals share.
#include "shapes/surface_point.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shapes/flat.h"

namespace raygrade {

SurfacePoint nearest_of(const std::vector<SurfaceCandidate>& cs, const Vec3d& p, double tie) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < cs.size(); ++i) {
    if (length(cs[i].nearest - p) < length(cs[best].nearest - p)) best = i;
  }
  SurfacePoint s{cs[best].nearest, cs[best].normal, cs[best].part, ""};
  Vec3d n = normalized(cs[best].normal);
  for (std::size_t i = 0; i < cs.size(); ++i) {
    bool as_near = length(cs[i].nearest - p) <= length(cs[best].nearest - p) + tie;
    if (i != best && as_near && length(normalized(cs[i].normal) - n) > kOnSurfaceRelative) {
      s.other = cs[i].part;
    }
  }
  return s;
}

Vec3d nearest_on_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  Vec3d ab = b - a;
  double s = std::clamp(dot(p - a, ab) / length_squared(ab), 0.0, 1.0);
  return a + s * ab;
}

Vec3d unit_across(const Vec3d& p, const Vec3d& base, const Vec3d& a) {
  Vec3d q = p - base;
  Vec3d radial = q - dot(q, a) * a;
  double rho = length(radial);
  if (rho > 0) return radial / rho;
  return normalized(cross(a, std::abs(a.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0}));
}

SurfacePoint nearest_flat(const std::vector<Vec3d>& v, const Vec3d& p) {
  Vec3d n = newell_normal(v);
  Vec3d u = normalized(n);
  Vec3d q = p - dot(p - v[0], u) * u;
  // Inside: q is on the inner side of every edge when the polygon is convex; in general, by
  // the winding of the edges around q (the sum of the angles they subtend is 2π inside).
  double winding = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    Vec3d a = v[i] - q, b = v[(i + 1) % v.size()] - q;
    winding += std::atan2(dot(cross(a, b), u), dot(a, b));
  }
  SurfacePoint s{q, n, "", ""};
  // The winding is 2π inside and 0 outside (π on an edge, where the edge point is as near).
  if (std::abs(winding) > std::numbers::pi) return s;
  double best = kInfinity;
  for (std::size_t i = 0; i < v.size(); ++i) {
    Vec3d e = nearest_on_segment(q, v[i], v[(i + 1) % v.size()]);
    if (length(e - p) < best) {
      best = length(e - p);
      s.nearest = e;
    }
  }
  return s;
}

void derive_flat_normal(Deriver& d, const std::vector<Vec3d>& v, const NormalNames& n) {
  std::vector<E> vs;
  for (std::size_t i = 0; i < v.size(); ++i) {
    vs.push_back(d.given(fmt::format("v{}", i), fmt::format("v_{}", i), v[i]));
  }
  if (v.size() == 3) {
    d.step("e1", "e_1", vs[1] - vs[0]);
    d.step("e2", "e_2", vs[2] - vs[0]);
    d.step("n", "n", cross(d.sym("e1"), d.sym("e2")), "by vertex order: e_1 × e_2");
  } else {
    E sum = cross(vs[0], vs[1]);
    for (std::size_t i = 1; i < v.size(); ++i) sum = sum + cross(vs[i], vs[(i + 1) % v.size()]);
    d.step("n", "n", sum, "Newell's normal: the sum of v_i × v_(i+1), by vertex order");
  }
  d.step(n.name, n.display, d.sym("n") / norm(d.sym("n")), "the same at every point of the face");
}

}  // namespace raygrade
