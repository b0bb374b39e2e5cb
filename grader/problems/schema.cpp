// The problem schema: problem_schema_base.json with a definition per primitive of the table.
#include "problems/schema.h"

#include <fmt/format.h>

#include "core/internal_error.h"
#include "problems/problem.h"
#include "problems/schema_assets.h"
#include "shapes/shape.h"

namespace raygrade {
namespace {

// A primitive's definition: the keys every object may carry, then its own from its fragment
// (description, required keys, properties, constraints such as oneOf, examples); no other key.
nlohmann::ordered_json primitive_definition(std::string_view type,
                                            const nlohmann::ordered_json& fragment) {
  nlohmann::ordered_json def = {{"type", "object"}};
  if (fragment.contains("description")) def["description"] = fragment["description"];
  nlohmann::ordered_json required = {"type"};
  const nlohmann::ordered_json own_required =
      fragment.value("required", nlohmann::ordered_json::array());
  for (const auto& key : own_required) required.push_back(key);
  def["required"] = std::move(required);
  nlohmann::ordered_json properties = {
      {"type", {{"const", type}}},
      {"name", {{"$ref", "#/$defs/name"}}},
      {"material",
       {{"description", "read in scenes only: an object's material in any other kind is an error"},
        {"oneOf", {{{"$ref", "#/$defs/material"}}, {{"type", "string"}}}}}},
      {"transform", {{"$ref", "#/$defs/transform"}}},
  };
  const nlohmann::ordered_json own_properties =
      fragment.value("properties", nlohmann::ordered_json::object());
  for (const auto& [key, value] : own_properties.items()) properties[key] = value;
  def["properties"] = std::move(properties);
  for (const auto& [key, value] : fragment.items()) {
    if (key != "description" && key != "required" && key != "properties") def[key] = value;
  }
  def["additionalProperties"] = false;
  return def;
}

// The kinds, from the table of kinds: `kind` takes its names, and each kind's case (an `if` on
// the kind in the problem's allOf, with the kind's own "required" and "properties") allows
// exactly the keys read_problem allows, the common ones and the kind's own. A kind whose case
// does not describe one of its keys is a bug of raygrade.
void derive_kinds(nlohmann::ordered_json& problem) {
  nlohmann::ordered_json names = nlohmann::ordered_json::array();
  for (const KindEntry& k : kind_table()) names.push_back(k.name);
  problem["properties"]["kind"]["enum"] = names;
  nlohmann::ordered_json cases = nlohmann::ordered_json::array();
  for (const KindEntry& k : kind_table()) {
    nlohmann::ordered_json then;
    try {
      then = nlohmann::ordered_json::parse(k.schema);
    } catch (const nlohmann::json::exception& e) {
      throw InternalError(
          fmt::format("the schema of the kind '{}' is not JSON: {}", k.name, e.what()));
    }
    nlohmann::ordered_json keys = nlohmann::ordered_json::array();
    for (const auto& key : common_problem_keys()) keys.push_back(key);
    for (const auto& key : k.keys) {
      if (!then["properties"].contains(key))
        throw InternalError(
            fmt::format("the schema of the kind '{}' does not describe its key '{}'", k.name, key));
      keys.push_back(key);
    }
    then["propertyNames"] = {{"enum", keys}};
    nlohmann::ordered_json c;
    // The first kind is also the kind of a problem that names none.
    bool first = cases.empty();
    if (first) {
      c["if"] = {{"properties", {{"kind", {{"const", k.name}}}}}};
    } else {
      c["if"] = {{"required", {"kind"}}, {"properties", {{"kind", {{"const", k.name}}}}}};
    }
    c["then"] = std::move(then);
    if (first) {
      c["$comment"] = fmt::format(
          "kind {}, also when `kind` is left out; propertyNames flags unknown keys", k.name);
    }
    cases.push_back(std::move(c));
  }
  problem["allOf"] = std::move(cases);
}

}  // namespace

nlohmann::ordered_json problem_schema() {
  nlohmann::ordered_json base = nlohmann::ordered_json::parse(kProblemSchemaBase);
  nlohmann::ordered_json defs = nlohmann::ordered_json::object();
  nlohmann::ordered_json types = nlohmann::ordered_json::array();
  nlohmann::ordered_json cases = nlohmann::ordered_json::array();
  for (auto& [key, value] : base["$defs"].items()) {
    if (key == "object") {
      // The primitives' definitions come before the object that chooses among them.
      for (const ShapeEntry& entry : shape_table()) {
        defs[std::string(entry.type)] = primitive_definition(entry.type, entry.schema());
        types.push_back(entry.type);
        cases.push_back({{"if", {{"properties", {{"type", {{"const", entry.type}}}}}}},
                         {"then", {{"$ref", fmt::format("#/$defs/{}", entry.type)}}}});
      }
      value["properties"]["type"] = {{"enum", types}};
      value["allOf"] = cases;
    }
    if (key == "problem") derive_kinds(value);
    defs[key] = value;
  }
  base["$defs"] = std::move(defs);
  return base;
}

std::string problem_schema_text() { return problem_schema().dump(2) + "\n"; }

}  // namespace raygrade
