// Integer geometry for generated problems: lattice points on spheres and circles, so that
// hits land on integer points at integer t.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "sampling/prng.h"

namespace raygrade {

// Every integer vector of length r (r from 1 to 20): (3, 4, 0) and (2, 3, 6)·1 for r = 5, 7.
const std::vector<Vec3d>& lattice_sphere(int r);

// Every integer vector (x, y, 0) of length r.
const std::vector<Vec3d>& lattice_circle(int r);

// The greatest common divisor of the components (integer-valued) of a nonzero vector.
long long component_gcd(const Vec3d& v);

// v divided by the gcd of its components: the shortest integer vector along v.
Vec3d reduced(const Vec3d& v);

// A random integer vector with components in [-limit, limit].
Vec3d random_point(Prng& rng, int limit);

// A random nonzero integer direction with small components; never parallel to `avoid` when
// given (a zero `avoid` allows any).
Vec3d random_direction(Prng& rng, const Vec3d& avoid = {0, 0, 0});

// A random permutation of the axes with random signs, applied to a vector.
struct AxisMap {
  int axis[3] = {0, 1, 2};
  double sign[3] = {1, 1, 1};
  Vec3d operator()(const Vec3d& v) const;
};
AxisMap random_axis_map(Prng& rng);

// Numbers as JSON: integers as integer literals ("2", not "2.0"), others as written.
nlohmann::ordered_json number_json(double v);
nlohmann::ordered_json vector_json(const Vec3d& v);

// "(1, 0, -2)" and "<1, 0, -2>" for statements.
std::string point_text(const Vec3d& v);
std::string direction_text(const Vec3d& v);

}  // namespace raygrade
