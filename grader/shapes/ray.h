// Ray and Hit: p(t) = origin + t·direction, with the direction exactly as given.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "math/vec3.h"

namespace raygrade {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Ray {
  Vec3d origin;
  Vec3d direction;   // never normalized by the solver: t is in units of this vector
  double t_min = 0;  // closed interval [t_min, t_max]
  double t_max = kInfinity;

  Vec3d at(double t) const { return origin + t * direction; }
  // A t beyond double's range (the infinity a division by an underflowed quantity gives) is
  // never a hit, even in [t_min, ∞].
  bool accepts(double t) const { return std::isfinite(t) && t >= t_min && t <= t_max; }
};

struct Hit {
  double t = 0;
  Vec3d point;
  Vec3d normal;  // unit length; outward for solids, as given for planes, by vertex order for flats
  std::optional<std::array<double, 3>> barycentric;  // triangles: point = wa·a + wb·b + wc·c
  std::string part;  // which part was hit, for the solution: "side", "top cap", "face x = 1"
};

// Every hit in [t_min, t_max], ascending in t.
struct Intersection {
  std::vector<Hit> hits;
  bool contained = false;  // the ray lies in the flat object's plane and meets it along a line
};

}  // namespace raygrade
