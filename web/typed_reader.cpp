// The pages' reader of typed answers: the grader's own (grading/typed_box.h) compiled alone to
// WebAssembly by scripts/build-typed-reader.sh, and embedded in the handout, practice and SCORM
// pages (grader/assignments/typed_reader.js), so that a page reads every typed box as the
// grader does.
#include <string>

#include "grading/typed_box.h"

namespace {

std::vector<std::string> split_symbols(std::string_view text) {
  std::vector<std::string> out;
  while (!text.empty()) {
    std::size_t comma = text.find(',');
    out.emplace_back(text.substr(0, comma));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return out;
}

}  // namespace

// `box` is "number", "vector" or "formula"; `answer_json` the box's value as JSON text;
// `symbols` a formula box's names, separated by commas. The reading as JSON text
// (typed_reading_json), valid until the next call.
extern "C" const char* raygrade_read_typed(const char* box, const char* answer_json,
                                           const char* symbols) {
  static std::string out;
  raygrade::TypedBox b{};
  if (!raygrade::typed_box_from_name(box, b)) {
    out = R"({"ok":false,"message":"unknown box"})";
    return out.c_str();
  }
  raygrade::TypedReading r = raygrade::read_typed_box(b, answer_json, split_symbols(symbols));
  out = raygrade::typed_reading_json(r).dump(-1, ' ', false,
                                             nlohmann::json::error_handler_t::replace);
  return out.c_str();
}
