// Error bounds of hit points and the origins of spawned rays.
#include "scenes/offset.h"

#include <cmath>

namespace raygrade {
namespace {

Vec3d abs3(const Vec3d& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

// |A|·v with the absolute values of A's entries.
Vec3d abs_linear(const Affine& a, const Vec3d& v) {
  return {dot(abs3(a.rows[0]), v), dot(abs3(a.rows[1]), v), dot(abs3(a.rows[2]), v)};
}

}  // namespace

Vec3d hit_point_error(const Ray& world, double t, const Transform* transform) {
  // |o| + |t·d|: the magnitudes the roundings of o + t·d and of t are relative to.
  Vec3d size = abs3(world.origin) + std::abs(t) * abs3(world.direction);
  Vec3d error = gamma_bound(kRootRoundings + kPointRoundings) * size;
  if (transform && !transform->identity()) {
    // In object space the ray o' = M⁻¹o, d' = A⁻¹d was rounded (γ3 of |A⁻¹|·size and the
    // translation), and its hit carries the same root and point roundings as above; A maps
    // both back to the world.
    const Affine& inv = transform->to_object;
    Vec3d object_size = abs_linear(inv, size) + abs3(inv.translation);
    Vec3d object_error = gamma_bound(kTransformRoundings) * object_size +
                         gamma_bound(kRootRoundings + kPointRoundings) * object_size;
    error = error +
            (1 + gamma_bound(kTransformRoundings)) * abs_linear(transform->to_world, object_error);
  }
  return error;
}

double offset_distance(const Vec3d& error, const Vec3d& normal) { return dot(abs3(normal), error); }

Vec3d offset_ray_origin(const Vec3d& point, const Vec3d& error, const Vec3d& normal,
                        const Vec3d& direction) {
  double d = offset_distance(error, normal);
  Vec3d offset = d * normal;
  if (dot(direction, normal) < 0) offset = -offset;
  Vec3d po = point + offset;
  // The sum may round back toward the surface: step one ulp further out in each coordinate.
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0) {
      po[i] = std::nextafter(po[i], kInfinity);
    } else if (offset[i] < 0) {
      po[i] = std::nextafter(po[i], -kInfinity);
    }
  }
  return po;
}

}  // namespace raygrade
