// raygrade read-typed (hidden, for tests): typed answer boxes read as the grader reads them.
// Each line of standard input is a box and the JSON text of its value, separated by a tab:
//   number<TAB>"1/3"
//   vector<TAB>["1", "2", "3"]
//   formula:px,vx<TAB>"2*px + vx"
// and each line of output is the reading as JSON (grading/typed_box.h).
#include <fmt/format.h>

#include <iostream>
#include <string>

#include "cli/command.h"
#include "grading/typed_box.h"

namespace raygrade::cli {
namespace {

// The symbols after "formula:", separated by commas.
std::vector<std::string> symbol_list(std::string_view text) {
  std::vector<std::string> out;
  while (!text.empty()) {
    std::size_t comma = text.find(',');
    out.emplace_back(text.substr(0, comma));
    if (comma == std::string_view::npos) break;
    text.remove_prefix(comma + 1);
  }
  return out;
}

int run_read_typed() {
  std::string line;
  int line_number = 0;
  while (std::getline(std::cin, line)) {
    ++line_number;
    std::size_t tab = line.find('\t');
    std::string_view head = std::string_view(line).substr(0, tab);
    std::size_t colon = head.find(':');
    TypedBox box{};
    if (tab == std::string::npos || !typed_box_from_name(head.substr(0, colon), box)) {
      fmt::print(stderr, "raygrade read-typed: line {}: expected BOX<TAB>JSON\n", line_number);
      return kExitBadInput;
    }
    std::vector<std::string> symbols;
    if (colon != std::string_view::npos) symbols = symbol_list(head.substr(colon + 1));
    TypedReading r = read_typed_box(box, std::string_view(line).substr(tab + 1), symbols);
    fmt::print("{}\n", typed_reading_json(r).dump(-1, ' ', false,
                                                  nlohmann::json::error_handler_t::replace));
  }
  return kExitOk;
}

}  // namespace

Runner setup_read_typed(CLI::App& sub) {
  sub.group("");  // not listed in --help: a tool of the tests
  return [] { return run_read_typed(); };
}

}  // namespace raygrade::cli
