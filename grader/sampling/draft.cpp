// Shared pieces of generated problems.
#include "sampling/draft.h"

namespace raygrade {

Outcome choose_outcome(Prng& rng, std::optional<Outcome> asked, const std::vector<Outcome>& can) {
  return asked ? *asked : rng.pick(can);
}

nlohmann::ordered_json known_hit_json(const KnownHit& h) {
  nlohmann::ordered_json j;
  j["t"] = number_json(h.t);
  j["point"] = vector_json(h.point);
  return j;
}

std::string ray_text(const Vec3d& origin, const Vec3d& direction) {
  return fmt::format("p(t) = {} + t{}", point_text(origin), direction_text(direction));
}

Draft intersect_draft(const Vec3d& origin, const Vec3d& direction, nlohmann::ordered_json object,
                      const std::string& object_text, const std::vector<KnownHit>& hits,
                      bool contained) {
  Draft d;
  d.fields["statement"] = fmt::format(
      "Find every point where the ray {} meets {}. Give t and the point of each hit, or say "
      "that there is none.",
      ray_text(origin, direction), object_text);
  d.fields["ray"] = {{"origin", vector_json(origin)}, {"direction", vector_json(direction)}};
  d.fields["object"] = std::move(object);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& h : hits) list.push_back(known_hit_json(h));
  d.fields["expected"]["hits"] = list;
  if (contained) d.fields["expected"]["contained"] = true;
  return d;
}

}  // namespace raygrade
