// Grading an assignment: each submission against the variant of the student it names, with the
// assignment's points and feedback policy.
#pragma once

#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assignments/assignment.h"
#include "grading/submission.h"

namespace raygrade {

struct AssignmentGradeOptions {
  std::int64_t now = 0;                    // seconds since 1970 UTC: before or after the due date
  std::optional<FeedbackPolicy> feedback;  // overrides the assignment's policy for every problem
  std::vector<StudentIdentity> roster;     // when not empty, every student must be on it
  // The accounts that uploaded the submission (Gradescope's submission_metadata.json): when
  // not empty, they are who the submission is from. With a roster, the student is the roster
  // entry of an uploader's email, and whatever the submission names must be that entry; without
  // one, the student is the account itself, and an assignment whose numbers differ per student
  // is refused (nothing ties an account to the id its numbers were drawn for).
  std::vector<StudentIdentity> uploaders;
  // The platform that said who uploaded it (PlatformEntry::name), for the message that asks for
  // its export with a roster.
  std::string_view uploads_platform;
};

class AssignmentGrader {
 public:
  // `problems` are the assignment's problems from its bank, in the assignment's order.
  AssignmentGrader(const AssignmentSpec& spec, std::vector<const Problem*> problems,
                   AssignmentGradeOptions options);
  ~AssignmentGrader();

  // Grades one file; safe to call from several threads at once. A submission that names no student
  // is graded against the generic set when every student's numbers are the same and there is no
  // roster; else it is rejected with the reason, as is one that names a student not on the
  // roster, or one whose variant cannot be drawn.
  // `seen`: the file submission_files listed at `path`; another file found there is refused.
  SubmissionGrade grade_file(const std::string& path,
                             std::optional<FileIdentity> seen = std::nullopt);

  // Grades a submission handed in through a learning platform (a file of its bulk download):
  // `owner` is the roster student the platform says handed it in, and whoever the submission
  // names must be that student. `name` is the file as diagnostics show it; `modified` its time.
  SubmissionGrade grade_handed_in(const std::string& name, std::string text, std::int64_t modified,
                                  const StudentIdentity& owner, std::string_view platform);

  // The student a submission is from: the uploader when there are uploaders, else the one it
  // names, completed from the roster; nobody (an empty identity) when it names nobody and
  // nobody needs naming (no per-student numbers, no roster). Throws Error when it names nobody
  // and must name someone, someone not on the roster, a name two students share, fields that
  // name different students, or someone other than the uploader.
  StudentIdentity identify(const Cursor& root) const;

  const std::vector<std::string>& problem_ids() const { return ids_; }

 private:
  struct Student;
  StudentIdentity identify_uploader(const Cursor& root,
                                    const std::optional<StudentIdentity>& claimed) const;
  std::shared_ptr<const Student> student(const std::string& key);
  // What grade_file and grade_handed_in share: `load` reads the file, `who` ties it to a student.
  SubmissionGrade grade_loaded(const std::string& path,
                               const std::function<std::shared_ptr<const SourceFile>()>& load,
                               const std::function<StudentIdentity(const Cursor&)>& who);

  const AssignmentSpec& spec_;
  std::vector<const Problem*> problems_;
  AssignmentGradeOptions options_;
  std::vector<std::string> ids_;
  bool per_student_numbers_ = false;  // has_per_student_numbers: students' numbers differ
  std::mutex students_mutex_;
  // The students drawn most recently, at most kCachedStudents, by key; recent_ orders the keys
  // from the most recently used.
  static constexpr std::size_t kCachedStudents = 64;
  std::list<std::string> recent_;
  std::map<std::string, std::pair<std::shared_ptr<const Student>, std::list<std::string>::iterator>>
      students_;
};

}  // namespace raygrade
