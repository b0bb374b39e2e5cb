// Gradescope's and PrairieLearn's results.json.
#include <fmt/format.h>

#include "grading/outputs.h"

namespace raygrade {
namespace {

std::string test_name(const GradeResult& r) {
  return r.title.empty() ? r.problem_id : fmt::format("{}: {}", r.problem_id, r.title);
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

std::string summary(const SubmissionGrade& g) {
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

}  // namespace

nlohmann::json gradescope_json(const SubmissionGrade& g, double execution_seconds) {
  nlohmann::json tests = nlohmann::json::array();
  for (const GradeResult& r : g.results) {
    std::string output = joined(feedback_lines(r));
    tests.push_back({{"name", test_name(r)},
                     {"score", r.score},
                     {"max_score", r.max_score},
                     {"status", r.score >= r.max_score ? "passed" : "failed"},
                     {"output", output},
                     {"output_format", "text"},
                     {"visibility", "visible"}});
  }
  return {{"score", g.gradable ? g.score : 0.0},
          {"execution_time", execution_seconds},
          {"output", summary(g)},
          {"output_format", "text"},
          {"visibility", "visible"},
          {"tests", tests}};
}

nlohmann::json prairielearn_json(const SubmissionGrade& g) {
  nlohmann::json tests = nlohmann::json::array();
  for (const auto& r : g.results) {
    auto lines = feedback_lines(r);
    tests.push_back({{"name", test_name(r)},
                     {"description", r.problem_id},
                     {"points", r.score},
                     {"max_points", r.max_score},
                     {"message", r.score >= r.max_score ? "Right."
                                 : lines.empty()        ? ""
                                                        : lines.front()},
                     {"output", joined(lines)}});
  }
  return {{"gradable", g.gradable},
          {"score", g.gradable ? std::clamp(g.fraction(), 0.0, 1.0) : 0.0},
          {"message", summary(g)},
          {"output", g.gradable ? "" : summary(g)},
          {"tests", tests}};
}

}  // namespace raygrade
