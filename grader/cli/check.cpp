// raygrade check: validate a problem bank, solve it, and flag wrong or ill-posed problems.
#include "check/check.h"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>

#include "assignments/assignment.h"
#include "assignments/check_assignment.h"
#include "check/report.h"
#include "cli/command.h"

namespace raygrade::cli {
namespace {

struct CheckCliOptions {
  std::vector<std::string> paths;
  std::string format = "text";
  std::string solutions;
  bool solutions_given = false;
  bool no_solutions = false;
  bool no_conditioning = false;
  bool strict = false;
};

int run_check(const CheckCliOptions& o) {
  CheckOptions options;
  if (o.no_solutions) {
    // neither solutions_dir nor solutions_search: no check
  } else if (o.solutions_given) {
    options.solutions_dir = o.solutions;
  } else {
    options.solutions_search = solution_folder_candidates(o.paths);
  }
  options.solutions_required = o.solutions_given;
  options.conditioning = !o.no_conditioning;
  // One assignment file: the assignment and a sample of its variants; otherwise a bank.
  bool assignment = o.paths.size() == 1 && is_assignment_file(o.paths[0]);
  CheckReport report = assignment ? check_assignment(o.paths[0]) : check_bank(o.paths, options);
  if (o.format == "json") {
    std::cout << check_report_json(report).dump(2) << "\n";
  } else if (o.format == "junit") {
    std::cout << check_report_junit(report);
  } else {
    std::cout << check_report_text(report);
  }
  std::cout.flush();
  if (report.unreadable) return kExitBadInput;
  bool failed =
      report.count(Severity::kError) > 0 || (o.strict && report.count(Severity::kWarning) > 0);
  return failed ? kExitFailed : kExitOk;
}

}  // namespace

Runner setup_check(CLI::App& sub) {
  auto o = std::make_shared<CheckCliOptions>();
  sub.add_option("paths", o->paths, "problem files or folders, or one assignment file")->required();
  sub.add_option("--format", o->format, "text (default), json or junit")
      ->check(CLI::IsMember({"text", "json", "junit"}));
  auto* solutions =
      sub.add_option("--solutions", o->solutions,
                     "the folder of worked solutions (default: the first of PATH/solutions, "
                     "solutions beside PATH, and ./solutions that exists)");
  sub.add_flag("--no-solutions", o->no_solutions, "do not check that worked solutions exist");
  sub.add_flag("--no-conditioning", o->no_conditioning,
               "skip the conditioning check (perturbing every printed input)");
  sub.add_flag("--strict", o->strict, "warnings fail the check too");
  return [o, solutions] {
    o->solutions_given = solutions->count() > 0;
    return run_check(*o);
  };
}

}  // namespace raygrade::cli
