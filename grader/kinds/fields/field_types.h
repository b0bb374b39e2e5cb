// The list of field types: one line each. A new type is a header of kinds/fields/ and its line
// here (docs/architecture.md, "Adding a field type").
#pragma once

#include "kinds/fields/choice.h"
#include "kinds/fields/field_type.h"
#include "kinds/fields/formula.h"
#include "kinds/fields/hits.h"
#include "kinds/fields/number.h"
#include "kinds/fields/rows.h"
#include "kinds/fields/set.h"
#include "kinds/fields/tree.h"
#include "kinds/fields/vector.h"
#include "kinds/fields/yes_no.h"

namespace raygrade {

template <FieldTypeSpec... T>
struct FieldTypeList {};

using FieldTypes = FieldTypeList<field_types::Number, field_types::Vector, field_types::Formula,
                                 field_types::YesNo, field_types::Choice, field_types::Set,
                                 field_types::Hits, field_types::Rows, field_types::Tree>;

}  // namespace raygrade
