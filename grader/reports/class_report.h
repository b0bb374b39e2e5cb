// The class report (docs/report.md): per problem and part the scores, the named mistakes, the
// wrong answers grouped by the single change of the derivation that explains them, the
// fairness of variants and each problem's discrimination; as JSON, and as an HTML page built
// from that JSON alone.
#pragma once

#include <memory>
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
// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
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

// The same report built one student at a time, keeping of each only what the report shows:
// the scores and parts' statuses, the mistakes' ids, which variant, and the text of an answer
// below full marks. A class of any size costs a few hundred bytes per student, not the
// students' graded results (docs/report.md, "Speed").
class ClassReportBuilder {
 public:
  // `bases`: the bank's problems in the report's order. Given, each variant is kept as its
  // numbers and read again from its base when its wrong answers are searched; null, the
  // answers' variants are kept as pointers and must outlive the builder.
  ClassReportBuilder(std::string title, std::vector<std::string> problem_ids,
                     std::vector<std::string> problem_titles,
                     std::vector<const Problem*> bases = {});
  ~ClassReportBuilder();
  ClassReportBuilder(const ClassReportBuilder&) = delete;
  ClassReportBuilder& operator=(const ClassReportBuilder&) = delete;

  // A student, one answer per problem; a student of the same id added before is replaced,
  // in its place.
  void add(const ClassStudent& student);
  void set_no_submission(std::vector<AbsentStudent> absent);
  std::size_t students() const;
  // What the builder holds, in bytes (its rows, strings and tables; the allocator's own
  // overhead aside).
  std::size_t retained_bytes() const;
  nlohmann::json json(unsigned jobs) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The page: every number on it is a number of `report`, in an element whose data-j attribute
// is that number's JSON pointer.
std::string class_report_html(const nlohmann::json& report);

}  // namespace raygrade
