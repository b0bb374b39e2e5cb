// Unit vectors (normals) computed in double-double and rounded once, so that a normal is within
// an ulp or two of the exact one even where its pieces cancel in double.
#pragma once

#include <algorithm>
#include <cmath>

#include "math/double_double.h"
#include "math/vec3.h"

namespace raygrade {

using Vec3dd = Vec3<DoubleDouble>;

// v / |v| in double-double. v is first divided by its largest component, so that its squared
// length neither overflows nor underflows. A zero vector stays zero.
inline Vec3dd unit_dd(const Vec3dd& v) {
  DoubleDouble m = std::max({abs(v.x), abs(v.y), abs(v.z)});
  if (m.hi == 0) return {};
  Vec3dd w = v / m;
  return w / sqrt(dot(w, w));
}

// v / |v| rounded to double.
inline Vec3d unit_rounded(const Vec3dd& v) {
  Vec3dd u = unit_dd(v);
  return {static_cast<double>(u.x), static_cast<double>(u.y), static_cast<double>(u.z)};
}

// v rounded to double.
inline Vec3d rounded(const Vec3dd& v) {
  return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

// b − a exactly, as double-double (Knuth's TwoSum per component).
inline Vec3dd difference_dd(const Vec3d& b, const Vec3d& a) { return Vec3dd(b) - Vec3dd(a); }

}  // namespace raygrade
