// The naive textbook formulations, one template per primitive: what a student or a quick
// script writes, the baseline of the precision ladder.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "math/vec3.h"

namespace raygrade::naive {

// The nearest hit with t ≥ 0, if any.
template <typename T>
std::optional<T> nearest_root(T t0, T t1) {
  if (t0 >= T(0)) return t0;
  if (t1 >= T(0)) return t1;
  return std::nullopt;
}

// Sphere: a t² + b t + c = 0 with b = 2 d·(o − c), discriminant b² − 4ac, roots (−b ± √Δ)/2a.
template <typename T>
std::optional<T> sphere(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& center, T r) {
  using std::sqrt;
  Vec3<T> f = o - center;
  T a = dot(d, d), b = T(2) * dot(f, d), c = dot(f, f) - r * r;
  T disc = b * b - T(4) * a * c;
  if (disc < T(0)) return std::nullopt;
  T s = sqrt(disc);
  return nearest_root((-b - s) / (T(2) * a), (-b + s) / (T(2) * a));
}

// Infinite cylinder: the same quadratic on the components across the unit axis.
template <typename T>
std::optional<T> cylinder(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& base,
                          const Vec3<T>& axis, T r) {
  using std::sqrt;
  Vec3<T> f = o - base;
  Vec3<T> fp = f - dot(f, axis) * axis, dp = d - dot(d, axis) * axis;
  T a = dot(dp, dp), b = T(2) * dot(fp, dp), c = dot(fp, fp) - r * r;
  if (a == T(0)) return std::nullopt;
  T disc = b * b - T(4) * a * c;
  if (disc < T(0)) return std::nullopt;
  T s = sqrt(disc);
  return nearest_root((-b - s) / (T(2) * a), (-b + s) / (T(2) * a));
}

// Plane through p with normal n: t = n·(p − o) / n·d.
template <typename T>
std::optional<T> plane(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& n, const Vec3<T>& p) {
  T den = dot(n, d);
  if (den == T(0)) return std::nullopt;
  T t = dot(n, p - o) / den;
  if (t < T(0)) return std::nullopt;
  return t;
}

// Triangle: hit the plane, then test the point against each edge (≥ 0 is inside).
template <typename T>
std::optional<T> triangle(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& a, const Vec3<T>& b,
                          const Vec3<T>& c) {
  Vec3<T> n = cross(b - a, c - a);
  std::optional<T> t = plane(o, d, n, a);
  if (!t) return std::nullopt;
  Vec3<T> q = o + *t * d;
  if (dot(cross(b - a, q - a), n) < T(0)) return std::nullopt;
  if (dot(cross(c - b, q - b), n) < T(0)) return std::nullopt;
  if (dot(cross(a - c, q - c), n) < T(0)) return std::nullopt;
  return *t;
}

// Polygon: hit the plane of its first three vertices, then count crossings of a ray along +u
// in the projection that drops the normal's largest component.
template <typename T>
std::optional<T> polygon(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& v) {
  Vec3<T> n = cross(v[1] - v[0], v[2] - v[0]);
  std::optional<T> t = plane(o, d, n, v[0]);
  if (!t) return std::nullopt;
  Vec3<T> q = o + *t * d;
  int drop = max_dimension(n), iu = (drop + 1) % 3, iv = (drop + 2) % 3;
  bool inside = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3<T>& a = v[i];
    const Vec3<T>& b = v[(i + 1) % v.size()];
    if ((a[iv] > q[iv]) != (b[iv] > q[iv])) {
      T u = a[iu] + (q[iv] - a[iv]) * (b[iu] - a[iu]) / (b[iv] - a[iv]);
      if (q[iu] < u) inside = !inside;
    }
  }
  if (!inside) return std::nullopt;
  return *t;
}

// Box: the slab method with plain divisions (a zero direction component gives ±∞, and NaN
// when the origin lies on that slab's plane).
template <typename T>
std::optional<T> box(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& lo, const Vec3<T>& hi) {
  T t_enter = -std::numeric_limits<T>::infinity(), t_exit = std::numeric_limits<T>::infinity();
  for (int i = 0; i < 3; ++i) {
    T t1 = (lo[i] - o[i]) / d[i], t2 = (hi[i] - o[i]) / d[i];
    t_enter = std::max(t_enter, std::min(t1, t2));
    t_exit = std::min(t_exit, std::max(t1, t2));
  }
  if (t_enter > t_exit) return std::nullopt;
  return nearest_root(t_enter, t_exit);
}

}  // namespace raygrade::naive
