// The triangle's normal at a point: e₁ × e₂ by vertex order, the same over the face.
#include "shapes/triangle.h"

namespace raygrade {

SurfacePoint Triangle::nearest_surface(const Vec3d& p, double /*tie*/) const {
  return nearest_flat({v_.begin(), v_.end()}, p);
}

void Triangle::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                             const NormalNames& n) const {
  derive_flat_normal(d, {v_.begin(), v_.end()}, n);
}

}  // namespace raygrade
