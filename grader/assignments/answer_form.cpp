// Answer forms by kind.
#include "assignments/answer_form.h"

#include <fmt/format.h>

#include "core/internal_error.h"
#include "grading/grade.h"
#include "kinds/fields/field_type.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

// The parts an input answers: its "parts", else the first segment of its key ("ray/origin"
// answers "ray").
std::vector<std::string> parts_of(const json& f) {
  if (f.contains("parts")) return f["parts"].get<std::vector<std::string>>();
  std::string key = f["key"];
  return {key.substr(0, key.find('/'))};
}

// Only the inputs of parts that carry points: a part worth 0 points is not asked. The JSON
// catch-all (key "") stays; a table of hits keeps the columns that are asked.
json only_asked(json form, const Grader& grader) {
  auto asked = [&](const json& f) {
    for (const auto& part : parts_of(f)) {
      if (grader.part_points(part) > 0) return true;
    }
    return false;
  };
  json kept = json::array();
  for (auto& f : form["fields"]) {
    FieldShape shape = field_type_of(f).shape;
    if (shape == FieldShape::kOpenTable) {
      json columns = json::array();
      for (auto& c : f["columns"]) {
        if (!asked(c)) continue;
        c.erase("parts");
        columns.push_back(c);
      }
      if (columns.empty()) continue;
      f["columns"] = columns;
    } else if (shape == FieldShape::kTreeBuilder) {
      // The tree's points are always built (they place the shadows and terms); the columns of
      // shadows and terms only when those parts are asked.
      json asks = json::array();
      for (const auto& part : parts_of(f)) {
        if (grader.part_points(part) > 0) asks.push_back(part);
      }
      if (asks.empty()) continue;
      f["asks"] = asks;
    } else if (f["key"] != "" && !asked(f)) {
      continue;
    }
    f.erase("parts");
    kept.push_back(f);
  }
  form["fields"] = kept;
  return form;
}

}  // namespace

json answer_form(const Problem& p) { return only_asked(every_input(p), Grader(p)); }

json every_input(const Problem& p) {
  const KindEntry* entry = find_kind(p.kind);
  if (!entry) throw InternalError(fmt::format("problem {} has no kind of the table", p.id));
  return entry->answer_form(p);
}

json blank_answer(const json& form) {
  json out = json::object();
  for (const auto& f : form["fields"]) {
    json blank = blank_of(f);
    if (blank.is_null()) continue;
    std::string key = f["key"];
    json* at = &out;
    std::size_t start = 0;
    for (std::size_t slash; (slash = key.find('/', start)) != std::string::npos;
         start = slash + 1) {
      at = &(*at)[key.substr(start, slash - start)];
    }
    (*at)[key.substr(start)] = blank;
  }
  return out;
}

}  // namespace raygrade
