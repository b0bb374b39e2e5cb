// Answer forms by kind.
#include "assignments/answer_form.h"

#include "grading/grade.h"
#include "kinds/derive.h"
#include "kinds/shade.h"
#include "shapes/primitives.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

json field(std::string type, std::string key, std::string label) {
  return {{"type", std::move(type)}, {"key", std::move(key)}, {"label", std::move(label)}};
}

json column(std::string type, std::string key, std::string label) {
  return field(std::move(type), std::move(key), std::move(label));
}

// The names of a list of objects or lights, in order.
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
  json f = field("choice", "object", "The first object hit");
  json options = json::array({{{"text", "none (the ray hits nothing)"}, {"value", nullptr}}});
  for (const auto& n : names) options.push_back({{"text", n}, {"value", n}});
  f["options"] = options;
  return f;
}

json hits_field(bool barycentric, bool several, bool point_and_normal) {
  json f = field("hits", "hits", several ? "Hits, in any order" : "The first hit");
  json columns = json::array({column("number", "t", "t")});
  if (point_and_normal) {
    columns.push_back(column("vector", "point", "point"));
    columns.push_back(column("vector", "normal", "normal"));
  }
  if (barycentric)
    columns.push_back(column("vector", "barycentric", "barycentric (w_a, w_b, w_c)"));
  f["columns"] = columns;
  f["several"] = several;
  return f;
}

json intersect_form(const Problem& p) {
  const json& object = p.source.contains("object") ? p.source["object"] : json();
  bool barycentric =
      object.is_object() && hits_have_barycentric(object.value("type", std::string()));
  json f = hits_field(barycentric, true, true);
  f["miss"] = "The ray misses (no hits)";
  f["contained"] = "The ray lies in the surface (contained)";
  return {{"fields", json::array({f})}};
}

json first_hit_form(const Problem& p) {
  return {{"fields", json::array({object_choice(names_of(p.source.value("objects", json()))),
                                  hits_field(false, false, true)})}};
}

json camera_ray_form() {
  return {{"fields",
           json::array({field("vector", "ray/origin", "The ray's origin"),
                        field("vector", "ray/direction", "The ray's direction"),
                        field("vector", "unit_direction", "The direction as a unit vector")})}};
}

json reflect_form() {
  return {{"fields", json::array({field("vector", "direction", "The reflected direction"),
                                  field("vector", "unit_direction",
                                        "The reflected direction as a unit vector")})}};
}

json normal_form(const Problem& p) {
  json fields = json::array({field("vector", "normal", "The outward unit normal at P")});
  if (p.task->answer().contains("object_normal")) {
    fields.push_back(field("vector", "object_normal", "The normal in object space, before (A⁻¹)ᵀ"));
  }
  return {{"fields", fields}};
}

json view_ray_form() {
  return {{"fields", json::array({field("vector", "origin", "Where the ray starts"),
                                  field("vector", "direction", "The ray's direction")})}};
}

json fresnel_form() {
  return {{"fields", json::array({field("number", "reflectance", "The reflectance F"),
                                  field("number", "transmittance", "The transmitted share 1 − F"),
                                  field("yesno", "total_internal_reflection",
                                        "Total internal reflection?")})}};
}

json refract_form() {
  // "Yes" to total internal reflection also answers the direction: there is none.
  json tir = field("yesno", "total_internal_reflection", "Total internal reflection?");
  tir["parts"] = json::array({"total_internal_reflection", "direction"});
  return {
      {"fields",
       json::array({tir,
                    field("vector", "direction",
                          "The refracted direction (blank under total internal reflection)"),
                    field("vector", "reflected_direction",
                          "The reflected direction (under total internal reflection)"),
                    field("number", "angle_of_incidence", "The angle of incidence, in degrees"),
                    field("number", "angle_of_refraction", "The angle of refraction, in degrees"),
                    field("number", "critical_angle",
                          "The critical angle, in degrees (when there is one)")})}};
}

json shade_form(const Problem& p) {
  // With colours every term is [r, g, b]: three numbers, as a vector's field takes them.
  const auto* task = dynamic_cast<const ShadeTask*>(p.task.get());
  bool rgb = task && task->colour();
  std::string term = rgb ? "vector" : "number";
  std::string unit = rgb ? " [r, g, b]" : "";
  json lights = field("rows", "lights", "Each light");
  json rows = json::array();
  for (const auto& n : names_of(p.source.value("lights", json()))) {
    rows.push_back({{"label", "light " + n}, {"fixed", {{"light", n}}}});
  }
  lights["rows"] = rows;
  lights["columns"] = json::array(
      {column("number", "n_dot_l", "N·L"), column("number", "r_dot_v", "R·V"),
       column("yesno", "reaches", "reaches the point?"), column(term, "diffuse", "diffuse" + unit),
       column(term, "specular", "specular" + unit)});
  json terms = field("set", "terms", "The terms that apply");
  terms["options"] = json::array({"ambient", "diffuse", "specular"});
  return {
      {"fields", json::array({field(term, "ambient", "The ambient term" + unit),
                              field(term, "diffuse", "The diffuse term" + unit),
                              field(term, "specular", "The specular term" + unit),
                              field(term, "intensity", "The intensity" + unit), lights, terms})}};
}

json ray_tree_form(const Problem& p) {
  std::string ask = p.source.value("ask", "tree");
  if (ask == "hit") {
    // The object and its t are one part, "hit".
    json scene = p.source.value("scene", json::object());
    json object = object_choice(names_of(scene.value("objects", json())));
    json hits = hits_field(false, false, false);
    object["parts"] = json::array({"hit"});
    for (auto& c : hits["columns"]) c["parts"] = json::array({"hit"});
    return {{"fields", json::array({object, hits})}};
  }
  json f = field("json", "",
                 "The ray tree as JSON ({\"nodes\": [...], \"all_terms\": [...], "
                 "\"ambient_only\": [...]}), as docs/scenes.md describes");
  return {{"fields", json::array({f})}};
}

json derive_form(const Problem& p) {
  const auto* task = dynamic_cast<const DeriveTask*>(p.task.get());
  json fields = json::array();
  if (!task) return {{"fields", fields}};
  json symbols = json::array();
  for (const auto& s : task->symbols()) {
    symbols.push_back(s.name);
    if (s.display != s.name) symbols.push_back(s.display);
  }
  for (const auto& q : task->quantities()) {
    json f = field("formula", q.name, q.name + " =");
    f["symbols"] = symbols;
    fields.push_back(f);
  }
  return {{"fields", fields}};
}

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
  if (p.kind == "intersect") return intersect_form(p);
  if (p.kind == "first-hit") return first_hit_form(p);
  if (p.kind == "camera-ray") return camera_ray_form();
  if (p.kind == "reflect") return reflect_form();
  if (p.kind == "refract") return refract_form();
  if (p.kind == "normal") return normal_form(p);
  if (p.kind == "fresnel") return fresnel_form();
  if (p.kind == "view-ray") return view_ray_form();
  if (p.kind == "shade") return shade_form(p);
  if (p.kind == "ray-tree") return ray_tree_form(p);
  if (p.kind == "derive") return derive_form(p);
  return {{"fields", json::array({field("json", "", "The answer as JSON")})}};
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
