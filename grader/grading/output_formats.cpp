// raygrade's own grade formats: each format's name is written here once. The platforms' are
// theirs (assignments/platforms/).
#include "grading/outputs.h"

namespace raygrade {
namespace {

std::string text_format(const SubmissionGrade& g, double /*seconds*/) { return text_report(g); }

std::string json_format(const SubmissionGrade& g, double /*seconds*/) {
  return json_text(submission_json(g)) + "\n";
}

std::string html_format(const SubmissionGrade& g, double /*seconds*/) { return feedback_html(g); }

}  // namespace

const std::vector<GradeFormat>& own_grade_formats() {
  static const std::vector<GradeFormat> table = {
      {"text", "for a terminal: each problem's score, parts and feedback", ".txt",
       GradeLayout::kDocument, false, false, &text_format},
      {"json", "raygrade's own: every part, mistake and note as data", ".json",
       GradeLayout::kJsonArray, false, false, &json_format},
      {"csv", "a gradebook: a row per student, a column per problem, then total, max and status",
       ".csv", GradeLayout::kGradebook, false, false, nullptr},
      {"html", "a self-contained feedback page per student", ".html", GradeLayout::kDocument, true,
       false, &html_format},
  };
  return table;
}

}  // namespace raygrade
