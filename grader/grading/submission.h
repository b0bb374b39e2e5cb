// Submissions: a student's answers to the problems of an assignment, read from a JSON file
// (docs/submission-format.md) and graded with every problem prepared once.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "grading/grade.h"
#include "json/cursor.h"
#include "json/source.h"
#include "problems/problem.h"

namespace raygrade {

// Who a submission is from: its "student" ({"name", "id", "email"}, or a name alone).
struct StudentIdentity {
  std::string name;
  std::string id;
  std::string email;

  bool empty() const { return name.empty() && id.empty() && email.empty(); }
  // The first of name, id and email given: how reports name the student.
  std::string display() const;
};

// How a submission that names no student is named: its file's name without the folder and the
// extension, as text (a byte that is not UTF-8, Latin-1's "jos\xe9.json", written \xE9).
std::string student_of_file(const std::string& path);

// The "student" of a submission's root object; nothing when it has none. Throws Error at
// /student when it is neither a string nor an object of name, id and email strings.
std::optional<StudentIdentity> read_student(const Cursor& root);

struct SubmissionGrade {
  std::string file;
  std::string student;       // the submission's "student", or the file's name without .json
  StudentIdentity identity;  // as the submission gives it (empty when it names nobody)
  // Who a submission rejected before it could be tied to a student says it is from (empty
  // when it says nothing readable): a gradebook shows the rejection on that student's row.
  StudentIdentity claimed;
  bool gradable = true;
  std::optional<Diagnostic> fault;  // why it could not be graded (file, JSON path, fault)
  std::vector<GradeResult> results;
  // What was read but could not be graded, each a warning with its JSON path: an answer to a
  // problem the assignment does not have ("did you mean ...?"). The other answers are graded.
  std::vector<Diagnostic> findings;
  double score = 0;
  double max_score = 0;
  // When it was handed in: the submission's own "submitted" time (seconds since 1970 UTC) when
  // it gives one, and the file's modification time. They order a student's submissions.
  std::optional<std::int64_t> submitted;
  std::int64_t file_time = 0;
  double fraction() const { return max_score > 0 ? score / max_score : 0; }
  std::size_t mistakes() const;
};

struct AssignmentOptions {
  // Grade only the problems a submission answers (sample submissions answer a few problems
  // of a large bank); otherwise every problem counts and unanswered ones earn nothing.
  bool answered_only = false;
};

// The problems of an assignment, each prepared for grading.
class Assignment {
 public:
  // Problems whose tolerance or points are faulty are left out and reported in errors().
  explicit Assignment(const std::vector<Problem>& problems, AssignmentOptions options = {});

  // `seen`: the file submission_files listed at `path`; another file found there is refused.
  SubmissionGrade grade_file(const std::string& path,
                             std::optional<FileIdentity> seen = std::nullopt) const;
  SubmissionGrade grade(const std::shared_ptr<const SourceFile>& file) const;

  const std::vector<Grader>& graders() const { return graders_; }
  const std::vector<Diagnostic>& errors() const { return errors_; }

 private:
  std::vector<Grader> graders_;
  std::map<std::string, std::size_t, std::less<>> by_id_;
  std::vector<Diagnostic> errors_;
  AssignmentOptions options_;
};

// The .json files among `paths` (folders searched recursively, in sorted order). Reported in
// `errors`, and left out: paths that do not exist, folders that cannot be read (code
// "unreadable"), and entries that are not regular files (FIFOs, devices, sockets), dangling
// symbolic links, links to folders and links leading outside the folder walked (code
// "skipped"). A path named in `paths` itself is followed wherever it leads. Given `seen`, it
// receives the identity of each file listed (to pass to grade_file), so that a folder on its
// path replaced by a link after the listing leads to a file that is refused.
std::vector<std::string> submission_files(const std::vector<std::string>& paths,
                                          std::vector<Diagnostic>& errors,
                                          std::vector<std::optional<FileIdentity>>* seen = nullptr);

}  // namespace raygrade
