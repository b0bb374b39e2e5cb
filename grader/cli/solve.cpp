// raygrade solve: the reference answer of every problem, and optionally its worked steps.
#include <fmt/format.h>

#include <iostream>

#include "assignments/variants.h"
#include "cli/command.h"
#include "problems/problem.h"
#include "reports/render.h"
#include "reports/solve_output.h"

namespace raygrade::cli {
namespace {

struct SolveOptions {
  std::vector<std::string> paths;
  std::string format = "json";
  std::string method;
  int precision = -1;
  bool steps = false;
  std::string student;      // with an assignment: that student's variant
  bool assignment = false;  // set when the one path is an assignment file
};

// The problems to solve: a bank's, or an assignment's (one student's variant, or the
// generic set with the default numbers).
Bank problems_to_solve(SolveOptions& o) {
  bool assignment = o.paths.size() == 1 && is_assignment_file(o.paths[0]);
  if (!assignment) {
    if (!o.student.empty()) {
      throw Error(Diagnostic{o.paths.empty() ? "" : o.paths[0], "", 0, 0, Severity::kError,
                             "--student goes with one assignment file", "usage"});
    }
    return load_bank(o.paths);
  }
  o.assignment = true;
  return student_bank(load_assignment(o.paths[0]), o.student);
}

int run_solve(SolveOptions& o) {
  Bank bank;
  try {
    bank = problems_to_solve(o);
  } catch (const Error& e) {
    fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
    return kExitBadInput;
  }
  for (const auto& e : bank.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  std::vector<Diagnostic> failures;
  std::string out = solve_output(
      bank, SolveOutputOptions{o.format, o.method, o.precision, o.steps, o.assignment}, failures);
  for (const auto& d : failures) fmt::print(stderr, "{}\n", format_diagnostic(d));
  std::cout << out;
  return bank.errors.empty() ? kExitOk : kExitBadInput;
}

}  // namespace

Runner setup_solve(CLI::App& sub) {
  auto o = std::make_shared<SolveOptions>();
  sub.add_option("paths", o->paths, "problem files or folders, or one assignment file")->required();
  sub.add_option("--format", o->format,
                 "json (answers; with --steps, the steps too), or a worked solution as md, html "
                 "or txt")
      ->check(CLI::IsMember(solution_format_names()));
  sub.add_option("--method", o->method, "a method name, or 'all' to show every method");
  sub.add_option("--precision", o->precision,
                 "decimals shown in worked solutions (default: the problem's precision, else 4 "
                 "significant digits)")
      ->check(CLI::Range(0, 15));
  sub.add_flag("--steps", o->steps, "with --format json: include the derivation steps");
  sub.add_option("--student", o->student,
                 "with an assignment file: the student (id) whose own numbers are solved");
  return [o] { return run_solve(*o); };
}

}  // namespace raygrade::cli
