// The feedback policies before and after the due date, on every path that shows feedback: the
// library's assignment grader (the page in the browser and the command both use it), and every
// format of `raygrade grade --assignment`, to standard output and in --out, and with the due
// date of Gradescope's metadata.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "assignments/grading.h"
#include "assignments/platforms/platforms.h"
#include "grading/outputs.h"
#include "run_binary.h"

namespace raygrade {
// Named rather than anonymous: a unity batch of tests shares one anonymous namespace.
namespace feedback_policy_test {

using testing::read_text;
using testing::run_raygrade;
using testing::TempDir;
using testing::write_text;

// A sphere of radius 2 at (0, 0, 5) seen from the origin along +z is hit at t = 3 and t = 7.
// The student gives only t = 7: the full policy tells them the ray also hits at t = 3; the
// mistakes policy says which part is wrong ("check this part again") without the number; the
// score policy says neither.
constexpr const char* kBank = R"({"problems": [{"id": "ball", "title": "A ball",
  "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
  "object": {"type": "sphere", "center": [0, 0, 5], "radius": 2}}]})";
constexpr const char* kSubmission =
    R"({"student": {"id": "s1"}, "answers": {"ball": {"hits": [{"t": 7, "point": [0, 0, 7]}]}}})";
constexpr const char* kDue = "2026-12-04T23:59:00Z";
constexpr const char* kBefore = "2026-12-01T00:00:00Z";
constexpr const char* kAfter = "2026-12-10T00:00:00Z";
constexpr std::array<const char*, 3> kPolicies = {"score", "mistakes", "full"};

// Which policy `text` shows, by what it says: "" when it fits none.
std::string shown_policy(const std::string& text) {
  bool value = text.find("t = 3") != std::string::npos;
  bool part = text.find("check this part again") != std::string::npos;
  if (value) return "full";
  if (part) return "mistakes";
  return "score";
}

void write_class(const TempDir& dir, const std::string& feedback) {
  write_text(dir.path() / "bank.json", kBank);
  write_text(dir.path() / "hw.json",
             fmt::format(R"({{"assignment": "hw", "bank": "bank.json", "due": "{}",
  "feedback": {}, "problems": [{{"id": "ball", "points": 2}}]}})",
                         kDue, feedback));
  std::filesystem::create_directories(dir.path() / "subs");
  write_text(dir.path() / "subs" / "s1.json", kSubmission);
}

std::string rule(const char* before, const char* after) {
  return fmt::format(R"({{"before_due": "{}", "after_due": "{}"}})", before, after);
}

// Every file under `folder`, one after another.
std::string all_files(const std::filesystem::path& folder) {
  std::string out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(folder))
    if (e.is_regular_file()) out += read_text(e.path());
  return out;
}

// The library's grader, which the command and the page in the browser both grade with.
TEST(FeedbackPolicy, TheGraderShowsEachPolicyBeforeAndAfterTheDueDate) {
  TempDir dir("policy-lib");
  for (const char* before : kPolicies) {
    for (const char* after : kPolicies) {
      write_class(dir, rule(before, after));
      AssignmentSpec spec = load_assignment((dir.path() / "hw.json").string());
      AssignmentBank bank = load_assignment_bank(spec);
      ASSERT_TRUE(bank.errors.empty());
      for (bool late : {false, true}) {
        AssignmentGradeOptions options;
        options.now = *spec.due + (late ? 60 : -60);
        AssignmentGrader grader(spec, bank.problems, options);
        SubmissionGrade g = grader.grade_file((dir.path() / "subs" / "s1.json").string());
        ASSERT_TRUE(g.gradable);
        EXPECT_EQ(shown_policy(text_report(g)), late ? after : before)
            << before << " then " << after << (late ? ", after" : ", before") << " the due date\n"
            << text_report(g);
        EXPECT_DOUBLE_EQ(g.score, 1);  // one of the two hits: half the points in every policy
      }
    }
  }
}

// A problem's own rule overrides the assignment's, after the due date as before it.
TEST(FeedbackPolicy, AProblemsOwnRuleHoldsAfterTheDueDate) {
  TempDir dir("policy-own");
  write_class(dir, rule("full", "full"));
  write_text(dir.path() / "hw.json",
             fmt::format(R"({{"assignment": "hw", "bank": "bank.json", "due": "{}",
  "feedback": "full", "problems": [{{"id": "ball", "feedback": {}}}]}})",
                         kDue, rule("mistakes", "score")));
  for (bool late : {false, true}) {
    auto r = run_raygrade(
        fmt::format("grade --assignment hw.json subs/s1.json --now {}", late ? kAfter : kBefore),
        dir.path());
    EXPECT_EQ(shown_policy(r.out), late ? "score" : "mistakes") << r.out << r.err;
  }
}

// `raygrade grade --assignment` in every format that shows feedback, to standard output and
// in --out, before and after the due date, for every pair of policies.
TEST(FeedbackPolicy, EveryGradeFormatShowsEachPolicyBeforeAndAfterTheDueDate) {
  TempDir dir("policy-cli");
  int runs = 0;
  for (const char* before : kPolicies) {
    for (const char* after : kPolicies) {
      write_class(dir, rule(before, after));
      for (const auto& f : grade_formats()) {
        if (!f.render) continue;  // a gradebook: points only
        for (bool late : {false, true}) {
          std::string expected = late ? after : before;
          std::string when = late ? kAfter : kBefore;
          std::string what = fmt::format("{} then {}, {} {} the due date", before, after, f.name,
                                         late ? "after" : "before");
          std::filesystem::remove_all(dir.path() / "out");
          auto r = run_raygrade(fmt::format("grade --assignment hw.json subs --format {} "
                                            "--now {} --out out",
                                            f.name, when),
                                dir.path());
          ++runs;
          EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << what << ": " << r.err;
          EXPECT_EQ(shown_policy(all_files(dir.path() / "out")), expected) << what;
          if (f.needs_out) continue;
          r = run_raygrade(
              fmt::format("grade --assignment hw.json subs/s1.json --format {} --now {}", f.name,
                          when),
              dir.path());
          ++runs;
          EXPECT_EQ(shown_policy(r.out), expected) << what << " (standard output)\n" << r.out;
        }
      }
    }
  }
  EXPECT_GE(runs, 9 * 2 * 5);
}

// On Gradescope the due date is the metadata's (with the student's extension): after it the
// after_due policy, before it the before_due one, whatever the assignment file says.
TEST(FeedbackPolicy, GradescopesDueDateDecidesThePolicy) {
  TempDir dir("policy-gradescope");
  for (const char* after : {"score", "mistakes"}) {
    write_class(dir, rule("full", after));
    for (bool late : {false, true}) {
      // The assignment's own due date is long past; Gradescope's is 2026-12-20.
      write_text(dir.path() / "metadata.json",
                 R"({"assignment": {"due_date": "2026-12-20T23:59:00.000000+00:00"},
                     "users": [{"name": "S One", "email": "s1@example.edu"}]})");
      std::filesystem::remove_all(dir.path() / "out");
      auto r = run_raygrade(
          fmt::format("grade --assignment hw.json subs/s1.json --format gradescope --out out "
                      "--gradescope-metadata metadata.json --now {}",
                      late ? "2026-12-21T00:00:00Z" : kAfter),
          dir.path());
      EXPECT_EQ(shown_policy(all_files(dir.path() / "out")), late ? after : "full")
          << after << (late ? ", after" : ", before") << " Gradescope's due date: " << r.err;
    }
  }
}

}  // namespace feedback_policy_test
}  // namespace raygrade
