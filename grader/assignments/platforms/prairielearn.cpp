// The PrairieLearn course fragment of an assignment: one question per problem, and raygrade
// with the assignment in serverFilesCourse.
#include "assignments/platforms/prairielearn.h"

#include <fmt/format.h>

#include <set>

#include "assignments/answer_form.h"
#include "assignments/platforms/prairielearn_assets.h"
#include "assignments/variants.h"
#include "core/escape.h"
#include "grading/outputs.h"
#include "kinds/fields/field_type.h"
#include "kinds/part_names.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

// Text in question.html: HTML-escaped, with braces as entities so that PrairieLearn's
// mustache pass leaves it alone.
std::string html_text(std::string_view s) { return html_escape_braces(s); }

// How one input of question.html reads: its element, and where server.py puts its value in
// the answer (raygrade.json's "inputs").
struct Input {
  json spec;         // name, type, path, and list/column/words/options
  std::string html;  // the element
};

std::string string_input(const std::string& name, const std::string& label,
                         const std::string& placeholder) {
  return fmt::format(
      // display="block": the input takes the line's width, however long its label. No
      // help popover: PrairieLearn's own says what its grader reads, and raygrade reads these.
      "<pl-string-input answers-name=\"{}\" label=\"{}\" placeholder=\"{}\" allow-blank=\"true\" "
      "remove-leading-trailing=\"true\" display=\"block\" show-help-text=\"false\">"
      "</pl-string-input>",
      name, html_text(label), html_text(placeholder));
}

// A choice among fixed options; raygrade grades it, not the element. A long list shows as a
// drop-down.
std::string choice_input(const std::string& name, const std::string& label, const json& options,
                         bool dropdown = false) {
  std::string html = fmt::format(
      "<p>{}</p>\n<pl-multiple-choice answers-name=\"{}\" "
      "builtin-grading=\"false\" order=\"fixed\" allow-blank=\"true\"{}>",
      html_text(label), name, dropdown ? " display=\"dropdown\"" : "");
  for (const auto& o : options) {
    html += fmt::format("\n  <pl-answer>{}</pl-answer>", html_text(o["text"].get<std::string>()));
  }
  return html + "\n</pl-multiple-choice>";
}

json yes_no() {
  return json::array({{{"text", "yes"}, {"value", true}}, {{"text", "no"}, {"value", false}}});
}

std::string placeholder_of(const json& field) {
  return std::string(field_type_of(field).placeholder);
}

