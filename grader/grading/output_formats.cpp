// The table of grade formats: each format's name is written here once.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "grading/outputs.h"

namespace raygrade {
namespace {

std::string text_format(const SubmissionGrade& g, double /*seconds*/) { return text_report(g); }

std::string json_format(const SubmissionGrade& g, double /*seconds*/) {
  return json_text(submission_json(g)) + "\n";
}

std::string gradescope_format(const SubmissionGrade& g, double seconds) {
  return json_text(gradescope_json(g, seconds)) + "\n";
}

std::string prairielearn_format(const SubmissionGrade& g, double /*seconds*/) {
  return json_text(prairielearn_json(g)) + "\n";
}

std::string html_format(const SubmissionGrade& g, double /*seconds*/) { return feedback_html(g); }

}  // namespace

const std::vector<GradeFormat>& grade_formats() {
  static const std::vector<GradeFormat> table = {
      {"text", "for a terminal: each problem's score, parts and feedback", ".txt",
       GradeLayout::kDocument, false, false, &text_format},
      {"json", "raygrade's own: every part, mistake and note as data", ".json",
       GradeLayout::kJsonArray, false, false, &json_format},
      {"gradescope", "Gradescope's autograder results.json", ".json", GradeLayout::kDocument, true,
       true, &gradescope_format},
      {"prairielearn", "PrairieLearn's external grader results.json", ".json",
       GradeLayout::kDocument, true, true, &prairielearn_format},
      {"csv", "a gradebook: a row per student, a column per problem, then total, max and status",
       ".csv", GradeLayout::kGradebook, false, false, nullptr},
      {"csv-canvas", "with --roster: Canvas's gradebook import (a Points Possible row)", ".csv",
       GradeLayout::kClassGradebook, false, false, nullptr},
      {"csv-moodle", "with --roster: Moodle's grade import from CSV, matched by email", ".csv",
       GradeLayout::kClassGradebook, false, false, nullptr},
      {"csv-blackboard", "with --roster: Blackboard's offline grade upload", ".csv",
       GradeLayout::kClassGradebook, false, false, nullptr},
      {"html", "a self-contained feedback page per student", ".html", GradeLayout::kDocument, true,
       false, &html_format},
  };
  return table;
}

const GradeFormat* find_grade_format(std::string_view name) {
  for (const auto& f : grade_formats()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::string grade_format_names() {
  std::vector<std::string_view> names;
  for (const auto& f : grade_formats()) names.push_back(f.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace raygrade
