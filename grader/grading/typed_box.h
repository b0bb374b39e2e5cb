// One typed answer box read as the grader reads it: a number box, a vector box (three
// numbers) or a formula box, from the JSON text a page or a server writes into a submission.
// The CLI's read-typed command, the pages' WebAssembly reader (web/typed_reader.cpp) and the
// differential test of the front ends (tests/typed_corpus.py) all go through read_typed_box.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace raygrade {

enum class TypedBox { kNumber, kVector, kFormula };

// The box of a field type whose one value is typed (kinds/fields/: a number, three numbers or
// a formula); false for any other name.
bool typed_box_from_name(std::string_view name, TypedBox& box);

struct TypedReading {
  bool accepted = false;
  // The number, the three components, or the formula's value with every symbol 1.
  std::vector<double> values;
  std::string message;  // why it is refused (when !accepted)
  // Why, in a word: "read" (the text does not parse), "finite" (it parses to no finite value),
  // "json" (not JSON text) or "type" (a value of another type).
  std::string fault;
};

// `answer_json` is the box's value as JSON text: a string for a number or a formula box, an
// array of three strings for a vector box. Text that is not JSON (a lone surrogate written as
// \ud800, say) is refused, as the grader refuses a submission holding it. `symbols` are the
// names a formula box knows. Never throws for bad input.
TypedReading read_typed_box(TypedBox box, std::string_view answer_json,
                            const std::vector<std::string>& symbols = {});

// {"ok": true, "values": ["3ff0000000000000", ...]} (each double's bits in hex) or
// {"ok": false, "message": "...", "fault": "read"}.
nlohmann::json typed_reading_json(const TypedReading& r);

}  // namespace raygrade
