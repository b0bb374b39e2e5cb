// A number box: one number, typed as a number or an expression.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Number {
  static constexpr std::string_view kName = "number";
  static constexpr FieldShape kShape = FieldShape::kOne;
  static constexpr FieldValue kValue = FieldValue::kNumber;
  static constexpr std::string_view kAsks =
      "one number: a decimal, a fraction or an expression such as 9 - sqrt(3)";
  static constexpr std::string_view kPlaceholder = "a number or an expression, e.g. 9 - sqrt(3)";
};

}  // namespace raygrade::field_types
