// The box's normal at a point: its face's, ±x, ±y or ±z; an edge, where two faces meet, has
// none.
#include <algorithm>

#include "derivation/number_format.h"
#include "shapes/box.h"

namespace raygrade {

SurfacePoint Box::nearest_surface(const Vec3d& p, double tie) const {
  const char* axis[] = {"x", "y", "z"};
  std::vector<SurfaceCandidate> cs;
  for (int i = 0; i < 3; ++i) {
    for (int side = 0; side < 2; ++side) {
      Vec3d q{std::clamp(p.x, lo_.x, hi_.x), std::clamp(p.y, lo_.y, hi_.y),
              std::clamp(p.z, lo_.z, hi_.z)};
      double face = side ? hi_[i] : lo_[i];
      q[i] = face;
      Vec3d n{};
      n[i] = side ? 1 : -1;
      cs.push_back({q, n, fmt::format("face {} = {}", axis[i], format_number(face))});
    }
  }
  return nearest_of(cs, p, tie);
}

void Box::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& s,
                        const NormalNames& n) const {
  d.given(n.name, n.display, s.normal, fmt::format("P is on the {}: its outward normal", s.part));
}

}  // namespace raygrade
