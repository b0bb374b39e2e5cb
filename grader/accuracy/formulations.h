// The nearest hit (t ≥ 0) of an AccuracyCase by the reference formulation or the naive one,
// at any number type: one template per formulation, instantiated for every level of the ladder.
#pragma once

#include <optional>

#include "accuracy/accuracy_case.h"
#include "accuracy/naive.h"
#include "shapes/box.h"
#include "shapes/cylinder.h"
#include "shapes/plane.h"
#include "shapes/polygon.h"
#include "shapes/sphere.h"
#include "shapes/triangle.h"

namespace raygrade {

// Newell's normal (as Polygon uses), at any number type.
template <typename T>
Vec3<T> newell_normal_of(const std::vector<Vec3<T>>& v) {
  Vec3<T> n{};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3<T>& a = v[i];
    const Vec3<T>& b = v[(i + 1) % v.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

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

// The first root at t ≥ 0.
template <typename T>
std::optional<T> nearest_of(const Roots<T>& r) {
  if (r.count == 0) return std::nullopt;
  if (r.t0 >= T(0)) return r.t0;
  if (r.t1 >= T(0)) return r.t1;
  return std::nullopt;
}

// The reference: the templates the solver's Shape::intersect runs in double, on inputs
// already in T (points and radius as AccuracyCase describes them).
// Inlined where it is called, as naive_nearest is: a std::optional<double> returned from a call
// is stored and reloaded through memory by GCC 12, a store-forwarding stall that costs as much as
// a plane's whole intersection and would be timed as part of the formula.
template <typename T>
[[gnu::always_inline]] inline std::optional<T> reference_nearest_at(Primitive primitive,
                                                                    const Vec3<T>& o,
                                                                    const Vec3<T>& d,
                                                                    const std::vector<Vec3<T>>& p,
                                                                    const T& radius) {
  using std::sqrt;
  switch (primitive) {
    case Primitive::kSphere: return nearest_of(sphere_roots(o, d, p[0], radius));
    // Each returns *t rather than the optional t: copying a std::optional<double> through
    // memory stalls store forwarding and cost as much as the plane's whole fast path (GCC 12).
    case Primitive::kPlane: {
      std::optional<T> t = plane_t(o, d, p[0], p[1]);
      if (t && *t >= T(0)) return *t;
      return std::nullopt;
    }
    case Primitive::kTriangle: {
      TriangleHit<T> h = watertight_triangle(o, d, p[0], p[1], p[2]);
      if (h.hit && h.t >= T(0)) return h.t;
      return std::nullopt;
    }
    case Primitive::kPolygon: {
      std::optional<T> t = plane_t(o, d, newell_normal_of(p), p[0]);
      if (!t || !(*t >= T(0)) || !watertight_polygon(o, d, p)) return std::nullopt;
      return *t;
    }
    case Primitive::kCylinder: {
      Vec3<T> axis = p[1] / sqrt(dot(p[1], p[1]));
      return nearest_of(cylinder_side_roots(o, d, p[0], axis, radius));
    }
    case Primitive::kBox: {
      SlabInterval<T> s = slab_interval(o, d, p[0], p[1]);
      if (!s.hit) return std::nullopt;
      if (s.t_enter >= T(0)) return s.t_enter;
      if (s.t_exit >= T(0)) return s.t_exit;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

// The reference nearest hit of a case, computed in T.
template <typename T>
std::optional<T> reference_nearest(const AccuracyCase& c) {
  return reference_nearest_at(c.primitive, Vec3<T>(c.origin), Vec3<T>(c.direction), points_as<T>(c),
                              T(c.radius));
}

// The naive textbook formulation of the same question.
template <typename T>
std::optional<T> naive_nearest(const AccuracyCase& c) {
  using std::sqrt;
  Vec3<T> o(c.origin), d(c.direction);
  const std::vector<Vec3<T>>& p = points_as<T>(c);
  switch (c.primitive) {
    case Primitive::kSphere: return naive::sphere(o, d, p[0], T(c.radius));
    case Primitive::kPlane: return naive::plane(o, d, p[0], p[1]);
    case Primitive::kTriangle: return naive::triangle(o, d, p[0], p[1], p[2]);
    case Primitive::kPolygon: return naive::polygon(o, d, p);
    case Primitive::kCylinder:
      return naive::cylinder(o, d, p[0], p[1] / sqrt(dot(p[1], p[1])), T(c.radius));
    case Primitive::kBox: return naive::box(o, d, p[0], p[1]);
  }
  return std::nullopt;
}

}  // namespace raygrade
