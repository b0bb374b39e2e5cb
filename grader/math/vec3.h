// Vec3: a 3-vector over any number type, with the operations intersection code needs.
#pragma once

#include <fmt/format.h>

#include <cmath>

namespace raygrade {

template <typename T>
struct Vec3 {
  T x{}, y{}, z{};

  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Vec3(const Vec3<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}

  constexpr const T& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  friend constexpr Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend constexpr Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
  friend constexpr Vec3 operator*(const T& s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend constexpr Vec3 operator*(const Vec3& a, const T& s) { return {s * a.x, s * a.y, s * a.z}; }
  friend constexpr Vec3 operator/(const Vec3& a, const T& s) { return {a.x / s, a.y / s, a.z / s}; }
  friend constexpr bool operator==(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
};

using Vec3d = Vec3<double>;

template <typename T>
constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <typename T>
constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <typename T>
constexpr T length_squared(const Vec3<T>& a) {
  return dot(a, a);
}

template <typename T>
T length(const Vec3<T>& a) {
  using std::sqrt;
  return sqrt(length_squared(a));
}

template <typename T>
Vec3<T> normalized(const Vec3<T>& a) {
  return a / length(a);
}

// The components' magnitudes, (|a.x|, |a.y|, |a.z|).
template <typename T>
Vec3<T> magnitudes(const Vec3<T>& a) {
  using std::abs;
  return {abs(a.x), abs(a.y), abs(a.z)};
}

// The 1-norm |a.x| + |a.y| + |a.z|, which the error bounds of the static filters take.
template <typename T>
T norm1(const Vec3<T>& a) {
  using std::abs;
  return abs(a.x) + abs(a.y) + abs(a.z);
}

// Index of the component with the largest magnitude.
template <typename T>
int max_dimension(const Vec3<T>& a) {
  using std::abs;
  T ax = abs(a.x), ay = abs(a.y), az = abs(a.z);
  return ax >= ay ? (ax >= az ? 0 : 2) : (ay >= az ? 1 : 2);
}

inline bool is_finite(const Vec3d& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace raygrade

template <typename T>
struct fmt::formatter<raygrade::Vec3<T>> : fmt::formatter<double> {
  template <typename Ctx>
  auto format(const raygrade::Vec3<T>& v, Ctx& ctx) const {
    return fmt::format_to(ctx.out(), "({}, {}, {})", double(v.x), double(v.y), double(v.z));
  }
};
