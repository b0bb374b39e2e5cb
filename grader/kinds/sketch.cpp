// Shared parts of the kinds' sketches.
#include "kinds/sketch.h"

#include <cmath>

#include "derivation/number_format.h"

namespace raygrade {
namespace {

// The ray is drawn this much past the farthest thing it meets, so its arrowhead stands clear.
constexpr double kOvershoot = 1.2;

}  // namespace

void sketch_ray(Sketch& figure, const Ray& ray, const std::vector<const Shape*>& objects,
                const std::vector<Hit>& hits) {
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
  figure.arrow(ray.at(t_start), ray.at(t_end), Ink::kRay);
  figure.point(ray.origin, Ink::kPoint, "O");
}

void sketch_hit(Sketch& figure, const Hit& hit, Ink ink, const std::string& prefix) {
  figure.point(hit.point, ink, prefix + "t = " + format_number(hit.t));
}

}  // namespace raygrade
