// The assignment check.
#include "assignments/check_assignment.h"

#include <fmt/format.h>

#include "assignments/assignment.h"
#include "assignments/variants.h"

namespace raygrade {

CheckReport check_assignment(const std::string& path) {
  CheckReport report;
  report.files.push_back(path);
  AssignmentSpec spec;
  try {
    spec = load_assignment(path);
  } catch (const Error& e) {
    ProblemResult r;
    r.name = r.file = path;
    r.diagnostics.push_back(e.diagnostic());
    report.problems.push_back(r);
    report.unreadable = e.diagnostic().code == "unreadable";
    return report;
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
    if (spec.per_student && p->parameters) {
      for (int s = 1; s <= kSampleStudents; ++s) {
        std::string student = fmt::format("sample-{:03}", s);
        try {
          (void)draw_variant(*p, variant_seed(spec.id, spec.seed, student, p->id));
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
