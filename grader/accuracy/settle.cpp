// Shapes as accuracy cases, and the solver's adaptive decision.
#include "accuracy/settle.h"

#include <algorithm>
#include <cmath>

#include "accuracy/certified.h"

namespace raygrade {
namespace {

// How far before a hit double missed (in units of the direction) the ray starts that asks
// the object for its normal there: far beyond rounding (1e-16), close enough that the probe
// meets the same part of the surface.
constexpr double kNormalProbeBack = 1e-6;

}  // namespace

std::optional<AccuracyCase> accuracy_case_of(const Shape& object, const Ray& ray) {
  if (ray.t_min != 0 || ray.t_max != kInfinity) return std::nullopt;
  // The object's primitive, when it is one of the study's: a transformed object is not (its
  // type is the wrapper's), and has no case of its own: the ladder's formulations are the
  // primitives' in world coordinates, and the solver answers it in double (docs/precision.md).
  AccuracyCase c;
  bool found = false;
  for_each_ladder_primitive([&]<typename P>() {
    if (const auto* shape = dynamic_cast<const P*>(&object)) {
      c.primitive = primitive_of<P>();
      found = P::Ladder::case_of(*shape, c.points, c.radius);
    }
  });
  if (!found) return std::nullopt;
  c.id = "problem";
  c.group = "problem";
  c.origin = ray.origin;
  // The direction scaled into [1, 2) by a power of two, as the shapes intersect it
  // (intersect_rescaled): exact, and t is then 2^k times the problem's.
  int k = direction_exponent(ray.direction);
  c.direction = scaled_by_power_of_two(ray.direction, -k);
  return c;
}

std::unique_ptr<Shape> shape_of(const AccuracyCase& c) {
  return visit_primitive(c.primitive,
                         [&]<typename P>() { return P::Ladder::shape_of(c.points, c.radius); });
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
