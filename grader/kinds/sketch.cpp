// Shared parts of the kinds' sketches.
#include "kinds/sketch.h"

#include <cmath>

#include "derivation/number_format.h"
#include "math/robust.h"

namespace raygrade {
namespace {

// The ray is drawn this much past the farthest thing it meets, so its arrowhead stands clear.
constexpr double kOvershoot = 1.2;
// A tangential part shorter than this fraction of the vector counts as zero: the vector runs
// along the normal (normal incidence), and the view takes any direction along the surface.
constexpr double kAlongNormal = 1e-9;

}  // namespace

void sketch_ray(Sketch& figure, const Ray& ray, const std::vector<const Shape*>& objects,
                const std::vector<Hit>& hits, const std::string& origin_label,
                const std::string& ray_label) {
  // The drawing does not depend on the direction's scale: it is drawn with the direction
  // scaled into [1, 2) by a power of two, whose squared length neither overflows nor
  // underflows (a direction of 1e-170 would give a ray of NaN).
  if (int k = direction_exponent(ray.direction); k != 0) {
    Ray unit{ray.origin, scaled_by_power_of_two(ray.direction, -k), std::ldexp(ray.t_min, k),
             std::ldexp(ray.t_max, k)};
    std::vector<Hit> unit_hits = hits;
    for (Hit& h : unit_hits) h.t = std::ldexp(h.t, k);
    sketch_ray(figure, unit, objects, unit_hits, origin_label, ray_label);
    return;
  }
  figure.across = ray.direction;
  figure.across_name = "the ray's direction";
  double dd = length_squared(ray.direction);
  double len = std::sqrt(dd);
  double t_start = std::isfinite(ray.t_min) ? ray.t_min : 0;
  double t_end = t_start;
  for (const auto& h : hits) t_end = std::max(t_end, h.t);
  for (const Shape* s : objects) {
    double closest = dot(s->center() - ray.origin, ray.direction) / dd;
    t_end = std::max(t_end, closest + s->extent() / len);
  }
  t_end = t_start + kOvershoot * (t_end - t_start);
  if (t_end <= t_start) {
    // Everything lies behind the origin: draw a ray as long as the largest object.
    double size = 1;
    for (const Shape* s : objects) size = std::max(size, 2 * s->extent());
    t_end = t_start + size / len;
  }
  if (std::isfinite(ray.t_max)) t_end = std::min(t_end, ray.t_max);
  if (t_start != 0) figure.path({ray.origin, ray.at(t_start)}, false, Ink::kGuide);
  figure.arrow(ray.at(t_start), ray.at(t_end), Ink::kRay, ray_label);
  figure.point(ray.origin, Ink::kPoint, origin_label);
}

void sketch_hit(Sketch& figure, const Hit& hit, Ink ink, const std::string& prefix) {
  figure.point(hit.point, ink, prefix + "t = " + format_number(hit.t));
}

std::string sketch_vector(const Vec3d& v) {
  std::string text = format_vector(v), out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    // A number's sign follows "(" or a space; an exponent's follows its "e".
    bool sign = text[i] == '-' && i > 0 && (text[i - 1] == '(' || text[i - 1] == ' ');
    out += sign ? std::string("−") : std::string(1, text[i]);
  }
  return out;
}

Vec3d sketch_surface(Sketch& figure, const Vec3d& at, const Vec3d& normal, const Vec3d& along,
                     const std::string& normal_label) {
  Vec3d right = along - dot(along, normal) * normal;
  if (length(right) <= kAlongNormal * length(along)) {
    Vec3d helper = std::abs(normal.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    right = cross(helper, normal);
  }
  right = normalized(right);
  figure.across = right;
  figure.across_name = "along the surface";
  figure.up = normal;
  figure.up_name = "the normal";
  figure.plane(at, normal, Ink::kObject, "surface");
  figure.arrow(at, at + normal, Ink::kObject, normal_label);
  return right;
}

void sketch_incoming(Sketch& figure, const Vec3d& at, const Vec3d& direction,
                     const std::string& label) {
  figure.path({at - direction, at}, false, Ink::kRay);
  figure.arrow(at - direction, at - 0.5 * direction, Ink::kRay, label);
}

}  // namespace raygrade
