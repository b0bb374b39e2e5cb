// The pieces of answer forms.
#include "kinds/form.h"

#include <algorithm>

#include "kinds/part_names.h"

namespace raygrade::form {

using json = nlohmann::json;

json field(const FieldTypeEntry& type, std::string key, std::string label) {
  return {{"type", type.name}, {"key", std::move(key)}, {"label", std::move(label)}};
}

std::vector<std::string> names_of(const json& list) {
  std::vector<std::string> out;
  if (!list.is_array()) return out;
  for (const auto& item : list) {
    if (item.is_object() && item.contains("name") && item["name"].is_string()) {
      out.push_back(item["name"].get<std::string>());
    }
  }
  return out;
}

json object_choice(const std::vector<std::string>& names) {
  json f = field<field_types::Choice>("object", "The first object hit");
  json options = json::array({{{"text", "none (the ray hits nothing)"}, {"value", nullptr}}});
  for (const auto& n : names) options.push_back({{"text", n}, {"value", n}});
  f["options"] = options;
  return f;
}

json hits_field(bool barycentric, bool several, bool point_and_normal) {
  json f = field<field_types::Hits>("hits", several ? "Hits, in any order" : "The first hit");
  json columns = json::array({field<field_types::Number>("t", "t")});
  if (point_and_normal) {
    columns.push_back(field<field_types::Vector>("point", "point"));
    columns.push_back(field<field_types::Vector>("normal", "normal"));
  }
  if (barycentric)
    columns.push_back(field<field_types::Vector>("barycentric", "barycentric (w_a, w_b, w_c)"));
  f["columns"] = columns;
  f["several"] = several;
  return f;
}

json tree_field(const Scene& scene) {
  json f =
      field<field_types::Tree>("", "The ray tree: one row per point where a ray meets an object");
  json objects = json::array(), lights = json::array();
  for (const auto& o : scene.objects) objects.push_back(o.name);
  for (const auto& l : scene.lights) lights.push_back(l.name);
  f["objects"] = objects;
  f["lights"] = lights;
  // A form of fixed size (a PrairieLearn question) offers the points of a full binary tree as
  // deep as the scene's max_depth, at most kTreeFormRows: the size follows from the givens,
  // never from the answer.
  int full = scene.max_depth >= 4 ? kTreeFormRows : (1 << scene.max_depth) - 1;
  f["rows"] = std::min(full, kTreeFormRows);
  f["parts"] = json::array({part_names::kTree, part_names::kShadows, part_names::kTerms});
  // Which of its parts the page's columns of shadow rays and of terms answer.
  f["shadows_part"] = part_names::kShadows;
  f["terms_part"] = part_names::kTerms;
  return f;
}

json fields(json list) { return {{"fields", std::move(list)}}; }

json fields(std::initializer_list<json> list) {
  json array = json::array();
  for (const auto& f : list) array.push_back(f);
  return fields(std::move(array));
}

}  // namespace raygrade::form
