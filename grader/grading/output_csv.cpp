// The CSV gradebook: one row per submission, one column per problem.
#include <fmt/format.h>

#include <map>

#include "core/escape.h"
#include "grading/outputs.h"

namespace raygrade {

std::string gradebook_csv_header(const std::vector<std::string>& problem_ids) {
  std::string s = "student,id,email,file";
  for (const auto& id : problem_ids) s += "," + csv_cell(id);
  return s + ",total,max,status\n";
}

std::string gradebook_csv_row(const SubmissionGrade& g,
                              const std::vector<std::string>& problem_ids) {
  std::string s = csv_cell(g.student) + "," + csv_cell(g.identity.id) + "," +
                  csv_cell(g.identity.email) + "," + csv_cell(g.file);
  std::map<std::string, const GradeResult*, std::less<>> by_id;
  for (const auto& r : g.results) by_id[r.problem_id] = &r;
  for (const auto& id : problem_ids) {
    auto it = by_id.find(id);
    s += ",";
    if (it != by_id.end() && it->second->answered) s += format_points(it->second->score);
  }
  if (g.gradable) {
    s += fmt::format(",{},{},graded\n", format_points(g.score), format_points(g.max_score));
  } else {
    s += ",,," + csv_cell("rejected: " + (g.fault ? format_diagnostic(*g.fault) : "")) + "\n";
  }
  return s;
}

std::string gradebook_csv(const std::vector<SubmissionGrade>& grades,
                          const std::vector<std::string>& problem_ids) {
  std::string s = gradebook_csv_header(problem_ids);
  for (const auto& g : grades) s += gradebook_csv_row(g, problem_ids);
  return s;
}

}  // namespace raygrade
