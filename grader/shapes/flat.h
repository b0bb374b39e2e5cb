// Shared plan of the flat primitives (plane, triangle, polygon): hit the plane, then test
// the interior; and the case of a ray lying in the plane.
#pragma once

#include <vector>

#include "shapes/ray.h"

namespace raygrade {

// Relative size below which n·D counts as zero and the origin as lying in the plane: a few
// ulps of the products involved (double epsilon is 2.2e-16), so that only rays parallel up to
// rounding are treated as parallel; a ray with n·D of 1e-12 relative still hits.
constexpr double kParallelRelative = 8 * 2.220446049250313e-16;

// True when the ray's direction is parallel to a plane with normal n, up to rounding.
bool parallel_to_plane(const Vec3d& n, const Vec3d& direction);

// True when `p` lies in the plane through `q` with normal n, up to rounding.
bool in_plane(const Vec3d& n, const Vec3d& q, const Vec3d& p);

// For a ray lying in the plane of a polygon: does it meet the polygon (within its interval)?
bool ray_in_plane_meets_polygon(const Ray& ray, const std::vector<Vec3d>& vertices,
                                const Vec3d& normal);

// Is q, a point of the plane, inside the simple polygon or on its boundary? By crossing
// number in the projection that drops the normal's largest component.
bool point_in_polygon(const Vec3d& q, const std::vector<Vec3d>& vertices, const Vec3d& normal);

// Does the ray's line pass through the simple polygon (boundary included)? The test runs in
// the ray's sheared frame, like the watertight triangle test: the vertices are moved so that
// the ray is the +z axis, and the origin of that 2D frame is tested against the polygon, with
// no plane point computed. An edge function within its rounding error of zero counts as on
// the boundary, so rays through edges and vertices hit.
bool ray_pierces_polygon(const Ray& ray, const std::vector<Vec3d>& vertices);

// Newell's normal at any number type (twice the area vector; not normalized): the sum of
// v_i × v_(i+1), by vertex order.
template <typename T>
Vec3<T> newell_normal_of(const std::vector<Vec3<T>>& v) {
  Vec3<T> n{};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3<T>& a = v[i];
    const Vec3<T>& b = i + 1 < v.size() ? v[i + 1] : v[0];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

// Newell's normal of a polygon in double.
Vec3d newell_normal(const std::vector<Vec3d>& vertices);

}  // namespace raygrade
