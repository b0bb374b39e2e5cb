// An assignment: problems taken from a bank, with points, a variant policy, a feedback policy
// and a due date (docs/assignments.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "problems/problem.h"

namespace raygrade {

// How much a graded answer tells the student.
enum class FeedbackPolicy {
  kScore,     // points only
  kMistakes,  // which part is wrong and the named mistake, never a reference value
  kFull,      // everything the grader says
};
const char* to_string(FeedbackPolicy p);
std::optional<FeedbackPolicy> parse_feedback_policy(std::string_view name);

// The policy before and after the due date.
struct FeedbackRule {
  FeedbackPolicy before_due = FeedbackPolicy::kMistakes;
  FeedbackPolicy after_due = FeedbackPolicy::kFull;
};

struct AssignmentProblem {
  std::string id;
  std::optional<double> points;          // the problem's total; its own points when empty
  bool variants = true;                  // false: every student gets the problem as written
  std::optional<FeedbackRule> feedback;  // overrides the assignment's
  std::string path;                      // JSON pointer in the assignment file
};

struct AssignmentSpec {
  std::string file;
  std::string id;
  std::string title;
  std::vector<std::string> bank;    // files and folders, as paths usable from here
  std::optional<std::int64_t> due;  // seconds since 1970-01-01 UTC
  std::string due_text;             // as written
  bool per_student = false;         // each student their own numbers
  bool allow_degenerate = false;    // keep draws on an edge, vertex, rim or tangent
  std::uint64_t seed = 0;
  FeedbackRule feedback;
  std::vector<AssignmentProblem> problems;

  // The policy for a problem at time `now` (seconds since 1970 UTC).
  FeedbackPolicy policy(const AssignmentProblem& p, std::int64_t now) const;
};

// Reads an assignment file; bank paths are taken relative to the file's folder. Throws Error
// naming the file and JSON path of any fault.
AssignmentSpec load_assignment(const std::string& path);
// The same, reading on past each fault: every fault found is in `errors` (unknown keys, a bad
// date, bad points, a problem listed twice ...), and the rest is read. Throws Error only when
// the file cannot be read or is not a JSON object.
AssignmentSpec read_assignment(const std::string& path, std::vector<Diagnostic>& errors);

// Whether a JSON file is an assignment (an object with an "assignment" key) rather than a bank.
bool is_assignment_file(const std::string& path);

// An ISO 8601 date and time, "2026-12-04T23:59:00Z" or with an offset ("+01:00"); a date alone
// means the end of that day in UTC. Seconds since 1970-01-01 UTC, or nothing if malformed.
std::optional<std::int64_t> parse_time(std::string_view text);
// A moment as pages show it, in UTC to the minute: "Friday 4 December 2026, 23:59 UTC".
std::string utc_time_text(std::int64_t seconds);
// A moment in ISO 8601, UTC, to the second: "2026-12-04T23:59:00Z" (a <time>'s datetime).
std::string iso_utc_time(std::int64_t seconds);

// The problems an assignment takes from its bank, in the assignment's order, as written (with
// their default numbers). Unknown ids are errors at their place in the assignment.
struct AssignmentBank {
  Bank bank;  // the whole bank, read once
  std::vector<const Problem*> problems;
  std::vector<Diagnostic> errors;  // the bank's and the assignment's
};
AssignmentBank load_assignment_bank(const AssignmentSpec& spec);

}  // namespace raygrade
