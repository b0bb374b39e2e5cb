// The forms graded submissions are written in: text for a terminal, raygrade's own JSON, a CSV
// gradebook and an HTML feedback page, and the pieces of a platform's results document.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "grading/submission.h"

namespace raygrade {

// Points as people read them: 2, 1.5, 0.33.
std::string format_points(double p);

// The feedback of one graded problem as plain lines (parts, then mistakes, then notes).
std::vector<std::string> feedback_lines(const GradeResult& r);

std::string text_report(const SubmissionGrade& g);
nlohmann::json submission_json(const SubmissionGrade& g);
// JSON as text (nlohmann's dump, `indent` spaces, ill-formed UTF-8 replaced) with the C1
// controls and DEL written as \u escapes too, so that it is safe to show on a terminal.
std::string json_text(const nlohmann::json& j, int indent = 2);

// {"submissions": [...]} written to `out` one submission at a time as it is graded, so that a
// batch of any size is never held whole; the text is what one json_text of it would be.
class JsonArrayStream {
 public:
  explicit JsonArrayStream(std::ostream& out) : out_(out) {}
  // `item`: json_text(submission_json(g)) of one graded submission.
  void add(const std::string& item);
  void finish();

 private:
  std::ostream& out_;
  bool first_ = true;
};

// The pieces of a platform's results document (platforms/: its results format): a
// submission's summary (its points and named mistakes, or why it could not be graded, and its
// findings), a problem's name as a test ("id: title"), and lines joined, each ended by '\n'.
std::string grade_summary(const SubmissionGrade& g);
std::string result_test_name(const GradeResult& r);
std::string joined_lines(const std::vector<std::string>& lines);

// One row per submission, one column per problem (its points), then the total; every cell
// escaped with csv_cell.
std::string gradebook_csv(const std::vector<SubmissionGrade>& grades,
                          const std::vector<std::string>& problem_ids);
// The same gradebook a line at a time, for a batch written as it is graded.
std::string gradebook_csv_header(const std::vector<std::string>& problem_ids);
std::string gradebook_csv_row(const SubmissionGrade& g,
                              const std::vector<std::string>& problem_ids);

// A self-contained HTML feedback page for one student; all text escaped.
std::string feedback_html(const SubmissionGrade& g);

// How the documents of a grade format go out.
enum class GradeLayout {
  kDocument,   // one document per submission: standard output for one, one file each in --out
  kJsonArray,  // json: {"submissions": [...]} on standard output, one file each in --out
  kGradebook,  // csv: a header, then a row per submission; in --out, one gradebook.csv
  // a platform's gradebook layout (platforms/platform.h), a row per roster
  // student (needs --roster); in --out, one gradebook.csv
  kClassGradebook,
};

// One row of the table of grade formats (`raygrade grade --format NAME`).
struct GradeFormat {
  std::string_view name;
  std::string_view summary;    // for --help and the docs
  std::string_view extension;  // of the files written in --out: ".txt", ".json", ".html"
  GradeLayout layout;
  bool needs_out;     // several submissions need --out (one file each), not standard output
  bool results_file;  // an LMS's: one submission in --out is written as results.json
  // A submission's document; `seconds` is the time it took to grade. Null for a gradebook.
  std::string (*render)(const SubmissionGrade& g, double seconds);
};

// A student's page among the HTML feedback pages of a batch, and the index that links them
// all with each one's score (index.html in --out).
struct FeedbackPage {
  std::string file;  // the page's name in the folder
  std::string student;
  std::string id;
  bool gradable = true;
  double score = 0;
  double max_score = 0;
};
std::string feedback_index_html(const std::vector<FeedbackPage>& pages);

// raygrade's own grade formats: text, json, csv, html. The table of every grade format, these
// and the platforms' (their results documents and gradebook layouts), is grade_formats()
// (assignments/platforms/platforms.h).
const std::vector<GradeFormat>& own_grade_formats();

}  // namespace raygrade
