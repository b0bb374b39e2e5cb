// A table of hits the student adds row by row: the field's columns for each.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Hits {
  static constexpr std::string_view kName = "hits";
  static constexpr FieldShape kShape = FieldShape::kOpenTable;
  static constexpr FieldValue kValue = FieldValue::kNone;
  static constexpr std::string_view kAsks =
      "as many rows as the student gives, each with the field's columns";
  static constexpr std::string_view kPlaceholder = "one row per hit";
};

}  // namespace raygrade::field_types
