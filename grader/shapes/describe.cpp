// Conclusion sentences shared by the primitives.
#include "shapes/describe.h"

#include <fmt/format.h>

#include <algorithm>

#include "derivation/number_format.h"
#include "shapes/round.h"

namespace raygrade {

std::string range_reason(const Ray& ray, double t) {
  if (t < ray.t_min) {
    return ray.t_min == 0 ? "it lies behind the origin (t < 0)"
                          : fmt::format("it lies before t_min = {}", format_number(ray.t_min));
  }
  if (t > ray.t_max) return fmt::format("it lies past t_max = {}", format_number(ray.t_max));
  return "";
}

std::vector<Candidate> each_hit_once(std::vector<Candidate> candidates) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.t < y.t; });
  std::vector<Candidate> once;
  for (auto& c : candidates) {
    bool seen = false;
    for (const auto& kept : once) {
      seen = seen || (kept.rejected.empty() && c.rejected.empty() &&
                      length(kept.point - c.point) <= kSeamRelative * (1 + length(c.point)));
    }
    if (!seen) once.push_back(std::move(c));
  }
  return once;
}

void conclude_candidates(Deriver& d, const std::string& object, const Ray& /*ray*/,
                         const std::vector<Candidate>& candidates, bool solid) {
  std::vector<const Candidate*> hits;
  for (const auto& c : candidates) {
    if (c.rejected.empty()) hits.push_back(&c);
  }
  // "t = 1, at P = (1, 0, 0)"
  auto at = [](Sentence& s, const Candidate* c) {
    s.text("t = ").value(c->t).text(", at P = ").value(c->point);
  };
  Sentence s;
  if (hits.empty()) {
    s.text(fmt::format("The ray does not hit the {}.", object));
  } else if (hits.size() == 1) {
    bool tangent = solid && candidates.size() == 1;
    s.text(fmt::format("The ray {} the {} at ", tangent ? "touches" : "hits", object));
    at(s, hits[0]);
    s.text(".");
  } else if (solid && hits.size() == 2) {
    s.text(fmt::format("The ray enters the {} at ", object));
    at(s, hits[0]);
    s.text(", and leaves at ");
    at(s, hits[1]);
    s.text(".");
  } else {
    s.text(fmt::format("The ray hits the {} at ", object));
    for (std::size_t i = 0; i < hits.size(); ++i) {
      if (i) s.text("; ");
      at(s, hits[i]);
    }
    s.text(".");
  }
  d.conclude(std::move(s));
  for (const auto& c : candidates) {
    if (!c.rejected.empty()) {
      d.conclude(Sentence("t = ").value(c.t).text(fmt::format(" is not a hit: {}.", c.rejected)));
    }
  }
}

}  // namespace raygrade
