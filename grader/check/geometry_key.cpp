// Keys that name a problem's geometry, to find the same exercise under two ids.
#include "check/geometry_key.h"

#include <algorithm>

#include "problems/problem.h"
#include "problems/ray_cast.h"

namespace raygrade {
namespace {

// Numbers in geometry keys: 12 significant digits, so that the same geometry written as
// 0.5 and 0.50000000000001 (or with a direction scaled) is recognised as the same.
std::string key_number(double v) {
  if (v == 0) return "0";  // and -0
  return fmt::format("{:.12g}", v);
}

std::string key_vec(const Vec3d& v) {
  return fmt::format("{},{},{}", key_number(v.x), key_number(v.y), key_number(v.z));
}

// The ray with its direction scaled to unit length (and its t range with it).
std::string ray_key(const Ray& r) {
  double len = length(r.direction);
  return fmt::format("{}|{}|{}|{}", key_vec(r.origin), key_vec(r.direction / len),
                     key_number(r.t_min * len), key_number(r.t_max * len));
}

}  // namespace

std::string geometry_key(const Problem& p) {
  std::string head = fmt::format("{}|{}|", p.kind, p.method);
  if (const RayCast* cast = p.task->ray_cast()) {
    // The objects in any order: one object, or the objects the first one met is named among.
    std::vector<std::string> objects;
    for (std::size_t i = 0; i < cast->object_count(); ++i)
      objects.push_back(cast->object_at(i).to_json().dump());
    std::sort(objects.begin(), objects.end());
    return head + ray_key(cast->cast_ray()) + "|" + fmt::format("{}", fmt::join(objects, "|"));
  }
  nlohmann::json rest = p.source;
  for (const auto& k : common_problem_keys()) rest.erase(k);
  return head + rest.dump();
}

}  // namespace raygrade
