// The class report (docs/report.md): per problem and part the scores, the named mistakes, the
// wrong answers grouped by the single change of the derivation that explains them, the
// fairness of variants and each problem's discrimination; as JSON, and as an HTML page built
// from that JSON alone.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grading/result.h"
#include "problems/problem.h"

namespace raygrade {

// A variant value is flagged as harder when its students' mean fraction is this much below the
// other values' (a quarter of the problem's points), with at least kMinFairnessStudents behind
// it: a difference a class of a few dozen shows by chance far less often than one time in ten.
constexpr double kFairnessGap = 0.25;
constexpr int kMinFairnessStudents = 5;
// Bars of a score histogram: tenths of the problem's (or part's) points.
constexpr int kHistogramBins = 10;

// One student's graded answer to one problem.
struct ClassAnswer {
  GradeResult result;
  nlohmann::json answer;             // as submitted; null when unanswered
  const Problem* variant = nullptr;  // the problem with the student's numbers
};

struct ClassStudent {
  std::string id;    // the roster id, else how the submission names the student
  std::string name;  // may be empty
  std::string page;  // the feedback page, relative to the report's folder ("" for none)
  std::vector<ClassAnswer> answers;  // one per problem, in the problems' order
};

// A roster student who handed in nothing.
struct AbsentStudent {
  std::string id;
  std::string name;  // may be empty
};

struct ClassInput {
  std::string title;
  std::vector<std::string> problem_ids;
  std::vector<std::string> problem_titles;
  std::vector<ClassStudent> students;
  // Listed apart, in the roster's order, and left out of every number of the problems: a
  // missing submission says nothing about what a class got wrong.
  std::vector<AbsentStudent> no_submission;
};

// The report as JSON (the layout of docs/report.md). `jobs` threads search for changes.
nlohmann::json class_report_json(const ClassInput& input, unsigned jobs);

// The page: every number on it is a number of `report`, in an element whose data-j attribute
// is that number's JSON pointer.
std::string class_report_html(const nlohmann::json& report);

}  // namespace raygrade
