// raygrade: solve, explain and grade ray-intersection exercises.
#include <fmt/format.h>

#include <cstring>
#include <iostream>
#include <string>

#include "cli/command.h"
#include "json/cursor.h"

int main(int argc, char** argv) {
  using namespace raygrade::cli;
  CLI::App app{"raygrade: solve, explain and grade ray-intersection exercises"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "raygrade 0.1.0");
  std::vector<std::pair<CLI::App*, Runner>> runners;
  for (const auto& c : command_table()) {
    CLI::App* sub = app.add_subcommand(std::string(c.name), std::string(c.summary));
    runners.emplace_back(sub, c.setup(*sub));
  }
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const auto& c : command_table()) names.emplace_back(c.name);
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::string hint = raygrade::closest_match(argv[1], names);
      fmt::print(stderr, "raygrade: unknown command '{}'{}\n", argv[1],
                 hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint));
      return kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  for (auto& [sub, run] : runners) {
    if (sub->parsed()) {
      try {
        return run();
      } catch (const std::logic_error& e) {
        fmt::print(stderr, "raygrade: internal error: {}; please report it with the input\n",
                   e.what());
        return kExitInternal;
      } catch (const std::exception& e) {
        fmt::print(stderr, "raygrade: {}\n", e.what());
        return kExitBadInput;
      }
    }
  }
  return kExitBadInput;
}
