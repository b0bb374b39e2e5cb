// Nearly tangent rays, rays nearly through an edge, and near ties: outcomes a tolerance
// cannot tell apart.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "check/problem_checks.h"
#include "derivation/number_format.h"
#include "kinds/intersect.h"

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

std::string describe(const ProbeOutcome& o, const FirstHitTask* first) {
  if (first) {
    return o.object < 0 ? "no object hit" : "a hit on " + first->objects()[o.object].name;
  }
  if (o.contained) return "the ray contained in the plane";
  if (o.hits == 0) return "no hit";
  return o.hits == 1 ? "1 hit" : fmt::format("{} hits", o.hits);
}

// The objects of the problem, in order.
std::vector<const Shape*> shapes_of(const Problem& p) {
  if (auto* t = dynamic_cast<const IntersectTask*>(p.task.get())) return {&t->object()};
  std::vector<const Shape*> out;
  if (auto* f = dynamic_cast<const FirstHitTask*>(p.task.get())) {
    for (const auto& o : f->objects()) out.push_back(o.shape.get());
  }
  return out;
}

// Which objects a ray with t_min > 0 starts on: those it meets within `reach` of t = 0.
std::vector<bool> start_surfaces(const Problem& p, const Ray& ray, double reach) {
  std::vector<const Shape*> shapes = shapes_of(p);
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
ProbeOutcome outcome_of(const Problem& p, const Ray& ray, const std::vector<bool>& starts = {},
                        double skip = 0) {
  ProbeOutcome o;
  std::vector<const Shape*> shapes = shapes_of(p);
  auto ray_for = [&](std::size_t i) {
    Ray r = ray;
    if (i < starts.size() && starts[i]) r.t_min = std::max(r.t_min, skip);
    return r;
  };
  bool starting = std::find(starts.begin(), starts.end(), true) != starts.end();
  if (auto* t = dynamic_cast<const IntersectTask*>(p.task.get())) {
    Intersection x = t->object().intersect(ray_for(0));
    o.hits = x.hits.size();
    o.contained = x.contained;
  } else if (auto* f = dynamic_cast<const FirstHitTask*>(p.task.get()); f && !starting) {
    FirstHit h = first_hit(ray, f->objects());
    o.object = h.index;
    o.hits = h.index >= 0 ? 1 : 0;
  } else if (f) {
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
std::optional<ProbeOutcome> shifted_outcome(const Problem& p, const Ray& ray, double distance) {
  double reach = kDepartureBand * distance / length(ray.direction);
  std::vector<bool> starts = start_surfaces(p, ray, reach);
  // With a starting surface, the hits on it near the start are left out here too.
  ProbeOutcome start = outcome_of(p, ray, starts, reach);
  auto [u, v] = sideways(ray.direction);
  for (int k = 0; k < kProbeAngles; ++k) {
    double angle = 2 * std::numbers::pi * k / kProbeAngles;
    Ray shifted = ray;
    shifted.origin = ray.origin + distance * (std::cos(angle) * u + std::sin(angle) * v);
    ProbeOutcome o = outcome_of(p, shifted, starts, reach);
    if (!(o == start)) return o;
  }
  return std::nullopt;
}

void check_close_hits(const Problem& p, const IntersectTask& t, double tol, BoundaryProbe& out) {
  Intersection x = t.object().intersect(t.ray());
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

void check_near_tie(const Problem& p, const FirstHitTask& f, double tol, BoundaryProbe& out) {
  FirstHit h = first_hit(f.ray(), f.objects());
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
                      f.objects()[h.index].name, f.objects()[i].name, format_number(h.hit.t)),
          "tie"));
    } else if (gap <= tol) {
      out.diagnostics.push_back(problem_diagnostic(
          p, "/objects", Severity::kError,
          fmt::format("near tie: {} is hit at t = {} and {} at t = {}, closer than the tolerance "
                      "{}: either could be graded as the first hit",
                      f.objects()[h.index].name, format_number(h.hit.t), f.objects()[i].name,
                      format_number(h.nearest[i]->t), format_number(tol)),
          "near-tie"));
    }
  }
}

// The t at which the tolerance is taken: the first hit's, or for a miss the t where the ray
// passes closest to the object's centre (the first object's, for a first-hit problem).
double typical_t(const Problem& p, const Ray& ray) {
  const Shape* shape = nullptr;
  if (auto* t = dynamic_cast<const IntersectTask*>(p.task.get())) {
    Intersection x = t->object().intersect(ray);
    if (!x.hits.empty()) return x.hits.front().t;
    shape = &t->object();
  } else if (auto* f = dynamic_cast<const FirstHitTask*>(p.task.get())) {
    FirstHit h = first_hit(ray, f->objects());
    if (h.index >= 0) return h.hit.t;
    shape = f->objects().front().shape.get();
  }
  if (!shape) return 1;
  return std::max(0.0,
                  dot(shape->center() - ray.origin, ray.direction) / length_squared(ray.direction));
}

}  // namespace

BoundaryProbe probe_boundaries(const Problem& p) {
  BoundaryProbe out;
  auto* inter = dynamic_cast<const IntersectTask*>(p.task.get());
  auto* first = dynamic_cast<const FirstHitTask*>(p.task.get());
  if (!inter && !first) return out;
  const Ray& ray = inter ? inter->ray() : first->ray();
  double tol = t_tolerance(p, typical_t(p, ray));
  // A t error of `tol` is a distance of tol·|d| along the ray: probe sideways by as much,
  // up to a small fraction of the (smallest) object.
  double size = kInfinity;
  if (inter) size = inter->object().extent();
  if (first) {
    for (const auto& o : first->objects()) size = std::min(size, o.shape->extent());
  }
  double distance = std::min(tol * length(ray.direction), kMaxProbeFraction * size);
  ProbeOutcome base = outcome_of(p, ray);
  out.exact_boundary = shifted_outcome(p, ray, distance * kExactBoundaryFraction).has_value();
  if (first) check_near_tie(p, *first, tol, out);
  // A near tie is itself a boundary between two outcomes: reported once, as a near tie.
  bool reported = !out.diagnostics.empty();
  if (!out.exact_boundary && !reported) {
    if (auto moved = shifted_outcome(p, ray, distance)) {
      out.diagnostics.push_back(problem_diagnostic(
          p, "/ray", Severity::kError,
          fmt::format("nearly tangent: the ray passes within {} of the object's boundary; moved "
                      "sideways by that much (the tolerance on t is {}) it gives {} instead of {}, "
                      "so a student's rounding can turn the answer around",
                      format_number(distance), format_number(tol), describe(*moved, first),
                      describe(base, first)),
          "nearly-tangent"));
    } else if (inter) {
      check_close_hits(p, *inter, tol, out);
    }
  }
  return out;
}

}  // namespace raygrade
