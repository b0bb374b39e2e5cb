// The pieces kinds build their answer forms from (docs/assignments.md, "Answer forms"): an
// input, a column of a table, the choice of an object, a table of hits.
#pragma once

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kinds/fields/field_types.h"
#include "scenes/scene.h"

namespace raygrade::form {

// One input of a field type: {"type", "key", "label"}; a key "ray/origin" answers ray.origin.
nlohmann::json field(const FieldTypeEntry& type, std::string key, std::string label);
template <FieldTypeSpec T>
nlohmann::json field(std::string key, std::string label) {
  return field(field_type_entry<T>(), std::move(key), std::move(label));
}

// The names of a list of objects or lights, in order.
std::vector<std::string> names_of(const nlohmann::json& list);

// The choice of the object hit first among `names`, or none.
nlohmann::json object_choice(const std::vector<std::string>& names);

// A table of hits: t, with the point and normal and the barycentric weights when asked.
nlohmann::json hits_field(bool barycentric, bool several, bool point_and_normal);

// The most points a ray tree form of fixed size offers.
inline constexpr int kTreeFormRows = 8;

// A ray tree built point by point (docs/assignments.md, "The ray tree form"): the scene's objects
// and lights to choose from, and how many points a form of fixed size offers. Its parts: tree,
// shadows, terms.
nlohmann::json tree_field(const Scene& scene);

// {"fields": fields}
nlohmann::json fields(nlohmann::json list);
// The same from the fields written out: {field} stays a list of one field whatever the compiler
// (a json parameter initialised from {field} is the field itself under clang, a list of it under
// gcc).
nlohmann::json fields(std::initializer_list<nlohmann::json> list);

}  // namespace raygrade::form
