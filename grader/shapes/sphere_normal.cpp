// The sphere's normal at a point: from the centre to the point, the gradient of |X − C|² − r².
#include "shapes/sphere.h"

namespace raygrade {

SurfacePoint Sphere::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d pc = p - center_;
  Vec3d dir = length(pc) > 0 ? normalized(pc) : Vec3d{0, 0, 1};
  return SurfacePoint{center_ + radius_ * dir, pc, "", ""};
}

void Sphere::derive_normal(Deriver& d, const E& P, const SurfacePoint& /*s*/,
                           const NormalNames& n) const {
  E C = d.given("C", "C", center_, "the sphere's centre");
  d.step("PC", n.point + " − C", P - C,
         "from the centre to the point: the gradient of |X − C|² − r²");
  d.step(n.name, n.display, d.sym("PC") / norm(d.sym("PC")), "the outward unit normal");
}

}  // namespace raygrade
