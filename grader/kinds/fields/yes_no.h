// A yes or no.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct YesNo {
  static constexpr std::string_view kName = "yesno";
  static constexpr FieldShape kShape = FieldShape::kOne;
  static constexpr FieldValue kValue = FieldValue::kFlag;
  static constexpr std::string_view kAsks = "yes or no";
  static constexpr std::string_view kPlaceholder = "yes or no";
};

}  // namespace raygrade::field_types
