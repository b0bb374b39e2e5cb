// The cone's normal at a point: (h·ê + r·â)/√(h² + r²) on the side, ê across the axis towards
// P; at the apex, where ê is undefined, â; −â on the base cap. On the rim the side's normal, as
// the cone's hits there have (docs/problem-format.md).
#include "shapes/cone.h"

namespace raygrade {

SurfacePoint Cone::nearest_surface(const Vec3d& p, double tie) const {
  Vec3d e = unit_across(p, base_, axis_);
  Vec3d apex = base_ + height_ * axis_;
  Vec3d on_side = nearest_on_segment(p, base_ + radius_ * e, apex);
  SurfacePoint side{on_side, height_ * e + radius_ * axis_, "side", ""};
  if (length(on_side - apex) <= tie) side = SurfacePoint{apex, axis_, "apex", ""};
  if (!capped_) return side;
  Vec3d q = p - base_;
  Vec3d radial = q - dot(q, axis_) * axis_;
  Vec3d on_cap = base_ + (length(radial) <= radius_ ? radial : radius_ * e);
  // The cap only where it is nearer than the side by more than `tie`: the rim is the side's.
  if (length(on_cap - p) + tie < length(side.nearest - p)) {
    return SurfacePoint{on_cap, -axis_, "base cap", ""};
  }
  return side;
}

void Cone::derive_normal(Deriver& d, const E& P, const SurfacePoint& s,
                         const NormalNames& n) const {
  E B = d.given("B", "B", base_, "the centre of the base");
  E a = d.given("a_hat", "â", axis_, "the unit axis");
  if (s.part == "side") {
    E h = d.given("h", "h", height_, "the height");
    E r = d.given("r", "r", radius_, "the radius of the base");
    d.step("q", "q", P - B);
    d.step("s", "s", dot(d.sym("q"), a), "the height of P along the axis");
    d.step("radial", "q_⊥", d.sym("q") - d.sym("s") * a, "the part of q across the axis");
    d.step("e_hat", "ê", d.sym("radial") / norm(d.sym("radial")),
           "the unit vector across the axis towards P");
    d.step("m", "m", h * d.sym("e_hat") + r * a,
           "h·ê + r·â: across the slanted side, pointing out");
    d.step(n.name, n.display, d.sym("m") / norm(d.sym("m")),
           "the outward unit normal of the side: (h·ê + r·â)/√(h² + r²)");
  } else if (s.part == "apex") {
    d.step(n.name, n.display, a,
           "P is the apex, where ê is undefined: by the cone's convention the normal is â");
  } else {
    d.step(n.name, n.display, -a, "P is on the base cap: the normal is −â, pointing out");
  }
}

}  // namespace raygrade
