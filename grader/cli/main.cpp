// raygrade: solve, explain and grade ray-intersection exercises.
#include <fmt/format.h>

#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <system_error>

#include "cli/command.h"
#include "core/error.h"
#include "json/cursor.h"

namespace {

bool is_resource_error(const std::error_code& code) {
  using std::errc;
  for (errc e :
       {errc::resource_unavailable_try_again, errc::not_enough_memory, errc::no_space_on_device,
        errc::too_many_files_open, errc::too_many_files_open_in_system, errc::file_too_large}) {
    if (code == e) return true;
  }
  return false;
}

}  // namespace

// What can still escape (memory running out while the command line's parser is built, an error
// message that cannot be written) ends the program through std::terminate: nothing better is
// left to do then.
// NOLINTNEXTLINE(bugprone-exception-escape)
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
      } catch (const std::bad_alloc&) {
        fmt::print(stderr, "raygrade: out of memory\n");
        return kExitResource;
      } catch (const std::system_error& e) {
        // A thread, memory, disk space or a file the system would not give is a resource;
        // anything else (a folder that cannot be made, say) is the input's.
        fmt::print(stderr, "raygrade: {}\n", e.what());
        return is_resource_error(e.code()) ? kExitResource : kExitBadInput;
      } catch (const raygrade::Error& e) {
        fmt::print(stderr, "{}\n", raygrade::format_diagnostic(e.diagnostic()));
        return e.diagnostic().code == "resource" ? kExitResource : kExitBadInput;
      } catch (const std::exception& e) {
        fmt::print(stderr, "raygrade: {}\n", e.what());
        return kExitBadInput;
      }
    }
  }
  return kExitBadInput;
}