// A ray tree as a fixed number of points I1, I2, ... (the form's "rows"), each a drop-down of
// where its ray comes from and one of the object it meets, then per light the shadow ray's
// status and its blockers, and the Phong terms. server.py puts the choices under
// "raygrade:tree" and turns them into the answer's nodes (docs/assignments.md).
void tree_inputs(const json& f, std::vector<Input>& out, json& question) {
  question["tree"] = true;
  int rows = f["rows"];
  std::set<std::string> asks;
  for (const auto& a : f["asks"]) asks.insert(a.get<std::string>());
  json none = {{"text", "\u2014"}, {"value", nullptr}};
  auto add_choice = [&](const std::string& name, const json& path, const std::string& label,
                        json options) {
    json spec = {{"name", name},
                 {"type", field_value_word(FieldValue::kOneOf)},
                 {"path", path},
                 {"options", options}};
    out.push_back({spec, choice_input(name, label, options, true)});
  };
  for (int k = 1; k <= rows; ++k) {
    std::string row = std::to_string(k), point = fmt::format("I{}", k);
    json base = json::array({"raygrade:tree", row});
    auto at = [&](const std::string& key) {
      json path = base;
      path.push_back(key);
      return path;
    };
    json from = json::array({none, {{"text", "the eye (the primary ray)"}, {"value", "eye"}}});
    for (int j = 1; j <= rows; ++j) {
      if (j == k) continue;
      from.push_back(
          {{"text", fmt::format("the reflection at I{}", j)}, {"value", fmt::format("R:{}", j)}});
      from.push_back(
          {{"text", fmt::format("the refraction at I{}", j)}, {"value", fmt::format("T:{}", j)}});
    }
    add_choice(fmt::format("tree_{}_from", k), at("from"),
               fmt::format("Point {}: the ray that meets it comes from", point), from);
    json objects = json::array({none});
    for (const auto& o : f["objects"]) objects.push_back({{"text", o}, {"value", o}});
    objects.push_back(
        {{"text", "nothing: the ray leaves the scene"}, {"value", "raygrade:nothing"}});
    add_choice(fmt::format("tree_{}_object", k), at("object"),
               fmt::format("Point {}: the object it is on", point), objects);
    if (asks.count(part_names::kShadows)) {
      for (std::size_t i = 0; i < f["lights"].size(); ++i) {
        std::string light = f["lights"][i];
        json status = json::array({none,
                                   {{"text", "reaches the light (lit)"}, {"value", "lit"}},
                                   {{"text", "is blocked (in shadow)"}, {"value", "shadow"}},
                                   {{"text", "the surface faces away"}, {"value", "away"}}});
        add_choice(fmt::format("tree_{}_light_{}", k, i), at(fmt::format("light{}", i)),
                   fmt::format("Point {}: the shadow ray toward {}", point, light), status);
        std::string name = fmt::format("tree_{}_blockers_{}", k, i);
        json spec = {{"name", name}, {"type", "names"}, {"path", at(fmt::format("blockers{}", i))}};
        out.push_back(
            {spec, string_input(name,
                                fmt::format("Point {}: when in shadow, the shadow ray toward {} "
                                            "is blocked by (names separated by commas)",
                                            point, light),
                                "names of objects, or blank")});
      }
    }
    if (asks.count(part_names::kTerms)) {
      json terms = json::array({none});
      for (const auto& [text, set] : std::vector<std::pair<std::string, std::vector<std::string>>>{
               {"ambient only", {"ambient"}},
               {"ambient and diffuse", {"ambient", "diffuse"}},
               {"ambient and specular", {"ambient", "specular"}},
               {"ambient, diffuse and specular", {"ambient", "diffuse", "specular"}}}) {
        terms.push_back({{"text", text}, {"value", set}});
      }
      add_choice(fmt::format("tree_{}_terms", k), at("terms"),
                 fmt::format("Point {}: the Phong terms that apply", point), terms);
    }
  }
}

