// Nearly tangent rays, rays nearly through an edge, and near ties: outcomes a tolerance
// cannot tell apart.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "check/problem_checks.h"
#include "derivation/number_format.h"
#include "problems/ray_cast.h"

namespace raygrade {
namespace {

// The sideways probe never moves the ray by more than this fraction of the object's size:
// grazing happens at the object's scale, and a relative tolerance on a far hit (0.1% of
// t = 1000) would otherwise move the ray by whole units, onto another problem.
constexpr double kMaxProbeFraction = 0.01;

// Sideways shifts probe the ray at this many evenly spaced angles around its direction.
constexpr int kProbeAngles = 8;

// The exact-boundary probe is this fraction of the tolerance probe. With the default
// tolerance and a unit direction it moves the ray by 1e-9: far below any digit a person
// prints or rounds to, far above the 1e-16 relative rounding of the solve itself. A boundary
// this close is the designed tangent, edge or vertex case, exact in the printed numbers.
constexpr double kExactBoundaryFraction = 1e-7;

// A ray that leaves a surface (t_min > 0, a shadow, reflection or refraction ray as courses set
// them up) is moved sideways off or into that surface by the probe, which makes or removes a hit
// on it within t·|d| = distance / sin(angle of departure). Those hits are not the answer's: hits
// on the starting surface nearer than this many probe distances are left out of the outcomes, so
// that only departures flatter than asin(1/10) ≈ 5.7°, which are nearly tangent themselves, are
// still reported.
constexpr double kDepartureBand = 10;

// What a grader must tell apart: how many hits, and which object is hit first.
struct ProbeOutcome {
  int object = -1;
  std::size_t hits = 0;
  bool contained = false;
  bool operator==(const ProbeOutcome&) const = default;
};

std::string describe(const ProbeOutcome& o, const RayCast& cast) {
  if (cast.asks_first_object()) {
    return o.object < 0 ? "no object hit" : "a hit on " + std::string(cast.object_name(o.object));
  }
  if (o.contained) return "the ray contained in the plane";
  if (o.hits == 0) return "no hit";
  return o.hits == 1 ? "1 hit" : fmt::format("{} hits", o.hits);
}

// The objects of the problem, in order.
std::vector<const Shape*> shapes_of(const RayCast& cast) {
  std::vector<const Shape*> out;
  for (std::size_t i = 0; i < cast.object_count(); ++i) out.push_back(&cast.object_at(i));
  return out;
}

// Which objects a ray with t_min > 0 starts on: those it meets within `reach` of t = 0.
std::vector<bool> start_surfaces(const RayCast& cast, const Ray& ray, double reach) {
  std::vector<const Shape*> shapes = shapes_of(cast);
  std::vector<bool> out(shapes.size(), false);
  if (ray.t_min <= 0) return out;
  Ray around = ray;
  around.t_min = -reach;
  around.t_max = reach;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    out[i] = !shapes[i]->intersect(around).hits.empty();
  return out;
}

// The outcome of `ray`; hits on a starting surface nearer than `skip` (in t) are left out.
ProbeOutcome outcome_of(const RayCast& cast, const Ray& ray, const std::vector<bool>& starts = {},
                        double skip = 0) {
  ProbeOutcome o;
  std::vector<const Shape*> shapes = shapes_of(cast);
  auto ray_for = [&](std::size_t i) {
    Ray r = ray;
    if (i < starts.size() && starts[i]) r.t_min = std::max(r.t_min, skip);
    return r;
  };
  bool starting = std::find(starts.begin(), starts.end(), true) != starts.end();
  if (!cast.asks_first_object()) {
    Intersection x = shapes.front()->intersect(ray_for(0));
    o.hits = x.hits.size();
    o.contained = x.contained;
  } else if (!starting) {
    FirstHit h = cast.first_met(ray);
    o.object = h.index;
    o.hits = h.index >= 0 ? 1 : 0;
  } else {
    double nearest = kInfinity;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      Intersection x = shapes[i]->intersect(ray_for(i));
      if (!x.hits.empty() && x.hits.front().t < nearest) {
        nearest = x.hits.front().t;
        o.object = static_cast<int>(i);
      }
    }
    o.hits = o.object >= 0 ? 1 : 0;
  }
  return o;
}

// Two unit vectors perpendicular to d and to each other.
std::pair<Vec3d, Vec3d> sideways(const Vec3d& d) {
  Vec3d n = normalized(d);
  Vec3d axis = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z) ? Vec3d{1, 0, 0}
               : std::abs(n.y) <= std::abs(n.z)                                 ? Vec3d{0, 1, 0}
                                                                                : Vec3d{0, 0, 1};
  Vec3d u = normalized(cross(n, axis));
  return {u, cross(n, u)};
}

// The first outcome, among rays shifted sideways by `distance`, that differs from the ray's.
std::optional<ProbeOutcome> shifted_outcome(const RayCast& cast, const Ray& ray, double distance) {
  double reach = kDepartureBand * distance / length(ray.direction);
  std::vector<bool> starts = start_surfaces(cast, ray, reach);
  // With a starting surface, the hits on it near the start are left out here too.
  ProbeOutcome start = outcome_of(cast, ray, starts, reach);
  auto [u, v] = sideways(ray.direction);
  for (int k = 0; k < kProbeAngles; ++k) {
    double angle = 2 * std::numbers::pi * k / kProbeAngles;
    Ray shifted = ray;
    shifted.origin = ray.origin + distance * (std::cos(angle) * u + std::sin(angle) * v);
    ProbeOutcome o = outcome_of(cast, shifted, starts, reach);
    if (!(o == start)) return o;
  }
  return std::nullopt;
}

