// A table of the form's rows (one per light, say), each with the field's columns.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Rows {
  static constexpr std::string_view kName = "rows";
  static constexpr FieldShape kShape = FieldShape::kFixedRows;
  static constexpr FieldValue kValue = FieldValue::kNone;
  static constexpr std::string_view kAsks = "each of the field's rows, with the field's columns";
  static constexpr std::string_view kPlaceholder = "one value per cell";
};

}  // namespace raygrade::field_types
