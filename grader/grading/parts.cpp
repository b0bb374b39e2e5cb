// Every kind's parts, looked up in the table of kinds.
#include "grading/parts.h"

#include "kinds/part_names.h"

namespace raygrade {

const std::vector<PartSpec>& kind_parts(std::string_view kind) {
  static const std::vector<PartSpec> none;
  const KindEntry* entry = find_kind(kind);
  return entry ? entry->parts : none;
}

const PartSpec* find_part(std::string_view kind, std::string_view name) {
  for (const auto& p : kind_parts(kind)) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

std::vector<std::pair<std::string, double>> default_points(std::string_view kind,
                                                           const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& n : names) {
    const PartSpec* p = find_part(kind, n);
    out.emplace_back(n, p ? p->points : 0);
  }
  return out;
}

ValueRule value_rule(std::string_view kind, const std::vector<std::string>& keys, bool vector) {
  ValueRule r;
  r.compare = vector ? Comparison::kPoint : Comparison::kScalar;
  if (keys.empty()) return r;
  std::string field =
      keys.back() == part_names::kUnitDirection ? part_names::kDirection : keys.back();
  auto numbers = [&](Comparison c) {
    if (!vector) return Comparison::kScalar;  // a number of any part, and each t of a set of hits
    if (c == Comparison::kDirection || c == Comparison::kUnitDirection) return c;
    return Comparison::kPoint;
  };
  if (const PartSpec* p = find_part(kind, field)) {
    r.compare = numbers(p->compare);
    r.tolerance_field = field;
    return r;
  }
  r.tolerance_field = keys.front();
  const PartSpec* whole = find_part(kind, keys.front());
  if (keys.front() == part_names::kUnitDirection && !whole) {
    // A camera's unit direction stands for its ray's direction.
    for (const auto& p : kind_parts(kind)) {
      if (p.compare == Comparison::kDirection) whole = &p;
    }
    if (whole) r.tolerance_field = whole->name;
  }
  if (whole && field != part_names::kOrigin && field != part_names::kPoint)
    r.compare = numbers(whole->compare);
  return r;
}

}  // namespace raygrade
