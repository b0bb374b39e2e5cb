// The gradebook of a class: one row per roster student, in roster order, whatever was handed
// in: graded, no submission, or rejected (and why), with 0 for what is missing. A student with
// several submissions is counted once, by a documented choice (docs/assignments.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assignments/roster.h"
#include "core/zip.h"
#include "grading/submission.h"

namespace raygrade {

// Which of a student's several graded submissions counts: the latest (by the submission's own
// "submitted" time, then the file's modification time, then its name), the best score, or the
// first.
enum class PickPolicy { kLatest, kBest, kFirst };
std::optional<PickPolicy> parse_pick_policy(std::string_view name);

// A student's feedback page: its file name and text, and the roster id it was written for.
struct StudentPage {
  std::string student_id;
  std::string file;
  std::string text;
};

// A platform's own gradebook file as downloaded (PlatformWorksheet): its rows, and the file they
// were read from, for messages.
struct Worksheet {
  std::string file;
  std::vector<std::vector<std::string>> rows;
};

// What a platform's importer would make of the grade column of its gradebook layout, before
// anything is graded: `error` when it would misread it (the column is then refused), `warning`
// when it reads it but not as an instructor may expect; both empty when it reads it as meant.
struct ColumnCheck {
  std::string error;
  std::string warning;
};

// Whether `id` is a platform's id of a grade column: digits, at least one.
bool is_column_id(std::string_view id);

// One roster student's line of a platform's gradebook layout.
struct ClassRow {
  StudentIdentity student;
  // The student's cell of the roster's column of the platform's user ids (PlatformEntry::
  // roster_column), "" where none.
  std::string platform_id;
  double score = 0;  // of the submission that counts; 0 without one
};

// The class as a platform's gradebook layout writes it (GradebookLayout::write): a row per roster
// student, in roster order, and the assignment's points when any submission was graded.
struct ClassRows {
  std::vector<ClassRow> rows;
  std::optional<double> points;
};

class RosterGradebook {
 public:
  RosterGradebook(const std::vector<StudentIdentity>& roster,
                  const std::vector<std::string>& problem_ids, PickPolicy pick);

  // Takes one graded (or rejected) submission. False when it belongs to no roster student
  // (rejected before it could be tied to one); it then has no row.
  bool add(const SubmissionGrade& g);

  // Each roster student's cell of the roster's column of a platform's user ids ("" where none),
  // for ClassRow::platform_id.
  void set_platform_ids(std::vector<std::string> ids) { platform_ids_ = std::move(ids); }

  // One line per student with several submissions: how many, which one counts, and why.
  std::vector<std::string> choices() const;

  // The header and one row per roster student, in roster order: raygrade's own columns (a
  // column per problem, total, max, status).
  std::string csv() const;

  // The same class for a platform's gradebook layout (platforms/platform.h): each roster
  // student's score, the one submission counted as csv() counts it.
  ClassRows class_rows() const;

 private:
  // What a row needs of one submission.
  struct Handed {
    std::string file;
    std::optional<std::int64_t> submitted;
    std::int64_t file_time = 0;
    bool gradable = false;
    std::string fault;
    double score = 0;
    double max_score = 0;
    std::vector<double> points;  // per problem id, 0 when unanswered
  };
  const Handed* chosen(const std::vector<Handed>& handed) const;
  std::optional<double> max_score() const;
  std::string status(std::size_t student) const;

  const std::vector<StudentIdentity>& roster_;
  std::vector<std::string> problem_ids_;
  PickPolicy pick_;
  std::vector<std::vector<Handed>> handed_;  // per roster student, in the order added
  std::vector<std::string> platform_ids_;    // per roster student, or empty
};

}  // namespace raygrade
