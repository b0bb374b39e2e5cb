// The nearest point of a primitive's surface to a given point, with the outward normal there:
// what the normal kind asks of each primitive (its nearest_surface and derive_normal, in its
// own shapes/<name>.cpp).
#pragma once

#include <string>
#include <vector>

#include "derivation/derivation.h"
#include "math/vec3.h"

namespace raygrade {

// A point within this fraction of the object's size (at least 1) of its surface is on it: a
// coordinate printed to four decimals, as exercises print √2/2 = 0.7071, is off by at most
// 5e-5. The same distance tells a rim or an edge (two parts of the surface as near) apart.
constexpr double kOnSurfaceRelative = 1e-4;

// The surface part nearest to an object-space point, with its outward normal there.
struct SurfacePoint {
  Vec3d nearest;      // the nearest point of that part of the surface
  Vec3d normal;       // the outward (or by vertex order, or as given) normal, not normalized
  std::string part;   // "side", "top cap", "face x = 1"; empty for one-part surfaces
  std::string other;  // a second part as near where the normal is not defined (an edge, a rim)
};

// One part of a surface as a candidate for the nearest: its nearest point and normal there.
struct SurfaceCandidate {
  Vec3d nearest, normal;
  std::string part;
};

// The nearest of the candidates, and a second one as near within `tie` whose normal differs
// (an edge, a rim; where two parts meet smoothly, as a capsule's side and end, the normal is
// the same and defined).
SurfacePoint nearest_of(const std::vector<SurfaceCandidate>& candidates, const Vec3d& p,
                        double tie);

// The nearest point to p of the segment a–b.
Vec3d nearest_on_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b);

// A unit vector across the unit axis `a`, towards p's part across it from `base`; any one
// when p is on the axis (every direction across it is then as near).
Vec3d unit_across(const Vec3d& p, const Vec3d& base, const Vec3d& a);

// A flat polygon's (a triangle's, a polygon's) nearest point to p: p projected on its plane
// when that is inside, else the nearest point of an edge; its normal by vertex order
// (Newell's).
SurfacePoint nearest_flat(const std::vector<Vec3d>& vertices, const Vec3d& p);

struct NormalNames;
// The steps of a flat polygon's normal by vertex order: e₁ × e₂ for three vertices, Newell's
// sum for more, then normalized.
void derive_flat_normal(Deriver& d, const std::vector<Vec3d>& vertices, const NormalNames& n);

// The names of the normal kind's steps a primitive writes: the normal's step ("N", or "N_obj"
// in object space) and its display ("N", "N'"), and P's display ("P", "P'").
struct NormalNames {
  std::string name, display, point;
};

}  // namespace raygrade
