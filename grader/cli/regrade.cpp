// raygrade regrade: which students' points or feedback a new bank changes (a discovered mistake
// promoted to a named one, say), before anything is written.
#include "grading/regrade.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>

#include "assignments/feedback.h"
#include "assignments/grading.h"
#include "cli/command.h"
#include "core/escape.h"
#include "core/parallel.h"
#include "grading/outputs.h"

namespace raygrade::cli {
// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace regrade_internal {

struct RegradeOptions {
  std::vector<std::string> problems;  // without an assignment: the bank as it is
  std::string assignment;
  std::vector<std::string> bank;  // the new bank
  std::vector<std::string> submissions;
  unsigned jobs = 0;
};

// Grades with one bank: an assignment's (each student's variant) or a bank's problems as written.
class BankGrading {
 public:
  BankGrading(const RegradeOptions& o, const std::vector<std::string>& bank) {
    if (o.assignment.empty()) {
      bank_ = load_bank(bank);
      errors_ = bank_.errors;
      plain_ = std::make_unique<Assignment>(bank_.problems);
      errors_.insert(errors_.end(), plain_->errors().begin(), plain_->errors().end());
      return;
    }
    spec_ = std::make_unique<AssignmentSpec>(load_assignment(o.assignment));
    if (!bank.empty()) spec_->bank = bank;
    spec_bank_ = std::make_unique<AssignmentBank>(load_assignment_bank(*spec_));
    errors_ = spec_bank_->errors;
    AssignmentGradeOptions options;
    options.feedback = FeedbackPolicy::kFull;
    grader_ = std::make_unique<AssignmentGrader>(*spec_, spec_bank_->problems, options);
  }
  const std::vector<Diagnostic>& errors() const { return errors_; }
  SubmissionGrade grade(const std::string& file, std::optional<FileIdentity> seen) const {
    return grader_ ? grader_->grade_file(file, seen) : plain_->grade_file(file, seen);
  }

 private:
  Bank bank_;
  std::unique_ptr<Assignment> plain_;
  std::unique_ptr<AssignmentSpec> spec_;
  std::unique_ptr<AssignmentBank> spec_bank_;
  std::unique_ptr<AssignmentGrader> grader_;
  std::vector<Diagnostic> errors_;
};

int run_regrade(const RegradeOptions& o) {
  if (o.assignment.empty() == o.problems.empty()) {
    fmt::print(stderr, "raygrade regrade: give --assignment or --problems (the bank as it is)\n");
    return kExitBadInput;
  }
  BankGrading before(o, o.problems), after(o, o.bank);
  bool bad = false;
  for (const auto* g : {&before, &after})
    for (const auto& e : g->errors()) fmt::print(stderr, "{}\n", format_diagnostic(e)), bad = true;
  if (bad) return kExitBadInput;
  std::vector<Diagnostic> errors;
  std::vector<std::optional<FileIdentity>> seen;
  std::vector<std::string> files = submission_files(o.submissions, errors, &seen);
  for (const auto& e : errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  unsigned jobs = o.jobs > 0 ? o.jobs : default_jobs();
  auto pairs = parallel_map<std::pair<SubmissionGrade, SubmissionGrade>>(
      files.size(), jobs, [&](std::size_t i) {
        return std::make_pair(before.grade(files[i], seen[i]), after.grade(files[i], seen[i]));
      });
  std::size_t changed = 0;
  for (const auto& [b, a] : pairs) {
    if (!b.gradable || !a.gradable) {
      fmt::print(stderr, "{}\n", format_diagnostic(b.gradable ? *a.fault : *b.fault));
      bad = true;
      continue;
    }
    std::string who = b.identity.id.empty() ? b.student : b.identity.id;
    // Paired by problem id: a problem the new bank adds, drops or moves is seen as such.
    auto changes = grade_changes(b.results, a.results);
    for (const auto& c : changes)
      fmt::print("{}\t{}\t{}\n", printable(who), printable(c.problem_id), printable(c.what));
    changed += !changes.empty();
  }
  fmt::print(stderr, "{} of {} students' grades change; nothing was written.\n", changed,
             pairs.size());
  return bad || !errors.empty() ? kExitBadInput : kExitOk;
}

}  // namespace regrade_internal

Runner setup_regrade(CLI::App& sub) {
  using namespace regrade_internal;  // NOLINT: this file's own functions
  auto o = std::make_shared<RegradeOptions>();
  sub.add_option("--problems", o->problems, "without --assignment: the bank as it is")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub.add_option("--assignment", o->assignment,
                 "an assignment file: each submission is graded as the variant of its student");
  sub.add_option("--bank", o->bank, "the new bank: a file or folder (repeat for more)")
      ->required()
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub.add_option("submissions", o->submissions, "submission files or folders")->required();
  sub.add_option("-j,--jobs", o->jobs, "threads (default: one per core)");
  return [o] { return run_regrade(*o); };
}

}  // namespace raygrade::cli
