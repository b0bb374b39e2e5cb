// The types of an answer form's inputs (docs/assignments.md, "Answer forms"). A field type is a
// class of its own header in kinds/fields/ and one line of the list `FieldTypes`
// (kinds/fields/field_types.h), checked by the concept FieldTypeSpec. Its name, written into a
// form's "type", is the one place the type is spelled: pages, exports, the PrairieLearn
// questions and the typed reader take what they do with a field from its shape and its value
// below, through the table, never by testing its name.
#pragma once

#include <concepts>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace raygrade {

// How a field lays out its values in the answer.
enum class FieldShape {
  kOne,          // one value under the field's key
  kOpenTable,    // rows the student adds, each with the field's "columns"
  kFixedRows,    // the form's "rows", each with its "fixed" keys and the "columns"
  kTreeBuilder,  // a ray tree built point by point (docs/assignments.md, "The ray tree form")
};

// What one value of a field is, as the student gives it.
enum class FieldValue {
  kNone,          // a field whose values are its columns' or its tree's
  kNumber,        // one typed number
  kThreeNumbers,  // three typed numbers
  kFormula,       // one typed formula of the field's "symbols"
  kFlag,          // yes or no
  kOneOf,         // one of the field's "options" ({"text", "value"})
  kSomeOf,        // any of the field's "options" (names)
};

template <typename T>
concept FieldTypeSpec = requires {
  { T::kName } -> std::convertible_to<std::string_view>;
  { T::kShape } -> std::convertible_to<FieldShape>;
  { T::kValue } -> std::convertible_to<FieldValue>;
  // What the student gives, in words (docs/assignments.md's table of field types).
  { T::kAsks } -> std::convertible_to<std::string_view>;
  // What to type into one text box of this type, shown where a box has no room for more.
  { T::kPlaceholder } -> std::convertible_to<std::string_view>;
};

// One row of the table of field types.
struct FieldTypeEntry {
  std::string_view name;
  FieldShape shape = FieldShape::kOne;
  FieldValue value = FieldValue::kNone;
  std::string_view asks;
  std::string_view placeholder;

  // A value the typed reader reads (a number, three numbers or a formula).
  bool typed() const {
    return value == FieldValue::kNumber || value == FieldValue::kThreeNumbers ||
           value == FieldValue::kFormula;
  }
  // A value of numbers: a number or three.
  bool numeric() const {
    return value == FieldValue::kNumber || value == FieldValue::kThreeNumbers;
  }
};

template <FieldTypeSpec T>
constexpr FieldTypeEntry field_type_entry() {
  return {T::kName, T::kShape, T::kValue, T::kAsks, T::kPlaceholder};
}

// The table of field types, in the order of FieldTypes.
const std::vector<FieldTypeEntry>& field_type_table();

// The field type named `name`, or nullptr.
const FieldTypeEntry* find_field_type(std::string_view name);

// The type of a form's field ({"type": name, ...}); a name of no field type is an internal
// error (a form is written by the kinds, never by the user).
const FieldTypeEntry& field_type_of(const nlohmann::json& field);

// A field's answer when nothing is typed: "" for a number or a formula, three of them for
// three numbers, one blank row of the columns for an open table, each fixed row with its
// numbers' blanks; null for a field that has no blank (yes/no, choices, a tree), which is left
// out of a blank answer.
nlohmann::json blank_of(const nlohmann::json& field);

// {"name": {"shape": ..., "value": ...}, ...}: the table as the pages' scripts take it, with the
// shapes and values as the words of field_shape_word and field_value_word.
nlohmann::json field_types_json();
std::string_view field_shape_word(FieldShape shape);
std::string_view field_value_word(FieldValue value);

}  // namespace raygrade
