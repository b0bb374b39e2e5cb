// The cylinder's normal at a point: the part of P − B across the axis on the side, ±â on a
// cap; a capped cylinder's rim, where side and cap meet, has none.
#include <algorithm>

#include "shapes/cylinder.h"

namespace raygrade {

SurfacePoint Cylinder::nearest_surface(const Vec3d& p, double tie) const {
  Vec3d q = p - base_;
  double y = dot(q, axis_);
  Vec3d radial = q - y * axis_;
  Vec3d out = unit_across(p, base_, axis_);
  std::vector<SurfaceCandidate> cs;
  double ys = height_ ? std::clamp(y, 0.0, *height_) : y;
  cs.push_back({base_ + ys * axis_ + radius_ * out, radial, "side"});
  if (capped_ && height_) {
    Vec3d across = length(radial) <= radius_ ? radial : radius_ * out;
    cs.push_back({base_ + across, -axis_, "bottom cap"});
    cs.push_back({base_ + *height_ * axis_ + across, axis_, "top cap"});
  }
  return nearest_of(cs, p, tie);
}

void Cylinder::derive_normal(Deriver& d, const E& P, const SurfacePoint& s,
                             const NormalNames& n) const {
  E B = d.given("B", "B", base_, "the centre of the base");
  E a = d.given("a_hat", "â", axis_, "the unit axis");
  if (s.part == "side") {
    d.step("q", "q", P - B);
    d.step("y", "y", dot(d.sym("q"), a), "the height of P along the axis");
    d.step("radial", "q_⊥", d.sym("q") - d.sym("y") * a, "the part of q across the axis");
    d.step(n.name, n.display, d.sym("radial") / norm(d.sym("radial")),
           "the outward unit normal of the side");
  } else {
    d.step(n.name, n.display, s.part == "top cap" ? a : -a,
           fmt::format("P is on the {}: the normal is the axis, pointing out", s.part));
  }
}

}  // namespace raygrade
