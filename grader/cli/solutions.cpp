// raygrade solutions: regenerate (or check) the folder of worked solutions of a bank.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/command.h"
#include "reports/solutions_folder.h"

namespace raygrade::cli {
namespace {

struct SolutionsOptions {
  std::vector<std::string> paths;
  std::string out = "solutions";
  std::vector<std::string> formats = solution_format_names();
  bool check = false;
};

std::string command_line(const SolutionsOptions& o) { return solutions_command(o.paths, o.out); }

int run_solutions(const SolutionsOptions& o) {
  Bank bank = load_bank(o.paths);
  std::vector<Format> formats;
  for (const auto& f : o.formats) formats.push_back(*parse_format(f));
  std::vector<GeneratedFile> files =
      solution_files(bank.problems, formats, command_line(o), bank.errors);
  for (const auto& e : bank.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  if (o.check) {
    FolderSync s = check_solution_folder(o.out, files);
    for (const auto& n : s.written) fmt::print("stale or missing: {}/{}\n", o.out, n);
    for (const auto& n : s.removed) fmt::print("no longer generated: {}/{}\n", o.out, n);
    if (!s.written.empty() || !s.removed.empty()) {
      fmt::print("{} is out of date: run `{}`.\n", o.out, command_line(o));
      return kExitFailed;
    }
    fmt::print("{} is up to date ({} files).\n", o.out, s.unchanged);
    return bank.errors.empty() ? kExitOk : kExitBadInput;
  }
  FolderSync s = write_solution_folder(o.out, files);
  fmt::print("Wrote {} of {} files in {} ({} unchanged, {} removed).\n", s.written.size(),
             files.size(), o.out, s.unchanged, s.removed.size());
  return bank.errors.empty() ? kExitOk : kExitBadInput;
}

}  // namespace

Runner setup_solutions(CLI::App& sub) {
  auto o = std::make_shared<SolutionsOptions>();
  sub.add_option("paths", o->paths, "problem files or folders")->required();
  sub.add_option("--out", o->out, "the solutions folder (default: solutions)");
  sub.add_option("--format", o->formats,
                 fmt::format("formats to write, separated by commas (default: {})",
                             fmt::join(solution_format_names(), ",")))
      ->check(CLI::IsMember(solution_format_names()))
      ->delimiter(',');
  sub.add_flag("--check", o->check,
               "change nothing; exit 1 listing files that are stale, missing or no longer "
               "generated");
  return [o] { return run_solutions(*o); };
}

}  // namespace raygrade::cli
