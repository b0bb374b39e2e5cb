// Reflection, refraction and the Phong terms.
#include "scenes/optics.h"

#include <cmath>
#include <numbers>

namespace raygrade {

Vec3d reflect(const Vec3d& d, const Vec3d& n) { return d - 2 * dot(d, n) * n; }

Refraction refract(const Vec3d& d, const Vec3d& n, double n1, double n2) {
  Refraction r;
  r.eta = n1 / n2;
  r.cos_i = -dot(d, n);
  r.k = 1 - r.eta * r.eta * (1 - r.cos_i * r.cos_i);
  if (r.k < 0) {
    r.total_internal_reflection = true;
    return r;
  }
  r.direction = normalized(r.eta * d + (r.eta * r.cos_i - std::sqrt(r.k)) * n);
  return r;
}

std::optional<double> critical_angle_degrees(double n1, double n2) {
  if (n1 <= n2) return std::nullopt;
  return std::asin(n2 / n1) * 180 / std::numbers::pi;
}

PhongLight phong_light(const Vec3d& n, const Vec3d& l, const Vec3d& v, double intensity, double k_d,
                       double k_s, double shininess) {
  PhongLight p;
  p.n_dot_l = dot(n, l);
  p.r = 2 * p.n_dot_l * n - l;
  p.r_dot_v = dot(p.r, v);
  if (p.n_dot_l <= 0) return p;
  p.diffuse = k_d * intensity * p.n_dot_l;
  if (p.r_dot_v > 0) p.specular = k_s * intensity * std::pow(p.r_dot_v, shininess);
  return p;
}

}  // namespace raygrade
