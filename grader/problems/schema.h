// The problem schema (docs/problem.schema.json): the format's own parts and one definition per
// primitive of the list, each from the primitive's fragment.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace raygrade {

// The whole schema, as `raygrade schema` writes it.
nlohmann::ordered_json problem_schema();

// The schema as the file's text: two spaces of indent, UTF-8, a final newline.
std::string problem_schema_text();

}  // namespace raygrade
