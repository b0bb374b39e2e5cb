// The table of primitives, derived from the list `Primitives`.
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

}  // namespace raygrade
