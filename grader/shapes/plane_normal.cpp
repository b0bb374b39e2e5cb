// The plane's normal at a point: the given one, the same everywhere.
#include "shapes/plane.h"

namespace raygrade {

SurfacePoint Plane::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d on = some_point();
  return SurfacePoint{p - dot(p - on, normal_) / length_squared(normal_) * normal_, normal_, "",
                      ""};
}

void Plane::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                          const NormalNames& n) const {
  E given = d.given("n", "n", normal_, "the plane's normal as given");
  d.step(n.name, n.display, given / norm(given), "the same at every point of the plane");
}

}  // namespace raygrade
