// raygrade solve: the reference answer of every problem, and optionally its worked steps.
#include <fmt/format.h>

#include <iostream>

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
};

int run_solve(const SolveOptions& o) {
  Bank bank = load_bank(o.paths);
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
  sub.add_option("paths", o->paths, "problem files or folders")->required();
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
  return [o] { return run_solve(*o); };
}

}  // namespace raygrade::cli
