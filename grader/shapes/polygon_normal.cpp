// The polygon's normal at a point: Newell's, by vertex order, the same over the face.
#include "shapes/polygon.h"

namespace raygrade {

SurfacePoint Polygon::nearest_surface(const Vec3d& p, double /*tie*/) const {
  return nearest_flat(v_, p);
}

void Polygon::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                            const NormalNames& n) const {
  derive_flat_normal(d, v_, n);
}

}  // namespace raygrade
