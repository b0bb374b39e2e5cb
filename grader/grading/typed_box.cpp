// Reading one typed answer box as the grader does (AnswerReader and the formula parser).
#include "grading/typed_box.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>

#include "core/error.h"
#include "derivation/formula.h"
#include "grading/answer_reader.h"
#include "kinds/fields/field_type.h"

namespace raygrade {

bool typed_box_from_name(std::string_view name, TypedBox& box) {
  const FieldTypeEntry* type = find_field_type(name);
  if (!type || type->shape != FieldShape::kOne) return false;
  switch (type->value) {
    case FieldValue::kNumber: box = TypedBox::kNumber; return true;
    case FieldValue::kThreeNumbers: box = TypedBox::kVector; return true;
    case FieldValue::kFormula: box = TypedBox::kFormula; return true;
    default: return false;
  }
}

namespace {

TypedReading refused(std::string message, std::string fault) {
  TypedReading r;
  r.message = std::move(message);
  r.fault = std::move(fault);
  return r;
}

// A number box's text that AnswerReader refuses: the parser's own words when it does not
// parse (the page shows them beside the box), else it has no finite value.
TypedReading refused_number(const AnswerReader& a, const std::string& fault) {
  if (!a.json().is_string()) return refused(fault, "finite");
  FormulaParse p = parse_formula(a.json().get_ref<const std::string&>());
  return p.ok ? refused("no finite value", "finite") : refused(p.message, "read");
}

// A formula box: parsed with its symbols (as grade_formula.cpp reads one), valued at 1 each.
TypedReading read_formula(const AnswerReader& a, const std::vector<std::string>& names) {
  SymbolTable symbols;
  for (const auto& n : names) symbols.add(n);
  std::string text = a.json().is_number() ? a.json().dump() : a.string();
  FormulaParse p = parse_formula(text, &symbols);
  if (!p.ok) return refused(p.message, "read");
  TypedReading r;
  r.accepted = true;
  r.values.push_back(p.formula.evaluate(std::vector<double>(names.size(), 1.0)));
  return r;
}

TypedReading read_box(TypedBox box, const AnswerReader& a, const std::vector<std::string>& names) {
  TypedReading r;
  switch (box) {
    case TypedBox::kNumber: {
      AnswerReader::Number n = a.number();
      if (!n.value) return refused_number(a, n.fault);
      r.values.push_back(n.value->value);
      break;
    }
    case TypedBox::kVector: {
      AnswerReader::Vector v = a.vector();
      if (!v.ok) return refused(v.fault, "read");
      for (const auto& c : v.c) r.values.push_back(c.value);
      break;
    }
    case TypedBox::kFormula: return read_formula(a, names);
  }
  r.accepted = true;
  return r;
}

}  // namespace

TypedReading read_typed_box(TypedBox box, std::string_view answer_json,
                            const std::vector<std::string>& symbols) {
  nlohmann::json value = nlohmann::json::parse(answer_json, nullptr, false);
  if (value.is_discarded()) return refused("the answer is not valid JSON text", "json");
  try {
    return read_box(box, AnswerReader(value, nullptr, ""), symbols);
  } catch (const Error& e) {
    return refused(e.diagnostic().message, "type");
  }
}

nlohmann::json typed_reading_json(const TypedReading& r) {
  if (!r.accepted) return {{"ok", false}, {"message", r.message}, {"fault", r.fault}};
  nlohmann::json values = nlohmann::json::array();
  for (double v : r.values) {
    std::uint64_t bits = 0;  // std::memcpy: Emscripten's libc++ has no std::bit_cast
    std::memcpy(&bits, &v, sizeof bits);
    values.push_back(fmt::format("{:016x}", bits));
  }
  return {{"ok", true}, {"values", values}};
}

}  // namespace raygrade
