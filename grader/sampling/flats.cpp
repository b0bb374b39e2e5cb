// Helpers the generators of flat primitives share.
#include "sampling/flats.h"

#include "sampling/draft.h"

namespace raygrade {
namespace {

// A small integer direction that crosses the plane (never parallel to it).
Vec3d crossing_direction(Prng& rng, const Vec3d& normal) {
  while (true) {
    Vec3d d = random_direction(rng);
    if (dot(d, normal) != 0) return d;
  }
}

}  // namespace

Frame random_frame(Prng& rng) {
  static const std::vector<std::pair<Vec3d, Vec3d>> kBases = {{{1, 0, 0}, {0, 1, 0}},
                                                              {{1, 1, 0}, {0, 0, 1}},
                                                              {{1, 0, -1}, {0, 1, 0}},
                                                              {{2, 1, 0}, {0, 0, 1}}};
  auto [e1, e2] = rng.pick(kBases);
  AxisMap map = random_axis_map(rng);
  return Frame{random_point(rng, 4), map(e1), map(e2)};
}

Draft flat_draft(Prng& rng, Outcome o, const Vec3d& p, const Vec3d& normal,
                 const nlohmann::ordered_json& object, const std::string& text) {
  Vec3d d = crossing_direction(rng, normal);
  int s = rng.range(1, 3);
  if (o == Outcome::kBehind) return intersect_draft(p + double(s) * d, d, object, text, {});
  std::vector<KnownHit> hits;
  if (o != Outcome::kMiss) hits.push_back({double(s), p});
  return intersect_draft(p - double(s) * d, d, object, text, hits);
}

std::string vertices_text(const std::vector<Vec3d>& v) {
  std::vector<std::string> parts;
  parts.reserve(v.size());
  for (const auto& p : v) parts.push_back(point_text(p));
  return fmt::format("{}", fmt::join(parts, ", "));
}

nlohmann::ordered_json vertices_json(const std::vector<Vec3d>& v) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& p : v) list.push_back(vector_json(p));
  return list;
}

}  // namespace raygrade
