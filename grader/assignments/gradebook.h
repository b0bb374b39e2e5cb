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

// The columns of Moodle's grading worksheet that raygrade reads, and each row's "Maximum Grade"
// (Moodle writes it as "5.00", or "5,00" in a language with a decimal comma). Throws Error
// naming `file` and the row when a column Moodle needs is missing, a row is cut short, or a
// maximum is not a positive number of points (an assignment graded on a scale).
struct MoodleWorksheet {
  MoodleWorksheet(const std::vector<std::vector<std::string>>& rows, const std::string& file);
  std::size_t identifier = 0, full_name = 0, email = 0, grade = 0, maximum = 0;
  std::vector<double> maxima;  // per row; the header's is 0
};

// A student's feedback page: its file name and text, and the roster id it was written for.
struct StudentPage {
  std::string student_id;
  std::string file;
  std::string text;
};

// Moodle's "Upload multiple feedback files in a zip": each page in the folder Moodle's importer
// reads, "<full name>_<participant number>_assignfeedback_file", the participant number taken
// from the worksheet row whose "Email address" is the page's student's on the roster. A page
// of no worksheet row is left out and listed in `notes`.
std::vector<ZipEntry> moodle_feedback_files(const std::vector<std::vector<std::string>>& rows,
                                            const std::string& file,
                                            const std::vector<StudentIdentity>& roster,
                                            const std::vector<StudentPage>& pages,
                                            std::vector<std::string>& notes);

// What a platform's importer would make of the grade column of platform_csv, before anything is
// graded: `error` when it would misread it (the column is then refused), `warning` when it reads
// it but not as an instructor may expect; both empty when it reads it as meant.
// - csv-canvas (Canvas's gradebook importer, instructure/canvas-lms): a column whose title
//   contains "Current Score", "Current Points", "Current Grade", "Final Score", "Final Points",
//   "Final Grade", "Override Score", "Override Grade" or "Override Status" (case-sensitive,
//   app/models/gradebook_importer.rb's NON_ASSIGNMENT_COLUMN_HEADERS) is dropped; a title ending
//   in white space and "(digits)" is read as "Title (assignment id)" (Assignment.title_and_id),
//   so without `column_id` it would grade another assignment. `column_id` must be digits.
// - csv-blackboard (Blackboard's "Uploading External Grade Center Items"): a column is matched by
//   the Column ID after '|' in its header, so a title may hold no '|'; without `column_id` the
//   upload adds a new text column with 0 points possible (a warning). `column_id` must be digits.
struct ColumnCheck {
  std::string error;
  std::string warning;
};
ColumnCheck check_platform_column(std::string_view layout, const std::string& title,
                                  const std::string& column_id);

class RosterGradebook {
 public:
  RosterGradebook(const std::vector<StudentIdentity>& roster,
                  const std::vector<std::string>& problem_ids, PickPolicy pick);

  // Takes one graded (or rejected) submission. False when it belongs to no roster student
  // (rejected before it could be tied to one); it then has no row.
  bool add(const SubmissionGrade& g);

  // Each roster student's Canvas user ID (the roster's "canvas_id" column, "" where none), for
  // the ID column of the Canvas layout.
  void set_canvas_ids(std::vector<std::string> ids) { canvas_ids_ = std::move(ids); }

  // One line per student with several submissions: how many, which one counts, and why.
  std::vector<std::string> choices() const;

  // The header and one row per roster student, in roster order: raygrade's own columns (a
  // column per problem, total, max, status).
  std::string csv() const;

  // The same class in a platform's import layout ("csv-canvas", "csv-moodle",
  // "csv-blackboard"): the total as one grade column named `title`, out of the assignment's
  // points (docs/assignments.md says how each platform matches its students). `column_id` is the
  // platform's id of the grade column, when known: Canvas's assignment id, written "Title (id)";
  // Blackboard's Column ID, written "Title [Total Pts: N Score] |id". Blackboard's fields are
  // each in quotation marks, as its upload wants.
  std::string platform_csv(std::string_view layout, const std::string& title,
                           const std::string& column_id = "") const;

  // Moodle's offline grading worksheet as downloaded from the assignment (`rows`, read from
  // `file`), each row's "Grade" set to the total of the roster student whose email is its
  // "Email address", out of the row's "Maximum Grade" (scaled from the assignment's points
  // when they differ, and said once in `notes`); every other cell as downloaded (a status can name
  // another student, so "Feedback comments" is not written), since Moodle matches a row by its
  // "Identifier" and skips one whose "Last modified (grade)" is older than its own record. A row of
  // no roster student stays as downloaded, and is listed in `notes`, as is each roster student
  // without a row. Throws Error naming the file when a column Moodle needs is missing or a row is
  // cut short.
  std::string moodle_worksheet(const std::vector<std::vector<std::string>>& rows,
                               const std::string& file, std::vector<std::string>& notes) const;

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
  std::vector<std::string> canvas_ids_;      // per roster student, or empty
};

}  // namespace raygrade
