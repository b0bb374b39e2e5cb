// The assignments a server offers: the assignment files of one folder, each with its bank read
// once, graded the way `raygrade grade --assignment` grades (assignments/grading.h).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "assignments/assignment.h"
#include "assignments/grading.h"
#include "core/error.h"
#include "grading/submission.h"

namespace raygrade::serve {

struct CatalogEntry {
  std::string name;  // the file's name in the folder: what a deep link names
  AssignmentSpec spec;
  AssignmentBank bank;
  std::unique_ptr<AssignmentGrader> grader;  // full feedback: the policy is applied when shown
  std::string title() const { return spec.title.empty() ? spec.id : spec.title; }
  double points() const;
};

class Catalog {
 public:
  // Reads every assignment file (*.json with an "assignment" key) of `folder`, not its
  // subfolders. One that cannot be read, or whose bank lacks a problem, is left out and
  // reported in errors().
  explicit Catalog(const std::string& folder);
  const CatalogEntry* find(const std::string& name) const;
  const std::vector<std::unique_ptr<CatalogEntry>>& entries() const { return entries_; }
  const std::vector<Diagnostic>& errors() const { return errors_; }

 private:
  std::vector<std::unique_ptr<CatalogEntry>> entries_;
  std::vector<Diagnostic> errors_;
};

// Grades `answers` ({problem id: answer}) as `student`'s submission to `entry`, with full
// feedback, at `now` (seconds since 1970 UTC). Not gradable: the fault says why.
SubmissionGrade grade_answers(const CatalogEntry& entry, const StudentIdentity& student,
                              const nlohmann::json& answers, std::int64_t now);

// The graded submission as the assignment's feedback policy allows at `now` (submission_json
// of it, each problem's result rewritten for its policy).
nlohmann::json feedback_at(const CatalogEntry& entry, SubmissionGrade full, std::int64_t now);

}  // namespace raygrade::serve
