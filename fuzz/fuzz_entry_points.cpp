// The readers of untrusted input, driven one input at a time.
#include "fuzz_entry_points.h"

#include <string>

#include "core/error.h"
#include "derivation/formula.h"
#include "grading/answer_reader.h"
#include "grading/grade.h"
#include "json/cursor.h"
#include "json/source.h"
#include "problems/problem.h"
#include "reports/json_report.h"
#include "reports/text.h"

namespace raygrade::fuzz {
namespace {

// JSON text with the limits of a submission, then every value's location and a dump.
void json_source(std::string_view input) {
  try {
    auto file = parse_json_text("fuzz.json", std::string(input), JsonLimits::submission());
    (void)file->root.dump();
    for (const auto& p : {"", "/0", "/answers/0/t", "/a/b/c"}) (void)locate(file->text, p);
    Cursor root(file);
    if (root.is_object()) {
      for (const auto& [key, value] : file->root.items()) (void)root.find(key);
      root.allow_only({"answers", "student"});
    }
  } catch (const Error&) {
  }
}

// A bank file: every problem read, solved and derived by each of its methods, as
// `raygrade solve --steps` does.
void problem_loader(std::string_view input) {
  std::shared_ptr<const SourceFile> file;
  try {
    file = parse_json_text("fuzz.json", std::string(input));
  } catch (const Error&) {
    return;
  }
  Cursor root(file);
  std::vector<Cursor> items;
  try {
    if (root.is_object() && root.has("problems")) {
      items = root.at("problems").items();
    } else {
      items.push_back(root);
    }
  } catch (const Error&) {
    return;
  }
  for (const auto& item : items) {
    try {
      Problem p = read_problem(item);
      (void)p.task->answer().dump();
      for (const auto& m : p.task->methods()) {
        auto parts = p.task->derive(m);
        (void)parts_json(parts, number_format_for(p, -1)).dump();
        (void)render_text(p, parts, number_format_for(p, -1));
      }
    } catch (const Error&) {
    }
  }
}

// A number as a student types it ("9 - sqrt(3)", "1/3", "7.27").
void number_parser(std::string_view input) {
  auto n = parse_student_number(input);
  if (n.value) (void)typed_digits(n.value->text);
}

// A formula in a problem's symbols, evaluated at a point, as the formula checker does.
void formula_parser(std::string_view input) {
  static const SymbolTable symbols = [] {
    SymbolTable t;
    for (const char* name : {"px", "py", "pz", "vx", "vy", "vz", "r"}) t.add(name);
    return t;
  }();
  FormulaParse p = parse_formula(input, &symbols);
  if (p.ok) (void)p.formula.evaluate({0.5, -1.25, 2, 1e-3, 3, -7, 1});
}

// One answer (JSON, with a submission's limits) graded against a problem of every kind.
void grader(std::string_view input) {
  static const std::vector<Problem> problems = [] {
    std::vector<Problem> out;
    for (const char* text : {
             R"({"id": "sphere", "method": "geometric",
                 "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
                 "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})",
             R"({"id": "plane", "method": "implicit",
                 "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
                 "object": {"type": "plane", "point": [2, 0, 0], "normal": [-1, 0, 0]}})",
             R"({"id": "cylinder", "ray": {"origin": [1, 2, 0], "direction": [1, 1, 0]},
                 "object": {"type": "cylinder", "base": [0, 0, 0], "radius": 1}})",
             R"({"id": "triangle", "ray": {"origin": [0.2, 0.2, 1], "direction": [0, 0, -1]},
                 "object": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}})",
             R"({"id": "first", "kind": "first-hit", "precision": 2,
                 "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
                 "objects": [{"name": "a", "type": "sphere", "center": [0, 0, 10], "radius": 2},
                             {"name": "b", "type": "sphere", "center": [0, 1, 9], "radius": 2}]})",
             R"({"id": "camera", "kind": "camera-ray", "convention": "corner",
                 "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0],
                            "focal_length": 4, "resolution": [8, 6]}, "pixel": [2, 5]})"}) {
      out.push_back(read_problem(Cursor(parse_json_text("grader.json", text))));
    }
    return out;
  }();
  static const std::vector<Grader> graders(problems.begin(), problems.end());
  std::shared_ptr<const SourceFile> file;
  try {
    file = parse_json_text("fuzz.json", std::string(input), JsonLimits::submission());
  } catch (const Error&) {
    return;
  }
  for (const auto& g : graders) {
    try {
      (void)g.grade(file->root, GradeOptions{"fuzz.json", ""});
    } catch (const Error&) {
    }
  }
}

}  // namespace

const std::vector<Target>& targets() {
  static const std::vector<Target> table = {
      {"json_source", &json_source},
      {"problem_loader", &problem_loader},
      {"number_parser", &number_parser},
      {"formula_parser", &formula_parser},
      {"grader", &grader},
  };
  return table;
}

}  // namespace raygrade::fuzz
