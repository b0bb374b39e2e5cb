// Shapes as accuracy cases, and the solver's adaptive decision.
#include "accuracy/settle.h"

#include <algorithm>
#include <cmath>

#include "accuracy/certified.h"
#include "shapes/box.h"
#include "shapes/cylinder.h"
#include "shapes/plane.h"
#include "shapes/polygon.h"
#include "shapes/sphere.h"
#include "shapes/triangle.h"

namespace raygrade {
namespace {

// How far before a hit double missed (in units of the direction) the ray starts that asks
// the object for its normal there: far beyond rounding (1e-16), close enough that the probe
// meets the same part of the surface.
constexpr double kNormalProbeBack = 1e-6;

Vec3d vec(const nlohmann::json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

}  // namespace

std::optional<AccuracyCase> accuracy_case_of(const Shape& object, const Ray& ray) {
  if (ray.t_min != 0 || ray.t_max != kInfinity) return std::nullopt;
  nlohmann::json j = object.to_json();
  // A transformed object has no case of its own: the ladder's formulations are the primitives'
  // in world coordinates, and the solver answers it in double (docs/precision.md).
  if (j.contains("transform")) return std::nullopt;
  AccuracyCase c;
  c.id = "problem";
  c.group = "problem";
  c.origin = ray.origin;
  // The direction scaled into [1, 2) by a power of two, as the shapes intersect it
  // (intersect_rescaled): exact, and t is then 2^k times the problem's.
  int k = direction_exponent(ray.direction);
  c.direction = scaled_by_power_of_two(ray.direction, -k);
  std::string_view type = object.type();
  if (type == "sphere") {
    c.primitive = Primitive::kSphere;
    c.points = {vec(j["center"])};
    c.radius = j["radius"].get<double>();
  } else if (type == "plane" && j.contains("point")) {
    c.primitive = Primitive::kPlane;
    c.points = {vec(j["normal"]), vec(j["point"])};
  } else if (type == "triangle" || type == "polygon") {
    c.primitive = type == "triangle" ? Primitive::kTriangle : Primitive::kPolygon;
    for (const auto& v : j["vertices"]) c.points.push_back(vec(v));
  } else if (type == "cylinder" && !j.contains("height")) {
    c.primitive = Primitive::kCylinder;
    c.points = {vec(j["base"]), vec(j["axis"])};
    c.radius = j["radius"].get<double>();
  } else if (type == "box") {
    c.primitive = Primitive::kBox;
    c.points = {vec(j["min"]), vec(j["max"])};
  } else {
    return std::nullopt;
  }
  return c;
}

std::unique_ptr<Shape> shape_of(const AccuracyCase& c) {
  const std::vector<Vec3d>& p = c.points;
  switch (c.primitive) {
    case Primitive::kSphere: return std::make_unique<Sphere>(p[0], c.radius);
    case Primitive::kPlane: return std::make_unique<Plane>(p[0], p[1], std::nullopt);
    case Primitive::kTriangle: return std::make_unique<Triangle>(p[0], p[1], p[2]);
    case Primitive::kPolygon: return std::make_unique<Polygon>(p);
    case Primitive::kCylinder:
      return std::make_unique<Cylinder>(p[0], p[1], c.radius, std::nullopt, false);
    case Primitive::kBox: return std::make_unique<Box>(p[0], p[1]);
  }
  return nullptr;
}

namespace {

// settle_nearest on the object's accuracy case `c`, returning the level itself.
Level settle_case(const AccuracyCase& c, const Shape& object, const Ray& ray, Intersection& x) {
  Adaptive a = adaptive_nearest(c);
  // Certified double deciding differently from the solver is certain too: a plane the solver
  // takes as parallel up to rounding, which the ray still crosses.
  if (a.level != Level::kExactBoundary && a.hit != !x.hits.empty()) {
    if (!a.hit) {
      x.hits.clear();
    } else {
      Hit h;
      h.t = std::ldexp(a.t, -direction_exponent(ray.direction));
      if (!ray.accepts(h.t)) return a.level;  // beyond what a double holds
      h.point = ray.at(h.t);
      // The normal: the object's own, from a ray that starts a little before the hit; when
      // that ray is parallel to the surface up to rounding too (a plane the ray crosses at a
      // glancing 1e-16), from rays along the axes through the hit point.
      std::vector<Ray> probes = {Ray{h.point - kNormalProbeBack * ray.direction, ray.direction}};
      double step = kNormalProbeBack * std::max(1.0, length(h.point));
      for (int axis = 0; axis < 3; ++axis) {
        Vec3d e{};
        e[axis] = 1;
        probes.push_back(Ray{h.point - step * e, e});
      }
      for (const Ray& probe : probes) {
        Intersection near = object.intersect(probe);
        if (near.hits.empty()) continue;
        h.normal = near.hits.front().normal;
        break;
      }
      x.hits.insert(x.hits.begin(), h);
    }
  }
  return a.level;
}

}  // namespace

std::optional<std::string> settle_nearest(const Shape& object, const Ray& ray, Intersection& x) {
  if (x.contained) return std::nullopt;
  std::optional<AccuracyCase> c = accuracy_case_of(object, ray);
  if (!c) return std::nullopt;
  return std::string(level_name(settle_case(*c, object, ray, x)));
}

std::optional<std::string> settle_first(const std::vector<const Shape*>& objects, const Ray& ray,
                                        std::vector<Intersection>& hits, int& index, bool& tie) {
  std::vector<AccuracyCase> cases;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    std::optional<AccuracyCase> c = accuracy_case_of(*objects[i], ray);
    if (!c || hits[i].contained) return std::nullopt;
    cases.push_back(std::move(*c));
  }
  Level level = Level::kDouble;
  std::vector<Level> levels;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    levels.push_back(settle_case(cases[i], *objects[i], ray, hits[i]));
    level = std::max(level, levels.back());
  }
  index = -1;
  tie = false;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (hits[i].hits.empty()) continue;
    if (index < 0) {
      index = static_cast<int>(i);
      continue;
    }
    Order order;
    if (levels[index] == Level::kExactBoundary || levels[i] == Level::kExactBoundary) {
      // A hit on a boundary has no certified enclosure to compare: its answered t orders it.
      double ta = hits[index].hits.front().t, tb = hits[i].hits.front().t;
      order = {ta < tb ? -1 : tb < ta ? 1 : 0, Level::kExactBoundary};
    } else {
      order = order_nearest(cases[index], cases[i]);
    }
    level = std::max(level, order.level);
    if (order.sign == 0) {
      tie = true;
    } else if (order.sign > 0) {
      index = static_cast<int>(i);
      tie = false;
    }
  }
  return std::string(level_name(level));
}

}  // namespace raygrade
