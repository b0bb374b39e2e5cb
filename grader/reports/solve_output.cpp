// The output of raygrade solve.
#include "reports/solve_output.h"

#include "json/numbers.h"
#include "reports/json_report.h"
#include "reports/render.h"

namespace raygrade {

std::string solve_output(Bank& bank, const SolveOutputOptions& o,
                         std::vector<Diagnostic>& failures) {
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
      failures.push_back(d);
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
    return without_negative_zeros(std::move(out)).dump(2) + "\n";
  }
  std::vector<const Solution*> list;
  list.reserve(worked.size());
  for (const auto& w : worked) list.push_back(&w);
  return render_document(*parse_format(o.format), list);
}

}  // namespace raygrade
