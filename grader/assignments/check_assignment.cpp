// The assignment check.
#include "assignments/check_assignment.h"

#include <fmt/format.h>

#include <map>
#include <set>

#include "assignments/assignment.h"
#include "assignments/variants.h"
#include "check/problem_checks.h"
#include "sampling/prng.h"

namespace raygrade {
namespace {

std::string describe_values(const ParameterValues& values) {
  std::string s;
  for (const auto& [name, value] : values)
    s += fmt::format("{}{} = {}", s.empty() ? "" : ", ", name, value.dump());
  return s;
}

// kCheckDraws draws of a problem's parameters, each checked as a student's variant would be.
// A draw whose stated answer is wrong is the bank's error, reported draw by draw (a few, then
// a count): the variants would silently skip it. The other rejections (degenerate geometry,
// numbers not nice) are counted by reason in a note, and a parameter most of whose values are
// rejected is a warning: the variety of the numbers collapses.
void check_draws(const AssignmentSpec& spec, const Problem& base, std::vector<Diagnostic>& out) {
  Prng rng(variant_seed(spec.id, spec.seed, "raygrade check", base.id));
  std::map<std::string, int> rejected;  // by code
  // The distinct draws whose stated answer is wrong, each with why, and how many draws were.
  std::map<std::string, std::string> wrong;
  int wrong_draws = 0;
  std::map<std::string, std::set<std::string>> drawn, kept;  // each parameter's values
  for (int k = 0; k < kCheckDraws; ++k) {
    ParameterValues values = base.parameters->draw(rng);
    for (const auto& [name, value] : values) drawn[name].insert(value.dump());
    std::vector<Diagnostic> findings;
    try {
      findings = variant_findings(read_problem_variant(base, values), spec.allow_degenerate);
    } catch (const Error& e) {
      findings.push_back(e.diagnostic());
    }
    std::string code, why;
    for (const auto& d : findings) {
      if (d.severity == Severity::kNote) continue;
      if (code.empty() || d.code == "wrong-expected") code = d.code, why = d.message;
    }
    if (code.empty()) {
      for (const auto& [name, value] : values) kept[name].insert(value.dump());
      continue;
    }
    ++rejected[code];
    if (code == "wrong-expected") {
      ++wrong_draws;
      wrong.emplace(describe_values(values), why);
    }
  }
  Diagnostic d = problem_diagnostic(base, "/expected", Severity::kError, "", "wrong-expected");
  std::size_t named = 0;
  for (const auto& [values, why] : wrong) {
    if (++named > kReportedWrongDraws) break;
    d.message = fmt::format("the stated answer is wrong for {} ({})", values, why);
    out.push_back(d);
  }
  if (wrong.size() > kReportedWrongDraws) {
    d.message = fmt::format("the stated answer is wrong for {} more values of the parameters",
                            wrong.size() - kReportedWrongDraws);
    out.push_back(d);
  }
  int total = 0;
  std::string reasons;
  for (const auto& [code, n] : rejected) {
    total += n;
    reasons += fmt::format("{}{} {}", reasons.empty() ? "" : ", ", n, code);
  }
  out.push_back(problem_diagnostic(
      base, "/parameters", Severity::kNote,
      total == 0 ? fmt::format("all {} draws checked are usable variants", kCheckDraws)
      : wrong_draws > 0
          ? fmt::format("{} of {} draws checked are rejected ({}); those with a wrong stated "
                        "answer would be drawn again without a word",
                        total, kCheckDraws, reasons)
          : fmt::format("{} of {} draws checked are rejected and drawn again ({})", total,
                        kCheckDraws, reasons),
      "draws"));
  for (const auto& [name, values] : drawn) {
    std::size_t survive = kept[name].size();
    if (values.size() < 2 || 2 * survive >= values.size()) continue;
    out.push_back(problem_diagnostic(
        base, "/parameters/" + name, Severity::kWarning,
        fmt::format("only {} of the {} values of {} drawn survive the checks: the students' "
                    "numbers are less varied than the parameters say",
                    survive, values.size(), name),
        "collapsed-parameter"));
  }
}

}  // namespace

CheckReport check_assignment(const std::string& path) {
  CheckReport report;
  report.files.push_back(path);
  AssignmentSpec spec;
  std::vector<Diagnostic> faults;  // every fault of the file, not only the first
  try {
    spec = read_assignment(path, faults);
  } catch (const Error& e) {
    faults.push_back(e.diagnostic());
    report.unreadable = e.diagnostic().code == "unreadable";
  }
  if (!faults.empty()) {
    ProblemResult r;
    r.name = r.file = path;
    r.diagnostics = faults;
    report.problems.push_back(r);
    // With no bank to read, there is nothing more to check.
    if (spec.bank.empty()) return report;
  }
  AssignmentBank bank = load_assignment_bank(spec);
  for (const auto& d : bank.errors) {
    ProblemResult r;
    r.name = d.file.empty() ? path : fmt::format("{}{}", d.file, d.path);
    r.file = d.file;
    r.path = d.path;
    r.diagnostics.push_back(d);
    report.problems.push_back(r);
  }
  for (const Problem* p : bank.problems) {
    ProblemResult r;
    r.name = r.id = p->id;
    r.kind = p->kind;
    r.file = p->file;
    r.path = p->path;
    r.solved = true;
    if (spec.per_student && p->parameters && !p->parameters->empty()) {
      check_draws(spec, *p, r.diagnostics);
      for (int s = 1; s <= kSampleStudents; ++s) {
        std::string student = fmt::format("sample-{:03}", s);
        try {
          (void)draw_variant(*p, variant_seed(spec.id, spec.seed, student, p->id),
                             spec.allow_degenerate);
        } catch (const Error& e) {
          Diagnostic d = e.diagnostic();
          d.message = fmt::format("{} (for {})", d.message, student);
          r.diagnostics.push_back(d);
          break;  // the same fault for the other samples says nothing more
        }
      }
    }
    report.problems.push_back(r);
  }
  return report;
}

}  // namespace raygrade
