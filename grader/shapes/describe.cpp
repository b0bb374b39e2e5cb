// Conclusion sentences shared by the primitives.
#include "shapes/describe.h"

#include <fmt/format.h>

#include "derivation/number_format.h"

namespace raygrade {

std::string range_reason(const Ray& ray, double t) {
  if (t < ray.t_min) {
    return ray.t_min == 0 ? "it lies behind the origin (t < 0)"
                          : fmt::format("it lies before t_min = {}", format_number(ray.t_min));
  }
  if (t > ray.t_max) return fmt::format("it lies past t_max = {}", format_number(ray.t_max));
  return "";
}

void conclude_candidates(Deriver& d, const std::string& object, const Ray& /*ray*/,
                         const std::vector<Candidate>& candidates, bool solid) {
  std::vector<const Candidate*> hits;
  for (const auto& c : candidates) {
    if (c.rejected.empty()) hits.push_back(&c);
  }
  auto at = [](const Candidate* c) {
    return fmt::format("t = {}, at P = {}", format_number(c->t), format_vector(c->point));
  };
  if (hits.empty()) {
    d.conclude(fmt::format("The ray does not hit the {}.", object));
  } else if (hits.size() == 1) {
    bool tangent = solid && candidates.size() == 1;
    d.conclude(
        fmt::format("The ray {} the {} at {}.", tangent ? "touches" : "hits", object, at(hits[0])));
  } else if (solid && hits.size() == 2) {
    d.conclude(fmt::format("The ray enters the {} at {}, and leaves at {}.", object, at(hits[0]),
                           at(hits[1])));
  } else {
    std::string list;
    for (std::size_t i = 0; i < hits.size(); ++i) list += (i ? "; " : "") + at(hits[i]);
    d.conclude(fmt::format("The ray hits the {} at {}.", object, list));
  }
  for (const auto& c : candidates) {
    if (!c.rejected.empty()) {
      d.conclude(fmt::format("t = {} is not a hit: {}.", format_number(c.t), c.rejected));
    }
  }
}

}  // namespace raygrade
