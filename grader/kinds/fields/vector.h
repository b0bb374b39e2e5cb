// A vector box: three numbers, each typed as a number box's.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Vector {
  static constexpr std::string_view kName = "vector";
  static constexpr FieldShape kShape = FieldShape::kOne;
  static constexpr FieldValue kValue = FieldValue::kThreeNumbers;
  static constexpr std::string_view kAsks =
      "three numbers (x, y, z), each as a number box takes it";
  static constexpr std::string_view kPlaceholder = "x, y, z";
};

}  // namespace raygrade::field_types
