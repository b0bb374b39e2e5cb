// Submissions: a student's answers to the problems of an assignment, read from a JSON file
// (docs/submission-format.md) and graded with every problem prepared once.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "grading/grade.h"
#include "json/source.h"
#include "problems/problem.h"

namespace raygrade {

struct SubmissionGrade {
  std::string file;
  std::string student;  // the submission's "student", or the file's name without .json
  bool gradable = true;
  std::optional<Diagnostic> fault;  // why it could not be graded (file, JSON path, fault)
  std::vector<GradeResult> results;
  double score = 0;
  double max_score = 0;
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

  SubmissionGrade grade_file(const std::string& path) const;
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
// "skipped"). A path named in `paths` itself is followed wherever it leads.
std::vector<std::string> submission_files(const std::vector<std::string>& paths,
                                          std::vector<Diagnostic>& errors);

}  // namespace raygrade
