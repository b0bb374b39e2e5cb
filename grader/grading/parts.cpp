// Every kind's parts, looked up in the table of kinds.
#include "grading/parts.h"

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

}  // namespace raygrade
