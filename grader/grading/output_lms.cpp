// The pieces of a platform's results document: a submission's summary, and each problem's
// name and feedback as a test.
#include <fmt/format.h>

#include "grading/outputs.h"

namespace raygrade {

std::string result_test_name(const GradeResult& r) {
  return r.title.empty() ? r.problem_id : fmt::format("{}: {}", r.problem_id, r.title);
}

std::string joined_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

std::string grade_summary(const SubmissionGrade& g) {
  if (!g.gradable) {
    return fmt::format("This submission could not be graded: {}",
                       g.fault ? format_diagnostic(*g.fault) : "unreadable");
  }
  std::string s =
      fmt::format("{} / {} points on {} problems; {} named mistakes.", format_points(g.score),
                  format_points(g.max_score), g.results.size(), g.mistakes());
  for (const auto& d : g.findings) s += "\n" + format_diagnostic(d);
  return s;
}

}  // namespace raygrade
