// Grading an assignment: each submission against the variant of the student it names, with the
// assignment's points and feedback policy.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "assignments/assignment.h"
#include "grading/submission.h"

namespace raygrade {

struct AssignmentGradeOptions {
  std::int64_t now = 0;                    // seconds since 1970 UTC: before or after the due date
  std::optional<FeedbackPolicy> feedback;  // overrides the assignment's policy for every problem
  std::vector<StudentIdentity> roster;     // when not empty, every student must be on it
  // The accounts that uploaded the submission (Gradescope's submission_metadata.json): when
  // not empty, the student a submission names must be one of them, by email (or by name when
  // the submission gives no email). The variant stays that of the student the file names.
  std::vector<StudentIdentity> uploaders;
};

class AssignmentGrader {
 public:
  // `problems` are the assignment's problems from its bank, in the assignment's order.
  AssignmentGrader(const AssignmentSpec& spec, std::vector<const Problem*> problems,
                   AssignmentGradeOptions options);
  ~AssignmentGrader();

  // Grades one file; safe to call from several threads at once. A submission that names no student,
  // or a student not on the roster, is rejected with the reason; so is one whose variant cannot be
  // drawn.
  SubmissionGrade grade_file(const std::string& path);

  // The student a submission names, completed from the roster; throws Error when it names
  // nobody or someone not on the roster.
  StudentIdentity identify(const Cursor& root) const;

  const std::vector<std::string>& problem_ids() const { return ids_; }

 private:
  struct Student;
  const Student& student(const std::string& key);

  const AssignmentSpec& spec_;
  std::vector<const Problem*> problems_;
  AssignmentGradeOptions options_;
  std::vector<std::string> ids_;
  std::mutex students_mutex_;
  std::map<std::string, std::unique_ptr<Student>> students_;
};

}  // namespace raygrade
