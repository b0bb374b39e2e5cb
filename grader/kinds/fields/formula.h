// A formula box: a formula of the field's symbols.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Formula {
  static constexpr std::string_view kName = "formula";
  static constexpr FieldShape kShape = FieldShape::kOne;
  static constexpr FieldValue kValue = FieldValue::kFormula;
  static constexpr std::string_view kAsks = "a formula of the symbols the field lists";
  static constexpr std::string_view kPlaceholder = "a formula";
};

}  // namespace raygrade::field_types
