// The nearest hit (t ≥ 0) of an AccuracyCase by the reference formulation or the naive one,
// at any number type: each primitive's Ladder templates, instantiated for every level of the
// ladder.
#pragma once

#include <optional>
#include <type_traits>
#include <vector>

#include "shapes/accuracy_case.h"

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
// already in T (points and radius as the primitive's Ladder describes them). True with the
// nearest hit at t ≥ 0 in `t`, false for a miss. The per-primitive functions of the ladder
// (ladder.cpp) call P::Ladder::reference directly, inlined, and hand t back through a
// reference: GCC 12 returns a std::optional<double> through memory, a store-forwarding stall
// that costs as much as a plane's whole intersection and would be timed with the formula.
template <typename T>
bool reference_hit_at(Primitive primitive, const Vec3<T>& o, const Vec3<T>& d,
                      const std::vector<Vec3<T>>& p, const T& radius, T& t) {
  return visit_primitive(primitive,
                         [&]<typename P>() { return P::Ladder::reference(o, d, p, radius, t); });
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
std::optional<T> naive_nearest_at(Primitive primitive, const Vec3<T>& o, const Vec3<T>& d,
                                  const std::vector<Vec3<T>>& p, const T& radius) {
  return visit_primitive(primitive,
                         [&]<typename P>() { return P::Ladder::naive(o, d, p, radius); });
}

// The naive nearest hit of a case, computed in T.
template <typename T>
std::optional<T> naive_nearest(const AccuracyCase& c) {
  return naive_nearest_at(c.primitive, vector_as<T>(c.origin), vector_as<T>(c.direction),
                          points_as<T>(c), T(c.radius));
}

}  // namespace raygrade
