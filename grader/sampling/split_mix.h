// A small portable random generator (SplitMix64), so that the accuracy study's random and hard
// cases are the same everywhere. Header-only: the primitives draw their own cases with it.
#pragma once

#include <cmath>
#include <cstdint>

#include "math/vec3.h"

namespace raygrade {

class SplitMix {
 public:
  explicit SplitMix(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // In [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }
  // In [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform on the sphere.
  Vec3d unit_vector() {
    double z = uniform(-1, 1), phi = uniform(0, 2 * M_PI), s = std::sqrt(1 - z * z);
    return {s * std::cos(phi), s * std::sin(phi), z};
  }
  // In [lo, hi].
  int integer(int lo, int hi) {
    return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  // Uniform in the cube [−s, s)³.
  Vec3d point(double s) { return Vec3d{uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }

 private:
  std::uint64_t state_;
};

// A random unit vector perpendicular to u.
inline Vec3d perpendicular(const Vec3d& u, SplitMix& rng) {
  return normalized(cross(u, rng.unit_vector()));
}

// Each random number is drawn in a statement of its own (or in a braced list, which C++
// evaluates in order): the order in which operands and arguments are evaluated is unspecified,
// and the stored corpus and the generated banks must not depend on the compiler.

// ±10^-k for k in [k_lo, k_hi]: the relative offset from a tangent of a grazing ray.
inline double offset(SplitMix& rng, int k_lo, int k_hi) {
  double sign = rng.uniform() < 0.5 ? -1 : 1;
  return sign * std::pow(10.0, -rng.integer(k_lo, k_hi));
}

}  // namespace raygrade
