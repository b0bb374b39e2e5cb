// A ray tree built point by point (docs/assignments.md, "The ray tree form").
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Tree {
  static constexpr std::string_view kName = "tree";
  static constexpr FieldShape kShape = FieldShape::kTreeBuilder;
  static constexpr FieldValue kValue = FieldValue::kNone;
  static constexpr std::string_view kAsks =
      "the points of a ray tree, with their shadows and terms as the field asks";
  static constexpr std::string_view kPlaceholder = "one row per point";
};

}  // namespace raygrade::field_types
