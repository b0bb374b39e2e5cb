// raygrade run: the main job over a bank, its solutions folder and sample submissions.
#include <fmt/format.h>

#include <map>

#include "cli/command.h"
#include "problems/problem.h"
#include "reports/solutions_folder.h"

namespace raygrade::cli {

// In grade.cpp: grades the sample submissions and prints a summary line; the exit code.
int grade_sample_submissions(const Bank& bank, const std::string& folder);

namespace {

struct RunOptions {
  std::vector<std::string> problems = {"problems"};
  std::string submissions = "submissions";
  std::string solutions = "solutions";
};

int run_main_job(const RunOptions& o) {
  Bank bank = load_bank(o.problems);
  for (const auto& e : bank.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  std::map<std::string, int> by_kind;
  int solved = 0, failed = 0;
  for (const auto& p : bank.problems) {
    try {
      (void)p.task->answer();
      ++solved;
      ++by_kind[p.kind];
    } catch (const Error& e) {
      fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
      ++failed;
    }
  }
  std::vector<std::string> kinds;
  kinds.reserve(by_kind.size());
  for (const auto& [k, n] : by_kind) kinds.push_back(fmt::format("{} {}", n, k));
  fmt::print("Solved {} problems from {} files ({}).\n", solved, bank.files.size(),
             fmt::join(kinds, ", "));
  std::vector<Diagnostic> unsolved;
  auto files = solution_files(bank.problems, all_formats(),
                              solutions_command(o.problems, o.solutions), unsolved);
  FolderSync sync = write_solution_folder(o.solutions, files);
  for (const auto& e : unsolved) fmt::print(stderr, "{}\n", format_diagnostic(e));
  fmt::print(
      "Wrote the worked solutions of {} problems to {}/ ({} files new or changed, {} "
      "unchanged, {} removed).\n",
      bank.problems.size() - unsolved.size(), o.solutions, sync.written.size(), sync.unchanged,
      sync.removed.size());
  failed += static_cast<int>(unsolved.size());
  int graded = grade_sample_submissions(bank, o.submissions);
  if (!bank.errors.empty() || failed) {
    fmt::print("{} problems could not be read or solved.\n", bank.errors.size() + failed);
    return kExitBadInput;
  }
  return graded;
}

}  // namespace

Runner setup_run(CLI::App& sub) {
  auto o = std::make_shared<RunOptions>();
  sub.add_option("--problems", o->problems, "the bank: files or folders");
  sub.add_option("--submissions", o->submissions, "a folder of sample submissions");
  sub.add_option("--solutions", o->solutions, "where worked solutions are written");
  return [o] { return run_main_job(*o); };
}

}  // namespace raygrade::cli