// One input per value the student types: a field of the answer form, a column of its hits (all
// the hits' values in one input, separated by semicolons), or a cell of its rows.
void inputs_of_field(const json& f, std::vector<Input>& out, json& question) {
  const FieldTypeEntry& type = field_type_of(f);
  std::string key = f["key"], label = f["label"];
  json path = json::array();
  std::string name;
  for (std::size_t start = 0;;) {
    std::size_t slash = key.find('/', start);
    path.push_back(key.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  for (const auto& p : path) name += (name.empty() ? "" : "_") + p.get<std::string>();
  if (type.shape == FieldShape::kOpenTable) {
    question["hits_key"] = key;
    bool several = f.value("several", false);
    json words = {{"none", "none"}};
    std::string hint = "none when the ray misses";
    if (f.contains("contained")) {
      words["contained"] = "contained";
      hint += ", contained when it lies in the surface";
    }
    for (const auto& c : f["columns"]) {
      std::string column = c["key"];
      json spec = {{"name", column},
                   {"type", field_value_word(field_type_of(c).value)},
                   {"list", true},
                   {"column", column}};
      if (column == part_names::kT) spec["words"] = words;
      std::string what = several ? column + " of every hit, in the same order, separated by ;"
                                 : column + " of the first hit";
      if (column == part_names::kT) what += " (" + hint + ")";
      out.push_back({spec, string_input(column, what, placeholder_of(c))});
    }
    return;
  }
  if (type.shape == FieldShape::kTreeBuilder) return tree_inputs(f, out, question);
  if (type.shape == FieldShape::kFixedRows) {
    for (std::size_t r = 0; r < f["rows"].size(); ++r) {
      const json& row = f["rows"][r];
      for (const auto& c : f["columns"]) {
        std::string column = c["key"];
        std::string cell = fmt::format("{}_{}_{}", name, r, column);
        json spec = {{"name", cell},
                     {"type", field_value_word(field_type_of(c).value)},
                     {"path", {key, r, column}}};
        std::string what =
            fmt::format("{}, {}", row["label"].get<std::string>(), c["label"].get<std::string>());
        if (field_type_of(c).value == FieldValue::kFlag) {
          spec["options"] = yes_no();
          out.push_back({spec, choice_input(cell, what, spec["options"])});
        } else {
          out.push_back({spec, string_input(cell, what, placeholder_of(c))});
        }
      }
    }
    return;
  }
  json spec = {{"name", name.empty() ? "answer" : name},
               {"type", field_value_word(type.value)},
               {"path", path}};
  if (type.value == FieldValue::kOneOf || type.value == FieldValue::kFlag) {
    spec["options"] = type.value == FieldValue::kFlag ? yes_no() : f["options"];
    out.push_back({spec, choice_input(spec["name"], label, spec["options"])});
    return;
  }
  std::string hint = label;
  if (type.value == FieldValue::kSomeOf) {
    for (std::size_t k = 0; k < f["options"].size(); ++k)
      hint += (k ? ", " : " (") + f["options"][k].get<std::string>();
    hint += ")";
  }
  out.push_back({spec, string_input(spec["name"], hint, placeholder_of(f))});
}

// A PrairieLearn uuid that is the same at every export of a problem of an assignment: its two
// halves are raygrade variant seeds (FNV-1a) of the assignment and problem ids, with the
// version (8, vendor-defined) and variant bits of RFC 9562.
std::string question_uuid(const std::string& assignment, const std::string& problem) {
  std::uint64_t hi = variant_seed(assignment, 0, "prairielearn-uuid-1", problem);
  std::uint64_t lo = variant_seed(assignment, 0, "prairielearn-uuid-2", problem);
  hi = (hi & ~0xf000ULL) | 0x8000ULL;
  lo = (lo & ~(0xc000ULL << 48)) | (0x8000ULL << 48);
  return fmt::format("{:08x}-{:04x}-{:04x}-{:04x}-{:012x}", hi >> 32, (hi >> 16) & 0xffff,
                     hi & 0xffff, lo >> 48, lo & 0xffffffffffffULL);
}

const char* kFeedbackPanel = R"html(<pl-submission-panel>
{{#feedback.raygrade}}
<ul>
{{#parts}}<li><strong>{{name}}</strong> ({{status}}){{#feedback}}: {{feedback}}{{/feedback}}</li>
{{/parts}}
{{#lines}}<li>{{.}}</li>
{{/lines}}
</ul>
{{/feedback.raygrade}}
</pl-submission-panel>
)html";

// The title as the bank writes it, each parameter named rather than given a value ("The camera
// ray through pixel (x, y)"): the instructor's list of questions shows no student's numbers.
std::string general_title(const Problem& p) {
  // A problem with parameters keeps its text as written (with "{h}") as its template.
  if (!p.template_json || !p.template_json->is_object()) return p.title.empty() ? p.id : p.title;
  auto it = p.template_json->find("title");
  if (it == p.template_json->end() || !it->is_string()) return p.id;
  std::string title;
  for (char c : it->get<std::string>()) {
    if (c != '{' && c != '}') title += c;
  }
  return title;
}

}  // namespace

std::vector<ZipEntry> prairielearn_course(const AssignmentSpec& spec,
                                          const std::vector<const Problem*>& problems,
                                          const Bank& bank, const std::filesystem::path& binary) {
  std::vector<ZipEntry> entries;
  std::string files = "serverFilesCourse/raygrade/";
  // Folder names from ids: never a path outside the course, never two the same.
  std::string assignment_folder = safe_file_name(spec.id);
  std::set<std::string> question_folders;
  entries.push_back({files + "raygrade", read_file_bytes(binary), true});
  for (auto& e : assignment_files(spec, bank)) {
    e.name = files + assignment_folder + "/" + e.name;
    entries.push_back(std::move(e));
  }
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const Problem& p = *problems[i];
    bool varies =
        spec.per_student && spec.problems[i].variants && p.parameters && !p.parameters->empty();
    std::string name = safe_file_name(p.id);
    for (int k = 2; !question_folders.insert(name).second; ++k)
      name = fmt::format("{}-{}", safe_file_name(p.id), k);
    std::string folder = fmt::format("questions/{}/{}/", assignment_folder, name);
    json info = {{"uuid", question_uuid(spec.id, p.id)},
                 {"type", "v3"},
                 {"title", varies            ? general_title(p)
                           : p.title.empty() ? p.id
                                             : p.title},
                 {"topic", "Ray intersection"},
                 {"tags", json::array({"raygrade", spec.id, p.kind})},
                 {"singleVariant", !varies},
                 {"showCorrectAnswer", false},
                 {"partialCredit", true}};
    json form = answer_form(p);
    json question = {
        {"assignment", assignment_folder}, {"problem", p.id}, {"blank", blank_answer(form)}};
    std::vector<Input> inputs;
    for (const auto& f : form["fields"]) inputs_of_field(f, inputs, question);
    question["inputs"] = json::array();
    std::string html =
        "<pl-question-panel>\n<p><strong>{{params.title}}</strong></p>\n<p>{{params.statement}}"
        "</p>\n</pl-question-panel>\n\n";
    for (const auto& in : inputs) {
      question["inputs"].push_back(in.spec);
      html += in.html + "\n\n";
    }
    html += kFeedbackPanel;
    entries.push_back({folder + "info.json", info.dump(2) + "\n", false});
    entries.push_back({folder + "question.html", html, false});
    entries.push_back({folder + "server.py", std::string(kPrairieLearnServer), false});
    entries.push_back({folder + "raygrade.json", question.dump(2) + "\n", false});
  }
  return entries;
}

namespace {

LmsPackage prairielearn_package(const LmsExportInput& in, const std::string& out) {
  LmsPackage p;
  p.files = prairielearn_course(*in.spec, in.bank->problems, in.bank->bank, in.binary);
  p.next_step = fmt::format(
      "Wrote {0}/questions/{1}/ ({2} questions) and {0}/serverFilesCourse/raygrade/ (raygrade "
      "from {3}). Copy both folders into the PrairieLearn course's repository and list the "
      "questions in an assessment.",
      out, safe_file_name(in.spec->id), in.spec->problems.size(), in.binary.string());
  return p;
}

}  // namespace

LmsExport PrairieLearn::lms_export() {
  LmsExport e;
  e.summary = "one question per problem, with raygrade in serverFilesCourse";
  e.ships_binary = true;
  e.make = &prairielearn_package;
  return e;
}

nlohmann::json prairielearn_json(const SubmissionGrade& g) {
  nlohmann::json tests = nlohmann::json::array();
  for (const auto& r : g.results) {
    auto lines = feedback_lines(r);
    tests.push_back({{"name", result_test_name(r)},
                     {"description", r.problem_id},
                     {"points", r.score},
                     {"max_points", r.max_score},
                     {"message", r.score >= r.max_score ? "Right."
                                 : lines.empty()        ? ""
                                                        : lines.front()},
                     {"output", joined_lines(lines)}});
  }
  return {{"gradable", g.gradable},
          {"score", g.gradable ? std::clamp(g.fraction(), 0.0, 1.0) : 0.0},
          {"message", grade_summary(g)},
          {"output", g.gradable ? "" : grade_summary(g)},
          {"tests", tests}};
}

namespace {

std::string prairielearn_format(const SubmissionGrade& g, double /*seconds*/) {
  return json_text(prairielearn_json(g)) + "\n";
}

}  // namespace

GradeFormat PrairieLearn::results_format() {
  return {"prairielearn",
          "PrairieLearn's external grader results.json",
          ".json",
          GradeLayout::kDocument,
          true,
          true,
          &prairielearn_format};
}

}  // namespace raygrade
