// Shared helpers of the primitives: reading by type, and ordering hits.
#include "shapes/shape.h"

#include <algorithm>
#include <cmath>

#include "math/robust.h"
#include "shapes/transformed.h"

namespace raygrade {

const std::vector<std::string>& common_object_keys() {
  static const std::vector<std::string> keys = {"type", "name", "material", "transform",
                                                "half_space"};
  return keys;
}

std::unique_ptr<Shape> read_primitive(const Cursor& object) {
  if (!object.is_object()) object.fail("expected an object with a 'type'", "type");
  std::string type = object.at("type").string();
  std::vector<std::string> names;
  for (const auto& entry : shape_table()) {
    if (entry.type == type) return entry.read(object);
    names.emplace_back(entry.type);
  }
  std::string hint = closest_match(type, names);
  object.at("type").fail(
      hint.empty()
          ? fmt::format("unknown object type '{}' (known: {})", type, fmt::join(names, ", "))
          : fmt::format("unknown object type '{}' (did you mean '{}'?)", type, hint),
      "unknown-type");
}

std::unique_ptr<Shape> read_shape(const Cursor& object) {
  std::unique_ptr<Shape> shape = read_primitive(object);
  if (auto m = object.find("material")) {
    m->fail("a material is used in scenes only: this kind neither shades nor traces", "unused-key");
  }
  if (auto h = object.find("half_space")) {
    h->fail("half_space is used in scenes only: this kind does not refract", "unused-key");
  }
  if (auto t = object.find("transform")) {
    Transform transform = read_transform(*t);
    if (!transform.identity()) {
      return std::make_unique<TransformedShape>(std::move(shape), std::move(transform));
    }
  }
  return shape;
}

int direction_exponent(const Vec3d& direction) { return scale_exponent(direction); }

std::optional<Intersection> intersect_rescaled(const Shape& shape, const Ray& ray) {
  int k = direction_exponent(ray.direction);
  if (k == 0) return std::nullopt;
  Ray unit{ray.origin, scaled_by_power_of_two(ray.direction, -k), std::ldexp(ray.t_min, k),
           std::ldexp(ray.t_max, k)};
  Intersection x = shape.intersect(unit);
  std::vector<Hit> hits;
  for (Hit& h : x.hits) {
    h.t = std::ldexp(h.t, -k);
    // A t beyond double's range has no hit to report.
    if (ray.accepts(h.t)) hits.push_back(std::move(h));
  }
  x.hits = std::move(hits);
  return x;
}

void finish_hits(std::vector<Hit>& hits, double seam_distance) {
  std::stable_sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
  // Two hits at the same t are the same point of the ray: a seam between two parts of the
  // surface. Equal within a few ulps, since both parts compute t by different formulas.
  constexpr double kSeamUlps = 8 * 2.220446049250313e-16;
  std::vector<Hit> out;
  for (auto& h : hits) {
    if (!out.empty() && (std::abs(h.t - out.back().t) <= kSeamUlps * std::max(1.0, std::abs(h.t)) ||
                         length(h.point - out.back().point) <= seam_distance)) {
      continue;
    }
    out.push_back(std::move(h));
  }
  hits = std::move(out);
}

}  // namespace raygrade
