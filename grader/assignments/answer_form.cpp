// Answer forms by kind.
#include "assignments/answer_form.h"

#include <fmt/format.h>

#include "core/internal_error.h"
#include "grading/grade.h"

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
    if (f["type"] == "hits") {
      json columns = json::array();
      for (auto& c : f["columns"]) {
        if (!asked(c)) continue;
        c.erase("parts");
        columns.push_back(c);
      }
      if (columns.empty()) continue;
      f["columns"] = columns;
    } else if (f["type"] == "tree") {
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

json blank_vector() { return json::array({"", "", ""}); }

json blank_of(const json& f) {
  std::string type = f["type"];
  if (type == "number" || type == "formula") return "";
  if (type == "vector") return blank_vector();
  if (type == "hits") {
    json row = json::object();
    for (const auto& c : f["columns"]) row[c["key"].get<std::string>()] = blank_of(c);
    return json::array({row});
  }
  if (type == "rows") {
    json rows = json::array();
    for (const auto& r : f["rows"]) {
      json row = r["fixed"];
      for (const auto& c : f["columns"]) {
        if (c["type"] == "number" || c["type"] == "vector")
          row[c["key"].get<std::string>()] = blank_of(c);
      }
      rows.push_back(row);
    }
    return rows;
  }
  return nullptr;  // yes/no, choices, sets and JSON have no blank: they are left out
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
