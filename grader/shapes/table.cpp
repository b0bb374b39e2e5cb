// The table of primitives, derived from the list `Primitives`.
#include <fmt/format.h>

#include "shapes/primitives.h"

namespace raygrade {

const std::vector<ShapeEntry>& shape_table() {
  static const std::vector<ShapeEntry> table = [] {
    std::vector<ShapeEntry> rows;
    for_each_primitive([&rows]<PrimitiveType T>() {
      rows.push_back({T::kType, T::kSummary, &T::read, &T::schema});
    });
    return rows;
  }();
  return table;
}

std::string contained_line(std::string_view type) {
  std::string line = fmt::format(
      "The ray lies in the {0}'s plane (N·D = 0 and its origin is on the plane): it meets the {0} "
      "along a whole line",
      type);
  for_each_primitive([&]<typename T>() {
    if constexpr (requires { T::kContainedLine; }) {
      if (type == T::kType) line = T::kContainedLine;
    }
  });
  return line;
}

}  // namespace raygrade
