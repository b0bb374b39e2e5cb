// The table of field types, and what follows from a field's shape and value.
#include "kinds/fields/field_type.h"

#include <fmt/format.h>

#include "core/internal_error.h"
#include "kinds/fields/field_types.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

template <FieldTypeSpec... T>
std::vector<FieldTypeEntry> table_of(FieldTypeList<T...> /*list*/) {
  return {field_type_entry<T>()...};
}

}  // namespace

const std::vector<FieldTypeEntry>& field_type_table() {
  static const std::vector<FieldTypeEntry> table = [] {
    std::vector<FieldTypeEntry> t = table_of(FieldTypes{});
    for (std::size_t i = 0; i < t.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (t[i].name == t[j].name)
          throw InternalError(fmt::format("the field type '{}' is twice in FieldTypes", t[i].name));
      }
    }
    return t;
  }();
  return table;
}

const FieldTypeEntry* find_field_type(std::string_view name) {
  for (const auto& e : field_type_table()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

const FieldTypeEntry& field_type_of(const json& field) {
  const json* type = field.is_object() && field.contains("type") ? &field["type"] : nullptr;
  const FieldTypeEntry* e =
      type && type->is_string() ? find_field_type(type->get<std::string>()) : nullptr;
  if (!e) {
    throw InternalError(fmt::format("a form's field has a type of no field type: {}",
                                    type ? type->dump() : std::string("none")));
  }
  return *e;
}

json blank_of(const json& field) {
  const FieldTypeEntry& type = field_type_of(field);
  switch (type.shape) {
    case FieldShape::kOne:
      if (type.value == FieldValue::kNumber || type.value == FieldValue::kFormula) return "";
      if (type.value == FieldValue::kThreeNumbers) return json::array({"", "", ""});
      return nullptr;
    case FieldShape::kOpenTable: {
      json row = json::object();
      for (const auto& c : field["columns"]) row[c["key"].get<std::string>()] = blank_of(c);
      return json::array({row});
    }
    case FieldShape::kFixedRows: {
      json rows = json::array();
      for (const auto& r : field["rows"]) {
        json row = r["fixed"];
        for (const auto& c : field["columns"]) {
          if (field_type_of(c).numeric()) row[c["key"].get<std::string>()] = blank_of(c);
        }
        rows.push_back(row);
      }
      return rows;
    }
    case FieldShape::kTreeBuilder: return nullptr;
  }
  return nullptr;
}

std::string_view field_shape_word(FieldShape shape) {
  switch (shape) {
    case FieldShape::kOne: return "one";
    case FieldShape::kOpenTable: return "open-table";
    case FieldShape::kFixedRows: return "fixed-rows";
    case FieldShape::kTreeBuilder: return "tree-builder";
  }
  return "one";
}

std::string_view field_value_word(FieldValue value) {
  switch (value) {
    case FieldValue::kNone: return "none";
    case FieldValue::kNumber: return "typed-number";
    case FieldValue::kThreeNumbers: return "typed-three";
    case FieldValue::kFormula: return "typed-formula";
    case FieldValue::kFlag: return "flag";
    case FieldValue::kOneOf: return "one-of";
    case FieldValue::kSomeOf: return "some-of";
  }
  return "none";
}

json field_types_json() {
  json out = json::object();
  for (const auto& e : field_type_table()) {
    out[std::string(e.name)] = {{"shape", field_shape_word(e.shape)},
                                {"value", field_value_word(e.value)}};
  }
  return out;
}

}  // namespace raygrade
