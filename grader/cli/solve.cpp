// raygrade solve: the reference answer of every problem, and optionally its worked steps.
#include <fmt/format.h>

#include <iostream>

#include "assignments/variants.h"
#include "cli/command.h"
#include "problems/problem.h"
#include "reports/json_report.h"
#include "reports/render.h"

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
  AssignmentSpec spec = load_assignment(o.paths[0]);
  AssignmentBank from = load_assignment_bank(spec);
  Bank out;
  out.errors = from.errors;
  if (from.problems.size() != spec.problems.size()) return out;
  out.problems = student_problems(spec, from.problems, o.student);
  return out;
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
  nlohmann::json solutions = nlohmann::json::array();
  std::vector<Solution> worked;
  worked.reserve(bank.problems.size());
  for (const auto& p : bank.problems) {
    NumberFormat numbers = number_format_for(p, o.precision);
    try {
      if (o.format == "json") {
        nlohmann::json s = {{"id", p.id}, {"kind", p.kind}, {"answer", p.task->answer()}};
        if (auto level = p.task->level()) s["level"] = *level;
        // An assignment's problem as the student reads it: their numbers in the text.
        if (o.assignment) {
          s["title"] = p.title;
          s["statement"] = p.statement;
          if (!p.values.empty()) s["parameters"] = p.values;
        }
        if (o.steps) {
          nlohmann::json all = nlohmann::json::array();
          for (const auto& m : make_solution(p, o.method, numbers).methods) {
            for (auto& part : parts_json(m.parts, numbers)) all.push_back(part);
          }
          s["derivations"] = all;
        }
        solutions.push_back(std::move(s));
      } else {
        worked.push_back(make_solution(p, o.method, numbers));
      }
    } catch (const Error& e) {
      Diagnostic d = e.diagnostic();
      if (d.file.empty()) d.file = p.file;
      if (d.path.empty()) d.path = p.path;
      fmt::print(stderr, "{}\n", format_diagnostic(d));
      bank.errors.push_back(d);
    }
  }
  if (o.format == "json") {
    nlohmann::json out = {{"solutions", solutions}};
    if (!bank.errors.empty()) {
      nlohmann::json errors = nlohmann::json::array();
      for (const auto& e : bank.errors) errors.push_back(diagnostic_json(e));
      out["errors"] = errors;
    }
    std::cout << out.dump(2) << "\n";
  } else {
    std::vector<const Solution*> list;
    for (const auto& w : worked) list.push_back(&w);
    std::cout << render_document(*parse_format(o.format), list);
  }
  return bank.errors.empty() ? kExitOk : kExitBadInput;
}

}  // namespace

Runner setup_solve(CLI::App& sub) {
  auto o = std::make_shared<SolveOptions>();
  sub.add_option("paths", o->paths, "problem files or folders, or one assignment file")->required();
  sub.add_option("--format", o->format,
                 "json (answers; with --steps, the steps too), or a worked solution as md, html "
                 "or txt")
      ->check(CLI::IsMember({"json", "txt", "md", "html"}));
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
