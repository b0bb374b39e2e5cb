// The checks of one problem by itself (stated answer, boundaries, conditioning, self-tests), as
// the generator and assignment variants run them.
#include "check/problem_checks.h"
#include "check/self_tests.h"

namespace raygrade {

std::vector<Diagnostic> problem_findings(const Problem& p, const NumberLiterals& literals) {
  nlohmann::json reference = p.task->answer();
  std::vector<Diagnostic> out = check_expected(p, reference, literals);
  BoundaryProbe probe = probe_boundaries(p);
  out.insert(out.end(), probe.diagnostics.begin(), probe.diagnostics.end());
  auto c = check_conditioning(p, reference, literals, probe.exact_boundary);
  out.insert(out.end(), c.begin(), c.end());
  auto t = run_self_tests(p, reference);
  out.insert(out.end(), t.begin(), t.end());
  return out;
}

}  // namespace raygrade
