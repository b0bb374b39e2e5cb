// Nested media: the list of media a ray is inside, and n1 and n2 at each boundary.
#include "scenes/media.h"

#include <algorithm>
#include <optional>

#include "derivation/number_format.h"

namespace raygrade {

bool is_medium(const SceneObject& o) { return o.solid && o.material.transmits(); }

double medium_index(const Scene& scene, const std::vector<int>& media) {
  if (media.empty()) return scene.refractive_index;
  return scene.objects[media.back()].material.refractive_index;
}

Crossing cross_boundary(const Scene& scene, const std::vector<int>& media, int object, double t) {
  Crossing c;
  c.object = object;
  c.t = t;
  c.before = media;
  c.after = media;
  if (is_medium(scene.objects[object])) {
    // Leave the object if the ray is inside it, else enter it as the innermost medium.
    auto it = std::find(c.after.begin(), c.after.end(), object);
    if (it != c.after.end()) {
      c.after.erase(it);
    } else {
      c.after.push_back(object);
    }
  }
  c.enters = std::find(c.after.begin(), c.after.end(), object) != c.after.end();
  c.n1 = medium_index(scene, c.before);
  c.n2 = medium_index(scene, c.after);
  return c;
}

namespace {

// The first hit of one object along a ray, if any.
std::optional<SceneHit> first_hit_of(const Scene& scene, int object, const Ray& ray) {
  for (const auto& h : every_hit(scene, ray)) {
    if (h.object == object) return h;
  }
  return std::nullopt;
}

// Whether the point is inside the medium: the first hit of a ray from it meets the boundary
// from inside. The ray's own direction first, then its reverse and the axes, for a boundary
// the ray runs away from or along (a half-space's plane); no hit at all means outside.
bool contains(const Scene& scene, int object, const Ray& ray) {
  for (const Vec3d& d :
       {ray.direction, -ray.direction, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}}) {
    if (auto h = first_hit_of(scene, object, Ray{ray.origin, d, ray.t_min, kInfinity})) {
      return dot(d, h->hit.normal) > 0;
    }
  }
  return false;
}

}  // namespace

std::vector<int> media_at_origin(const Scene& scene, const Ray& ray) {
  // The medium the ray leaves last (or never) is the outermost: first on the list.
  std::vector<std::pair<double, int>> inside;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    int o = static_cast<int>(i);
    if (!is_medium(scene.objects[i]) || !contains(scene, o, ray)) continue;
    auto h = first_hit_of(scene, o, Ray{ray.origin, ray.direction, ray.t_min, kInfinity});
    inside.emplace_back(h ? h->hit.t : kInfinity, o);
  }
  std::stable_sort(inside.begin(), inside.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<int> out;
  out.reserve(inside.size());
  for (const auto& m : inside) out.push_back(m.second);
  return out;
}

std::vector<Crossing> crossings(const Scene& scene, const Ray& ray) {
  std::vector<Crossing> out;
  std::vector<int> media = media_at_origin(scene, ray);
  for (const auto& h : every_hit(scene, ray)) {
    out.push_back(cross_boundary(scene, media, h.object, h.hit.t));
    media = out.back().after;
  }
  return out;
}

std::string media_words(const Scene& scene, const std::vector<int>& media) {
  if (media.empty()) {
    return fmt::format("the space between objects (n = {})", format_number(scene.refractive_index));
  }
  const SceneObject& inner = scene.objects[media.back()];
  std::string s =
      fmt::format("{} (n = {})", inner.name, format_number(inner.material.refractive_index));
  if (media.size() > 1) {
    std::vector<std::string> outer;
    for (std::size_t i = media.size() - 1; i-- > 0;) outer.push_back(scene.objects[media[i]].name);
    s += fmt::format(", inside {}", fmt::join(outer, " inside "));
  }
  return s;
}

}  // namespace raygrade
