// One of the field's options: the object hit first, say.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Choice {
  static constexpr std::string_view kName = "choice";
  static constexpr FieldShape kShape = FieldShape::kOne;
  static constexpr FieldValue kValue = FieldValue::kOneOf;
  static constexpr std::string_view kAsks = "one of the options the field lists";
  static constexpr std::string_view kPlaceholder = "one of the options";
};

}  // namespace raygrade::field_types
