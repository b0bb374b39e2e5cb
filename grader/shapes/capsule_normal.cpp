// The capsule's normal at a point: from the nearest point F of the segment ab to P. The side
// and the ends meet smoothly, so the rims have this normal too.
#include <algorithm>

#include "shapes/capsule.h"

namespace raygrade {

SurfacePoint Capsule::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d f = nearest_on_segment(p, a_, b_);
  Vec3d out = length(p - f) > 0 ? p - f : radius_ * unit_across(p, a_, axis_);
  double u = dot(p - a_, axis_) / height_;
  std::string part = u <= 0 ? "end at a" : u >= 1 ? "end at b" : "side";
  return SurfacePoint{f + radius_ * normalized(out), out, part, ""};
}

void Capsule::derive_normal(Deriver& d, const E& P, const SurfacePoint& s,
                            const NormalNames& n) const {
  E A = d.given("A", "a", a_, "one end of the segment");
  E B = d.given("B", "b", b_, "the other end");
  if (s.part == "side") {
    d.step("ab", "b − a", B - A);
    d.step("u", "u", dot(P - A, d.sym("ab")) / dot(d.sym("ab"), d.sym("ab")),
           "how far along ab the point nearest to P lies (between 0 and 1: on the side)");
    d.step("F", "F", A + d.sym("u") * d.sym("ab"), "the point of the segment nearest to P");
  } else {
    d.step("F", "F", s.part == "end at a" ? A : B,
           fmt::format("P is beyond that end of the segment (on the {}): the nearest point of "
                       "the segment is the end itself",
                       s.part));
  }
  d.step("PF", n.point + " − F", P - d.sym("F"), "from the segment to the point");
  d.step(n.name, n.display, d.sym("PF") / norm(d.sym("PF")), "the outward unit normal");
}

}  // namespace raygrade
