// The nearest hit (t ≥ 0) of an AccuracyCase by the reference formulation or the naive one,
// at any number type: one template per formulation, instantiated for every level of the ladder.
#pragma once

#include <optional>

#include "accuracy/accuracy_case.h"
#include "accuracy/naive.h"
#include "shapes/box.h"
#include "shapes/cylinder.h"
#include "shapes/flat.h"
#include "shapes/plane.h"
#include "shapes/polygon.h"
#include "shapes/sphere.h"
#include "shapes/triangle.h"

namespace raygrade {

// The case's points in T. No copy for double, and a per-thread buffer for the other types,
// so that the benchmark times the formulas rather than memory allocation. The buffer is
// reused by the next call with the same T: copy it to keep it.
template <typename T>
const std::vector<Vec3<T>>& points_as(const AccuracyCase& c) {
  if constexpr (std::is_same_v<T, double>) {
    return c.points;
  } else {
    thread_local std::vector<Vec3<T>> buffer;
    buffer.resize(c.points.size());
    for (std::size_t i = 0; i < c.points.size(); ++i) buffer[i] = Vec3<T>(c.points[i]);
    return buffer;
  }
}

// A vector of the case in T: the case's own for double (no copy, which the compiler would make
// through memory), converted otherwise.
template <typename T>
decltype(auto) vector_as(const Vec3d& v) {
  if constexpr (std::is_same_v<T, double>) {
    return (v);
  } else {
    return Vec3<T>(v);
  }
}

// The reference: the templates the solver's Shape::intersect runs in double, on inputs
// already in T (points and radius as AccuracyCase describes them). True with the nearest hit at
// t ≥ 0 in `t`, false for a miss. Inlined where it is called, and t handed back through a
// reference: GCC 12 returns a std::optional<double> through memory, a store-forwarding stall
// that costs as much as a plane's whole intersection and would be timed with the formula.
template <typename T>
[[gnu::always_inline]] inline bool reference_hit_at(Primitive primitive, const Vec3<T>& o,
                                                    const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                                    const T& radius, T& t) {
  using std::sqrt;
  switch (primitive) {
    case Primitive::kSphere: return sphere_nearest(o, d, p[0], radius, t);
    case Primitive::kPlane: {
      std::optional<T> x = plane_t(o, d, p[0], p[1]);
      if (!x || !(*x >= T(0))) return false;
      t = *x;
      return true;
    }
    case Primitive::kTriangle: {
      TriangleHit<T> h = watertight_triangle(o, d, p[0], p[1], p[2]);
      if (!h.hit || !(h.t >= T(0))) return false;
      t = h.t;
      return true;
    }
    case Primitive::kPolygon: {
      std::optional<T> x = plane_t(o, d, newell_normal_of(p), p[0]);
      if (!x || !(*x >= T(0)) || !watertight_polygon(o, d, p)) return false;
      t = *x;
      return true;
    }
    case Primitive::kCylinder: {
      Vec3<T> axis = p[1] / sqrt(dot(p[1], p[1]));
      return cylinder_side_nearest(o, d, p[0], axis, radius, t);
    }
    case Primitive::kBox: {
      SlabInterval<T> s = slab_interval(o, d, p[0], p[1]);
      return s.hit && nearest_root(Roots<T>{2, s.t_enter, s.t_exit}, t);
    }
  }
  return false;
}

// The reference nearest hit of a case, computed in T.
template <typename T>
std::optional<T> reference_nearest(const AccuracyCase& c) {
  T t{};
  if (!reference_hit_at(c.primitive, vector_as<T>(c.origin), vector_as<T>(c.direction),
                        points_as<T>(c), T(c.radius), t))
    return std::nullopt;
  return t;
}

// The naive textbook formulation of the same question, on inputs already in T.
template <typename T>
[[gnu::always_inline]] inline std::optional<T> naive_nearest_at(Primitive primitive,
                                                                const Vec3<T>& o, const Vec3<T>& d,
                                                                const std::vector<Vec3<T>>& p,
                                                                const T& radius) {
  using std::sqrt;
  switch (primitive) {
    case Primitive::kSphere: return naive::sphere(o, d, p[0], radius);
    case Primitive::kPlane: return naive::plane(o, d, p[0], p[1]);
    case Primitive::kTriangle: return naive::triangle(o, d, p[0], p[1], p[2]);
    case Primitive::kPolygon: return naive::polygon(o, d, p);
    case Primitive::kCylinder:
      return naive::cylinder(o, d, p[0], p[1] / sqrt(dot(p[1], p[1])), radius);
    case Primitive::kBox: return naive::box(o, d, p[0], p[1]);
  }
  return std::nullopt;
}

// The naive nearest hit of a case, computed in T.
template <typename T>
std::optional<T> naive_nearest(const AccuracyCase& c) {
  return naive_nearest_at(c.primitive, vector_as<T>(c.origin), vector_as<T>(c.direction),
                          points_as<T>(c), T(c.radius));
}

}  // namespace raygrade
