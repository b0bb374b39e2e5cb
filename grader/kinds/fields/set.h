// Any of the field's options: the terms that apply, say.
#pragma once

#include "kinds/fields/field_type.h"

namespace raygrade::field_types {

struct Set {
  static constexpr std::string_view kName = "set";
  static constexpr FieldShape kShape = FieldShape::kOne;
  static constexpr FieldValue kValue = FieldValue::kSomeOf;
  static constexpr std::string_view kAsks = "any of the names the field lists";
  static constexpr std::string_view kPlaceholder = "names separated by commas";
};

}  // namespace raygrade::field_types
