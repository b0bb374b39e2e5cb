// The table of subcommands: {name, summary, setup}. Each command registers its options on
// its CLI11 subcommand and returns the function that runs it.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string_view>
#include <vector>

namespace raygrade::cli {

// Exit codes, the same for every command.
enum ExitCode : int {
  kExitOk = 0,        // everything solved, graded or checked as expected
  kExitFailed = 1,    // wrong answers, failed checks or stale files
  kExitBadInput = 2,  // bad usage, or some input could not be read
  kExitInternal = 3,  // a bug of raygrade (an internal error), whatever the input
  kExitResource = 4,  // the machine's limits: out of memory, a full disk, no thread could start
};

using Runner = std::function<int()>;

struct Command {
  std::string_view name;
  std::string_view summary;
  Runner (*setup)(CLI::App& sub);
};

const std::vector<Command>& command_table();

}  // namespace raygrade::cli