void check_close_hits(const Problem& p, const RayCast& cast, double tol, BoundaryProbe& out) {
  Intersection x = cast.object_at(0).intersect(cast.cast_ray());
  for (std::size_t i = 0; i + 1 < x.hits.size(); ++i) {
    double gap = x.hits[i + 1].t - x.hits[i].t;
    if (gap <= 2 * tol) {
      out.diagnostics.push_back(problem_diagnostic(
          p, "/ray", Severity::kError,
          fmt::format("nearly tangent: the hits at t = {} and t = {} are {} apart, within twice "
                      "the tolerance {}: a single touching hit between them would be graded "
                      "right too",
                      format_number(x.hits[i].t), format_number(x.hits[i + 1].t),
                      format_number(gap), format_number(tol)),
          "nearly-tangent"));
      return;
    }
  }
}

// The problem's expected answer says "tie": true: its author made the tie on purpose, and the
// statement tells students which object is named (the first in the list).
bool stated_tie(const Problem& p) {
  if (!p.expected || !p.expected->is_object()) return false;
  auto it = p.expected->find("tie");
  return it != p.expected->end() && it->is_boolean() && it->get<bool>();
}

void check_near_tie(const Problem& p, const RayCast& cast, double tol, BoundaryProbe& out) {
  FirstHit h = cast.first_met(cast.cast_ray());
  if (h.index < 0) return;
  for (std::size_t i = 0; i < h.nearest.size(); ++i) {
    if (static_cast<int>(i) == h.index || !h.nearest[i]) continue;
    double gap = h.nearest[i]->t - h.hit.t;
    if (gap == 0 && stated_tie(p)) continue;  // designed: the statement names the rule
    if (gap == 0) {
      out.diagnostics.push_back(problem_diagnostic(
          p, "/objects", Severity::kWarning,
          fmt::format("{} and {} are both first hit at t = {}: the answer names the first in the "
                      "list, which students cannot know",
                      cast.object_name(h.index), cast.object_name(i), format_number(h.hit.t)),
          "tie"));
    } else if (gap <= tol) {
      out.diagnostics.push_back(problem_diagnostic(
          p, "/objects", Severity::kError,
          fmt::format("near tie: {} is hit at t = {} and {} at t = {}, closer than the tolerance "
                      "{}: either could be graded as the first hit",
                      cast.object_name(h.index), format_number(h.hit.t), cast.object_name(i),
                      format_number(h.nearest[i]->t), format_number(tol)),
          "near-tie"));
    }
  }
}

// The t at which the tolerance is taken: the first hit's, or for a miss the t where the ray
// passes closest to the object's centre (the first object's, for a first-hit problem).
double typical_t(const RayCast& cast, const Ray& ray) {
  FirstHit h = cast.first_met(ray);
  if (h.index >= 0) return h.hit.t;
  const Shape& shape = cast.object_at(0);
  return std::max(0.0,
                  dot(shape.center() - ray.origin, ray.direction) / length_squared(ray.direction));
}

}  // namespace

BoundaryProbe probe_boundaries(const Problem& p) {
  BoundaryProbe out;
  const RayCast* cast = p.task->ray_cast();
  if (!cast) return out;
  const Ray& ray = cast->cast_ray();
  double tol = t_tolerance(p, typical_t(*cast, ray));
  // A t error of `tol` is a distance of tol·|d| along the ray: probe sideways by as much,
  // up to a small fraction of the (smallest) object.
  double size = kInfinity;
  for (const Shape* shape : shapes_of(*cast)) size = std::min(size, shape->extent());
  double distance = std::min(tol * length(ray.direction), kMaxProbeFraction * size);
  ProbeOutcome base = outcome_of(*cast, ray);
  out.exact_boundary = shifted_outcome(*cast, ray, distance * kExactBoundaryFraction).has_value();
  if (cast->asks_first_object()) check_near_tie(p, *cast, tol, out);
  // A near tie is itself a boundary between two outcomes: reported once, as a near tie.
  bool reported = !out.diagnostics.empty();
  if (!out.exact_boundary && !reported) {
    if (auto moved = shifted_outcome(*cast, ray, distance)) {
      out.diagnostics.push_back(problem_diagnostic(
          p, "/ray", Severity::kError,
          fmt::format("nearly tangent: the ray passes within {} of the object's boundary; moved "
                      "sideways by that much (the tolerance on t is {}) it gives {} instead of {}, "
                      "so a student's rounding can turn the answer around",
                      format_number(distance), format_number(tol), describe(*moved, *cast),
                      describe(base, *cast)),
          "nearly-tangent"));
    } else if (!cast->asks_first_object()) {
      check_close_hits(p, *cast, tol, out);
    }
  }
  return out;
}

}  // namespace raygrade
