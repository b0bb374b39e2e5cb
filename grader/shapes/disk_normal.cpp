// The disk's normal at a point: the given one, normalized, the same over the disk and its rim
// (the disk is flat: its rim is no edge between two parts).
#include "shapes/disk.h"

namespace raygrade {

SurfacePoint Disk::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d u = normalized(normal_);
  Vec3d q = p - dot(p - center_, u) * u;
  Vec3d off = q - center_;
  double rho = length(off);
  if (rho > radius_) q = center_ + (radius_ / rho) * off;  // beyond the rim: the rim's point
  return SurfacePoint{q, normal_, "", ""};
}

void Disk::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                         const NormalNames& n) const {
  E given = d.given("n", "n", normal_, "the disk's normal as given");
  d.step(n.name, n.display, given / norm(given),
         "the same at every point of the disk, its rim included");
}

}  // namespace raygrade
