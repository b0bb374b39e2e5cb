// The readers of untrusted input, driven one input at a time.
#include "fuzz_entry_points.h"

#include <string>

#include "core/error.h"
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

}  // namespace

const std::vector<Target>& targets() {
  static const std::vector<Target> table = {
      {"json_source", &json_source},
      {"problem_loader", &problem_loader},
  };
  return table;
}

}  // namespace raygrade::fuzz
