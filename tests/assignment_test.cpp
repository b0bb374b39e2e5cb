// Assignments: reading them, per-student variants, grading each student against their own
// numbers, feedback policies in every output format, rosters and templates.
#include "assignments/assignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <set>

#include "assignments/answer_form.h"
#include "assignments/check_assignment.h"
#include "assignments/feedback.h"
#include "assignments/grading.h"
#include "assignments/handout.h"
#include "assignments/platforms/gradescope.h"
#include "assignments/platforms/prairielearn.h"
#include "assignments/platforms/scorm.h"
#include "assignments/roster.h"
#include "assignments/variants.h"
#include "core/escape.h"
#include "grading/grade.h"
#include "grading/mistakes.h"
#include "grading/outputs.h"
#include "problems/kind.h"
#include "run_binary.h"
#include "test_util.h"

namespace raygrade {
namespace {

using testing::read_text;
using testing::TempDir;
using testing::write_text;

const std::string kExample = std::string(RAYGRADE_SOURCE_DIR) + "/assignments/homework-rays.json";
// 2026-12-04T23:59:00Z, computed independently (Python's calendar.timegm).
constexpr std::int64_t kDue = 1796428740;

std::string fault_of(const std::string& text) {
  TempDir dir("assignment");
  write_text(dir.path() / "a.json", text);
  try {
    (void)load_assignment((dir.path() / "a.json").string());
  } catch (const Error& e) {
    return e.diagnostic().path + ": " + e.diagnostic().message;
  }
  return "no error";
}

// A submission of `answers` (problem id → answer) by `student`.
std::string submission(const std::string& student, const nlohmann::json& answers) {
  nlohmann::json s = {{"answers", answers}};
  if (!student.empty()) s["student"] = {{"id", student}};
  return s.dump(2);
}

// Every reference answer of one student's variant.
nlohmann::json right_answers(const AssignmentSpec& spec, const AssignmentBank& bank,
                             const std::string& student) {
  nlohmann::json answers = nlohmann::json::object();
  for (const auto& p : student_problems(spec, bank.problems, student)) {
    answers[p.id] = p.task->answer();
  }
  return answers;
}

TEST(Assignment, ReadsTheExample) {
  AssignmentSpec a = load_assignment(kExample);
  EXPECT_EQ(a.id, "homework-rays");
  ASSERT_TRUE(a.due);
  EXPECT_EQ(*a.due, kDue);
  EXPECT_TRUE(a.per_student);
  EXPECT_EQ(a.seed, 2026u);
  ASSERT_EQ(a.problems.size(), 10u);
  EXPECT_EQ(a.problems[0].id, "variant-sphere");
  EXPECT_EQ(*a.problems[0].points, 3);
  EXPECT_EQ(a.policy(a.problems[0], kDue - 1), FeedbackPolicy::kMistakes);
  EXPECT_EQ(a.policy(a.problems[0], kDue + 1), FeedbackPolicy::kFull);
  EXPECT_EQ(a.policy(a.problems[9], kDue - 1), FeedbackPolicy::kFull);  // its own policy
  AssignmentBank bank = load_assignment_bank(a);
  EXPECT_TRUE(bank.errors.empty());
  ASSERT_EQ(bank.problems.size(), 10u);
}

TEST(Assignment, ParsesDueDates) {
  EXPECT_EQ(parse_time("2026-12-04T23:59:00Z"), kDue);
  EXPECT_EQ(parse_time("2026-12-04T23:59Z"), kDue);
  EXPECT_EQ(parse_time("2026-12-05T00:59:00+01:00"), kDue);
  EXPECT_EQ(parse_time("2026-12-04T22:59:00-01:00"), kDue);  // 22:59 at −01:00 is 23:59 UTC
  EXPECT_EQ(parse_time("2024-02-29"), 1709251199);           // a date alone: the end of that day
  EXPECT_FALSE(parse_time("2026-12-04T23:59:00"));           // no zone
  EXPECT_FALSE(parse_time("2026-02-29"));                    // not a leap year
  EXPECT_FALSE(parse_time("2026-13-01"));
  EXPECT_FALSE(parse_time("2026-12-04T24:00:00Z"));
  EXPECT_FALSE(parse_time("tomorrow"));
}

// Pages show a moment in UTC to the minute, and in ISO 8601 in a <time>'s datetime.
TEST(Assignment, ShowsTimesInUtc) {
  EXPECT_EQ(utc_time_text(kDue), "Friday 4 December 2026, 23:59 UTC");
  EXPECT_EQ(iso_utc_time(kDue), "2026-12-04T23:59:00Z");
  EXPECT_EQ(utc_time_text(0), "Thursday 1 January 1970, 00:00 UTC");
  EXPECT_EQ(iso_utc_time(-1), "1969-12-31T23:59:59Z");
  EXPECT_EQ(iso_utc_time(*parse_time("2024-02-29")), "2024-02-29T23:59:59Z");
  EXPECT_EQ(utc_time_text(*parse_time("2000-03-01T00:30:00+01:00")),
            "Tuesday 29 February 2000, 23:30 UTC");
}

TEST(Assignment, FaultsNameTheirPlace) {
  EXPECT_EQ(fault_of(R"({"assignment": "a", "bank": "b", "problems": ["x"], "due": "soon"})")
                .substr(0, 5),
            "/due:");
  EXPECT_NE(fault_of(R"({"assignment": "a", "bank": "b", "problems": ["x"], "feedbak": "full"})")
                .find("unknown key 'feedbak' (did you mean 'feedback'?)"),
            std::string::npos);
  EXPECT_NE(fault_of(R"({"assignment": "a", "bank": "b", "problems": ["x"], "feedback": "all"})")
                .find("/feedback: unknown feedback policy 'all'"),
            std::string::npos);
  EXPECT_NE(fault_of(R"({"assignment": "a", "bank": "b", "problems": ["x", {"id": "x"}]})")
                .find("/problems/1: problem 'x' is listed twice"),
            std::string::npos);
  EXPECT_NE(
      fault_of(R"({"assignment": "a", "bank": "b", "problems": []})").find("at least one problem"),
      std::string::npos);
}

TEST(Assignment, UnknownProblemsAreReportedWithASuggestion) {
  TempDir dir("assignment");
  write_text(dir.path() / "a.json",
             std::string(R"({"assignment": "a", "bank": ")") + RAYGRADE_SOURCE_DIR +
                 R"(/problems", "problems": ["sphere-hit", {"id": "sphere-hitt"}]})");
  AssignmentSpec a = load_assignment((dir.path() / "a.json").string());
  AssignmentBank bank = load_assignment_bank(a);
  ASSERT_EQ(bank.errors.size(), 1u);
  EXPECT_EQ(bank.errors[0].path, "/problems/1/id");
  EXPECT_NE(bank.errors[0].message.find("did you mean 'sphere-hit'?"), std::string::npos);
}

TEST(Assignment, EachStudentIsGradedAgainstTheirOwnNumbers) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  TempDir dir("grade");
  write_text(dir.path() / "ada.json", submission("s001", right_answers(spec, bank, "s001")));
  // Ada's answers handed in by Alan: graded against Alan's numbers.
  write_text(dir.path() / "alan.json", submission("s002", right_answers(spec, bank, "s001")));
  write_text(dir.path() / "nobody.json", submission("", right_answers(spec, bank, "s001")));
  AssignmentGradeOptions options;
  options.now = kDue - 60;
  AssignmentGrader grader(spec, bank.problems, options);
  SubmissionGrade ada = grader.grade_file((dir.path() / "ada.json").string());
  ASSERT_TRUE(ada.gradable) << format_diagnostic(*ada.fault);
  EXPECT_DOUBLE_EQ(ada.max_score, 21);  // 3 + 2 + 3 + 2 + 2 + 1 + 2 + 3 + 1 + 2
  EXPECT_DOUBLE_EQ(ada.score, 21);
  EXPECT_EQ(ada.identity.id, "s001");
  SubmissionGrade alan = grader.grade_file((dir.path() / "alan.json").string());
  ASSERT_TRUE(alan.gradable);
  EXPECT_LT(alan.score, 15);
  SubmissionGrade nobody = grader.grade_file((dir.path() / "nobody.json").string());
  EXPECT_FALSE(nobody.gradable);
  ASSERT_TRUE(nobody.fault);
  EXPECT_EQ(nobody.fault->code, "no-student");
  EXPECT_NE(nobody.fault->message.find("names no student"), std::string::npos);
  EXPECT_NE(nobody.fault->message.find("each student of 'homework-rays' has their own numbers"),
            std::string::npos)
      << nobody.fault->message;
}

// An assignment whose numbers are everyone's: with "per_student": false, or drawing per student
// only problems without parameters. A submission that names nobody is graded against the
// generic set, under its file's name; with a roster it must still name its student, and the
// refusal does not speak of numbers of one's own.
TEST(Assignment, WithoutPerStudentNumbersASubmissionNeedNotNameItsStudent) {
  TempDir dir("generic");
  const std::string bank = std::string(RAYGRADE_SOURCE_DIR) + "/problems";
  write_text(dir.path() / "same.json", R"({"assignment": "same", "bank": ")" + bank +
                                           R"(", "variants": {"per_student": false},
                 "problems": [{"id": "variant-sphere", "points": 3}, "sphere-hit"]})");
  write_text(dir.path() / "fixed.json",
             R"({"assignment": "fixed", "bank": ")" + bank +
                 R"(", "variants": {"per_student": true}, "problems": ["sphere-hit"]})");
  for (const char* name : {"same.json", "fixed.json"}) {
    SCOPED_TRACE(name);
    AssignmentSpec spec = load_assignment((dir.path() / name).string());
    AssignmentBank problems = load_assignment_bank(spec);
    ASSERT_TRUE(problems.errors.empty());
    EXPECT_FALSE(has_per_student_numbers(spec, problems.problems));
    write_text(dir.path() / "answers.json", submission("", right_answers(spec, problems, "")));
    AssignmentGrader grader(spec, problems.problems, AssignmentGradeOptions{});
    SubmissionGrade g = grader.grade_file((dir.path() / "answers.json").string());
    ASSERT_TRUE(g.gradable) << format_diagnostic(*g.fault);
    EXPECT_GT(g.max_score, 0);
    EXPECT_DOUBLE_EQ(g.score, g.max_score);
    EXPECT_TRUE(g.identity.empty());
    EXPECT_EQ(g.student, "answers");
    // A roster says who may hand in: a file that names nobody is refused, for that reason.
    AssignmentGradeOptions with_roster;
    with_roster.roster = {StudentIdentity{"Ada", "s001", ""}};
    AssignmentGrader rostered(spec, problems.problems, with_roster);
    SubmissionGrade refused = rostered.grade_file((dir.path() / "answers.json").string());
    EXPECT_FALSE(refused.gradable);
    ASSERT_TRUE(refused.fault);
    EXPECT_EQ(refused.fault->code, "no-student");
    EXPECT_NE(refused.fault->message.find("only the roster's students"), std::string::npos)
        << refused.fault->message;
    EXPECT_EQ(refused.fault->message.find("own numbers"), std::string::npos)
        << refused.fault->message;
  }
  // The example draws per student, and its problems have parameters: its numbers are each
  // student's own.
  AssignmentSpec example = load_assignment(kExample);
  EXPECT_TRUE(has_per_student_numbers(example, load_assignment_bank(example).problems));
}

// The exports that serve one page or one autograder to the whole class refuse only where
// students' numbers really differ: "per_student": true over a problem without parameters gives
// everyone the same numbers, so the Gradescope autograder needs no roster and a SCORM package
// may be made; the example's numbers differ, and both are refused, each for its reason.
TEST(Assignment, ExportsRefuseOnlyWhereNumbersDiffer) {
  TempDir dir("same-numbers-export");
  const std::string bank = std::string(RAYGRADE_SOURCE_DIR) + "/problems";
  write_text(dir.path() / "fixed.json",
             R"({"assignment": "fixed", "bank": ")" + bank +
                 R"(", "variants": {"per_student": true}, "problems": ["sphere-hit"]})");
  write_text(dir.path() / "raygrade", "not really a binary");
  write_text(dir.path() / "raygrade.js", "// not really the grader");
  auto refusal = [&](const std::string& file, auto&& export_it) -> std::string {
    AssignmentSpec spec = load_assignment(file);
    AssignmentBank problems = load_assignment_bank(spec);
    EXPECT_TRUE(problems.errors.empty());
    try {
      export_it(spec, problems);
    } catch (const Error& e) {
      return e.diagnostic().code;
    }
    return "";
  };
  auto gradescope = [&](const AssignmentSpec& spec, const AssignmentBank& problems) {
    EXPECT_FALSE(gradescope_autograder(spec, problems, dir.path() / "raygrade", "").empty());
  };
  auto scorm = [&](const AssignmentSpec& spec, const AssignmentBank& problems) {
    LmsExportInput in;
    in.spec = &spec;
    in.bank = &problems;
    in.grader_js = dir.path() / "raygrade.js";
    in.version = "1.2";
    EXPECT_FALSE(scorm_package(in, (dir.path() / "scorm").string()).files.empty());
  };
  const std::string fixed = (dir.path() / "fixed.json").string();
  EXPECT_EQ(refusal(fixed, gradescope), "");
  EXPECT_EQ(refusal(fixed, scorm), "");
  EXPECT_EQ(refusal(kExample, gradescope), "no-roster");
  EXPECT_EQ(refusal(kExample, scorm), "scorm-per-student");
}

TEST(Assignment, TheRosterNamesTheStudents) {
  TempDir dir("roster");
  write_text(dir.path() / "r.csv",
             "\xEF\xBB\xBFname,id,email\r\n\"Lovelace, Ada\",s001,Ada@Example.edu\r\n"
             "Alan Turing,s002,alan@example.edu\r\n");
  auto roster = load_roster((dir.path() / "r.csv").string());
  ASSERT_EQ(roster.size(), 2u);
  EXPECT_EQ(roster[0].name, "Lovelace, Ada");
  EXPECT_EQ(roster[0].id, "s001");
  const StudentIdentity* by_email = find_on_roster(roster, {"", "", "ada@example.EDU"});
  ASSERT_TRUE(by_email);
  EXPECT_EQ(by_email->id, "s001");
  EXPECT_FALSE(find_on_roster(roster, {"", "s003", ""}));
  write_text(dir.path() / "bad.csv", "id,nmae\ns1,x\n");
  try {
    (void)load_roster((dir.path() / "bad.csv").string());
    ADD_FAILURE() << "a misspelt column was accepted";
  } catch (const Error& e) {
    EXPECT_NE(e.diagnostic().message.find("unknown column 'nmae'"), std::string::npos);
    EXPECT_EQ(e.diagnostic().line, 1);
  }
  write_text(dir.path() / "twice.csv", "id\ns1\ns1\n");
  EXPECT_THROW((void)load_roster((dir.path() / "twice.csv").string()), Error);
}

// A submission naming `student` (any of id, name, email) with `answers`.
std::string submission_by(const nlohmann::json& student, const nlohmann::json& answers) {
  return nlohmann::json{{"student", student}, {"answers", answers}}.dump(2);
}

// Two students named alike and two emails: which fields name whom is known by construction.
constexpr const char* kTwinRoster =
    "id,name,email\n"
    "s001,Ann Lee,ann.lee@example.edu\n"
    "s002,Ann Lee,ann.lee2@example.edu\n"
    "s003,Bo Chen,bo@example.edu\n";

TEST(Identity, EveryFieldMustNameTheSameRosterStudent) {
  TempDir dir("identity");
  write_text(dir.path() / "r.csv", kTwinRoster);
  auto roster = load_roster((dir.path() / "r.csv").string());
  // A name two students share names nobody, and the candidates are listed.
  RosterMatch twin = match_on_roster(roster, {"Ann Lee", "", ""});
  EXPECT_FALSE(twin.entry);
  EXPECT_EQ(twin.code, "ambiguous-student");
  EXPECT_NE(twin.problem.find("s001"), std::string::npos) << twin.problem;
  EXPECT_NE(twin.problem.find("s002"), std::string::npos) << twin.problem;
  // The shared name with an id or an email is one student.
  ASSERT_TRUE(match_on_roster(roster, {"Ann Lee", "s002", ""}).entry);
  EXPECT_EQ(match_on_roster(roster, {"Ann Lee", "s002", ""}).entry->id, "s002");
  EXPECT_EQ(match_on_roster(roster, {"Ann Lee", "", "ANN.LEE2@example.edu"}).entry->id, "s002");
  // Fields that name two students: rejected, saying which.
  RosterMatch mixed = match_on_roster(roster, {"", "s003", "ann.lee@example.edu"});
  EXPECT_FALSE(mixed.entry);
  EXPECT_EQ(mixed.code, "student-mismatch");
  EXPECT_NE(mixed.problem.find("email 'ann.lee@example.edu'"), std::string::npos) << mixed.problem;
  EXPECT_NE(mixed.problem.find("id 's001'"), std::string::npos) << mixed.problem;
  EXPECT_EQ(match_on_roster(roster, {"Bo Chen", "s001", ""}).code, "student-mismatch");
  EXPECT_EQ(match_on_roster(roster, {"", "s009", ""}).code, "not-on-roster");
}

TEST(Identity, AnAmbiguousNameIsRejectedNotGradedAsTheWrongTwin) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  TempDir dir("twins");
  write_text(dir.path() / "r.csv", kTwinRoster);
  // The second Ann's own right answers, naming her by name alone.
  write_text(dir.path() / "ann.json", submission_by("Ann Lee", right_answers(spec, bank, "s002")));
  write_text(dir.path() / "ann2.json", submission_by({{"name", "Ann Lee"}, {"id", "s002"}},
                                                     right_answers(spec, bank, "s002")));
  AssignmentGradeOptions options;
  options.now = kDue - 60;
  options.roster = load_roster((dir.path() / "r.csv").string());
  AssignmentGrader grader(spec, bank.problems, options);
  SubmissionGrade ann = grader.grade_file((dir.path() / "ann.json").string());
  EXPECT_FALSE(ann.gradable);
  ASSERT_TRUE(ann.fault);
  EXPECT_EQ(ann.fault->code, "ambiguous-student");
  EXPECT_EQ(ann.fault->path, "/student");
  SubmissionGrade ann2 = grader.grade_file((dir.path() / "ann2.json").string());
  ASSERT_TRUE(ann2.gradable) << format_diagnostic(*ann2.fault);
  EXPECT_EQ(ann2.identity.id, "s002");
  EXPECT_DOUBLE_EQ(ann2.score, 21);
}

TEST(Identity, TheUploaderNotTheFileDecidesWhoseNumbersAreGraded) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  TempDir dir("uploader");
  write_text(dir.path() / "r.csv", kTwinRoster);
  nlohmann::json bo = right_answers(spec, bank, "s003");
  ASSERT_NE(bo, right_answers(spec, bank, "s001"));
  AssignmentGradeOptions options;
  options.now = kDue - 60;
  options.roster = load_roster((dir.path() / "r.csv").string());
  options.uploaders = {StudentIdentity{"Ann Lee", "", "ann.lee@example.edu"}};
  AssignmentGrader grader(spec, bank.problems, options);
  auto grade = [&](const nlohmann::json& student, const nlohmann::json& answers) {
    write_text(dir.path() / "up.json", student.is_null()
                                           ? nlohmann::json{{"answers", answers}}.dump()
                                           : submission_by(student, answers));
    return grader.grade_file((dir.path() / "up.json").string());
  };
  // Bo's id with the uploader's own email: the two fields name two students.
  SubmissionGrade mixed = grade({{"id", "s003"}, {"email", "ann.lee@example.edu"}}, bo);
  EXPECT_FALSE(mixed.gradable);
  ASSERT_TRUE(mixed.fault);
  EXPECT_EQ(mixed.fault->code, "student-mismatch");
  EXPECT_DOUBLE_EQ(mixed.score, 0);
  // Bo's whole identity from Ann's account.
  SubmissionGrade bos =
      grade({{"id", "s003"}, {"name", "Bo Chen"}, {"email", "bo@example.edu"}}, bo);
  EXPECT_FALSE(bos.gradable);
  ASSERT_TRUE(bos.fault);
  EXPECT_EQ(bos.fault->code, "not-uploader");
  // Naming nobody: the account is the student, and her own numbers are graded.
  SubmissionGrade own = grade(nullptr, right_answers(spec, bank, "s001"));
  ASSERT_TRUE(own.gradable) << format_diagnostic(*own.fault);
  EXPECT_EQ(own.identity.id, "s001");
  EXPECT_DOUBLE_EQ(own.score, 21);
  // Without a roster nothing ties an account to an id: an assignment with per-student numbers
  // is refused rather than graded as the id the file claims.
  options.roster.clear();
  AssignmentGrader no_roster(spec, bank.problems, options);
  write_text(dir.path() / "claim.json",
             submission_by({{"id", "s003"}, {"email", "ann.lee@example.edu"}}, bo));
  SubmissionGrade claim = no_roster.grade_file((dir.path() / "claim.json").string());
  EXPECT_FALSE(claim.gradable);
  ASSERT_TRUE(claim.fault);
  EXPECT_EQ(claim.fault->code, "no-roster");
}

TEST(Assignment, TheBlankTemplateEarnsNothingAndIsNotAFault) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  StudentIdentity who{"Ada", "s001", ""};
  Handout h = make_handout(spec, student_problems(spec, bank.problems, "s001"), &who);
  EXPECT_EQ(h.template_json["student"]["id"], "s001");
  EXPECT_EQ(h.template_json["answers"]["variant-sphere"]["hits"][0]["t"], "");
  TempDir dir("template");
  write_text(dir.path() / "t.json", h.template_json.dump(2));
  AssignmentGradeOptions options;
  options.feedback = FeedbackPolicy::kFull;
  AssignmentGrader grader(spec, bank.problems, options);
  SubmissionGrade g = grader.grade_file((dir.path() / "t.json").string());
  ASSERT_TRUE(g.gradable) << format_diagnostic(*g.fault);
  EXPECT_DOUBLE_EQ(g.score, 0);
  std::string text = text_report(g);
  EXPECT_EQ(text.find("could not read"), std::string::npos) << text;
}

// The numbers written in a text, as whole tokens ("0.67" holds no "0.6").
std::set<std::string> number_tokens(const std::string& text) {
  static const std::regex number(R"((\d+(\.\d+)?(e[+-]?\d+)?))");
  std::set<std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), number), end; it != end; ++it) {
    out.insert(it->str());
  }
  return out;
}

// The reference values of a student's variant a student could copy: every number of every
// answer that is not a whole number, written as reports write numbers, less those the student
// is given anyway (in a statement or title).
std::set<std::string> reference_values(const std::vector<Problem>& problems) {
  std::set<std::string> out, given;
  auto walk = [&](const nlohmann::json& v, auto&& self) -> void {
    if (v.is_number()) {
      double x = v.get<double>();
      if (std::abs(x - std::round(x)) < 1e-6) return;
      for (int digits : {3, 4, 5, 6}) out.insert(fmt::format("{:.{}g}", std::abs(x), digits));
    } else if (v.is_array() || v.is_object()) {
      for (const auto& item : v) self(item, self);
    }
  };
  for (const auto& p : problems) {
    walk(p.task->answer(), walk);
    for (const auto& t : number_tokens(p.statement + " " + p.title)) given.insert(t);
  }
  for (const auto& g : given) out.erase(g);
  return out;
}

TEST(Assignment, TheMistakesPolicyRevealsNoReferenceValueInAnyFormat) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  auto mine = student_problems(spec, bank.problems, "s001");
  // Wrong answers to every problem: the numbers of another student.
  TempDir dir("policy");
  write_text(dir.path() / "s.json", submission("s001", right_answers(spec, bank, "s777")));
  std::set<std::string> values = reference_values(mine);
  ASSERT_GT(values.size(), 20u);
  for (auto policy : {FeedbackPolicy::kMistakes, FeedbackPolicy::kScore, FeedbackPolicy::kFull}) {
    AssignmentGradeOptions options;
    options.feedback = policy;
    AssignmentGrader grader(spec, bank.problems, options);
    SubmissionGrade g = grader.grade_file((dir.path() / "s.json").string());
    ASSERT_TRUE(g.gradable);
    // Points are shown in every policy: a value that is also a number of points is not told.
    std::set<std::string> points = {format_points(g.score), format_points(g.max_score)};
    for (const auto& r : g.results) {
      points.insert(format_points(r.score));
      points.insert(format_points(r.max_score));
      for (const auto& part : r.parts) {
        points.insert(format_points(part.points));
        points.insert(format_points(part.max_points));
      }
    }
    std::vector<std::pair<std::string, std::string>> formats = {
        {"text", text_report(g)},
        {"json", submission_json(g).dump()},
        {"csv", gradebook_csv({g}, grader.problem_ids())},
        {"html", feedback_html(g)},
        {"gradescope", gradescope_json(g, 0.1).dump()},
        {"prairielearn", prairielearn_json(g).dump()}};
    int found = 0;
    for (const auto& [name, text] : formats) {
      for (const auto& token : number_tokens(text)) {
        if (!values.count(token) || points.count(token)) continue;
        ++found;
        if (policy != FeedbackPolicy::kFull) {
          ADD_FAILURE() << name << " shows " << token;
        }
      }
    }
    // The same search finds the values where they are allowed: it can fail.
    if (policy == FeedbackPolicy::kFull) {
      EXPECT_GT(found, 0);
    }
  }
}

TEST(Assignment, TheMistakesPolicyStillNamesTheMistakeAndThePart) {
  GradeResult r;
  r.problem_id = "p";
  r.parts.push_back({"t", 1, 2, PartStatus::kPartial, {"The far root t = 7.268 is a hit too."}});
  r.parts.push_back({"point",
                     0,
                     1,
                     PartStatus::kWrong,
                     {"could not read '7.2.7': a second decimal point at character 4"}});
  r.mistakes.push_back(make_mistake("far-root", "t", "You gave t = 7.268, the far root."));
  r.notes.emplace_back("The ray also hits at t = 1.057.");
  GradeResult mistakes = r, score = r;
  apply_feedback_policy(mistakes, FeedbackPolicy::kMistakes);
  std::string lines = fmt::format("{}", fmt::join(feedback_lines(mistakes), "\n"));
  EXPECT_EQ(lines.find("7.268"), std::string::npos) << lines;
  EXPECT_EQ(lines.find("1.057"), std::string::npos) << lines;
  EXPECT_NE(lines.find("Far root given as the first hit"), std::string::npos) << lines;
  EXPECT_NE(lines.find("t (1/2, partial): Partly right"), std::string::npos) << lines;
  EXPECT_NE(lines.find("could not read '7.2.7'"), std::string::npos) << lines;
  apply_feedback_policy(score, FeedbackPolicy::kScore);
  EXPECT_TRUE(score.mistakes.empty());
  EXPECT_TRUE(score.parts[0].feedback.empty());
}

// The graders say which part they could not read ("t: could not read '7.2.7': ..."); the
// mistakes policy keeps that sentence, which quotes the student's own text alone.
TEST(Assignment, TheMistakesPolicyQuotesANumberItCouldNotRead) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  TempDir dir("unreadable");
  write_text(dir.path() / "ada.json",
             submission("s001", {{"variant-shade", {{"intensity", "7.2.7"}}},
                                 {"variant-sphere", {{"hits", {{{"t", "9..1"}}}}}},
                                 {"scene-first-hit-only",
                                  {{"object", "ball"}, {"hits", {{{"t", "5,5"}}}}}}}));
  AssignmentGradeOptions options;
  options.now = kDue - 60;  // before the due date: the mistakes policy
  AssignmentGrader grader(spec, bank.problems, options);
  SubmissionGrade ada = grader.grade_file((dir.path() / "ada.json").string());
  ASSERT_TRUE(ada.gradable) << format_diagnostic(*ada.fault);
  std::string all;
  for (const auto& r : ada.results) all += fmt::format("{}\n", fmt::join(feedback_lines(r), "\n"));
  EXPECT_NE(all.find("could not read '7.2.7'"), std::string::npos) << all;
  EXPECT_NE(all.find("could not read '9..1'"), std::string::npos) << all;
  EXPECT_NE(all.find("t: could not read '5,5'"), std::string::npos) << all;
}

// The sentence about an unreadable number is kept whatever names the value: a part
// ("I1.reflected"), a colour channel ("intensity channel r"); a name that holds a reference
// value ("Hit 1 (ball at t = 5)") drops the sentence.
TEST(Assignment, TheMistakesPolicyQuotesAnUnreadableComponentOrChannel) {
  GradeResult r;
  r.problem_id = "p";
  r.parts.push_back(
      {"I1.reflected",
       0,
       1,
       PartStatus::kWrong,
       {"I1.reflected: could not read '0..4': a second decimal point at character 3"}});
  r.parts.push_back({"intensity",
                     0,
                     1,
                     PartStatus::kWrong,
                     {"intensity channel r: could not read 'x': expected a number"}});
  r.parts.push_back({"tree",
                     0,
                     1,
                     PartStatus::kWrong,
                     {"Hit 1 (ball at t = 5): n1: could not read '1..5': a second decimal point "
                      "at character 3"}});
  apply_feedback_policy(r, FeedbackPolicy::kMistakes);
  std::string lines = fmt::format("{}", fmt::join(feedback_lines(r), "\n"));
  EXPECT_NE(lines.find("I1.reflected: could not read '0..4'"), std::string::npos) << lines;
  EXPECT_NE(lines.find("intensity channel r: could not read 'x'"), std::string::npos) << lines;
  EXPECT_EQ(lines.find("t = 5"), std::string::npos) << lines;
  EXPECT_EQ(lines.find("'1..5'"), std::string::npos) << lines;
}

TEST(Assignment, TheCheckDrawsSampleVariants) {
  TempDir dir("check");
  // ox = 4.99999999 makes every draw nearly tangent to the sphere of radius 5: no variant
  // passes the boundary check.
  write_text(dir.path() / "bank.json", R"({"id": "tangent",
    "parameters": {"ox": {"choices": [4.99999999, 5.00000001], "default": 4.99999999}},
    "ray": {"origin": ["=ox", 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 10], "radius": 5}})");
  write_text(dir.path() / "a.json",
             R"({"assignment": "a", "bank": "bank.json", "variants": {"seed": 1},
                 "problems": ["tangent"]})");
  CheckReport bad = check_assignment((dir.path() / "a.json").string());
  ASSERT_EQ(bad.problems.size(), 1u);
  std::map<std::string, const Diagnostic*> by_code;
  for (const auto& d : bad.problems[0].diagnostics) by_code[d.code] = &d;
  ASSERT_TRUE(by_code.count("no-variant"));
  EXPECT_NE(by_code["no-variant"]->message.find("sample-001"), std::string::npos);
  // Both values of ox are rejected: the note counts the draws, the warning names ox.
  ASSERT_TRUE(by_code.count("draws"));
  EXPECT_NE(by_code["draws"]->message.find("200 of 200 draws"), std::string::npos)
      << by_code["draws"]->message;
  ASSERT_TRUE(by_code.count("collapsed-parameter"));
  EXPECT_NE(by_code["collapsed-parameter"]->message.find("only 0 of the 2 values of ox"),
            std::string::npos);
  CheckReport good = check_assignment(kExample);
  EXPECT_EQ(good.count(Severity::kError), 0);
  EXPECT_EQ(good.count(Severity::kWarning), 0);
  EXPECT_EQ(good.problems.size(), 10u);
}

// A stated answer that forgets a square, t = cz ∓ sqrt(25 − ox) for a sphere of radius 5 at
// (0, 0, cz) and a ray from (ox, 0, 0) along +z: right only where ox = ox², that is ox = 0 of
// the choices 0, 3, 4 (ox = 3: sqrt(22) against the right 4; ox = 4: sqrt(21) against 3).
// Every draw with ox = 3 or 4 is named, never one with ox = 0, and ox is said to collapse.
TEST(Assignment, TheCheckFindsAStatedAnswerWrongOnSomeDraws) {
  TempDir dir("forgot-square");
  write_text(dir.path() / "bank.json", R"json({"id": "forgot-square",
    "parameters": {"ox": {"choices": [0, 3, 4], "default": 0},
                   "cz": {"integer": [7, 12], "default": 10}},
    "ray": {"origin": ["=ox", 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, "=cz"], "radius": 5},
    "expected": {"hits": [{"t": "=cz - sqrt(25 - ox)"}, {"t": "=cz + sqrt(25 - ox)"}]}})json");
  write_text(dir.path() / "a.json",
             R"({"assignment": "a", "bank": "bank.json", "variants": {"seed": 1},
                 "problems": ["forgot-square"]})");
  CheckReport r = check_assignment((dir.path() / "a.json").string());
  ASSERT_EQ(r.problems.size(), 1u);
  int wrong = 0;
  bool collapsed = false;
  for (const auto& d : r.problems[0].diagnostics) {
    if (d.code == "wrong-expected") {
      ++wrong;
      EXPECT_EQ(d.severity, Severity::kError);
      EXPECT_EQ(d.message.find("ox = 0"), std::string::npos) << d.message;
    }
    collapsed |= d.code == "collapsed-parameter" &&
                 d.message.find("only 1 of the 3 values of ox") != std::string::npos;
  }
  // cz takes 6 values and ox 2 wrong ones: 12 wrong pairs, 10 named and one count of the rest.
  EXPECT_EQ(wrong, 11);
  EXPECT_TRUE(collapsed);
}

// Five faults in one file, each reported in one run: a month 13, a misspelt key, negative
// points, a problem listed twice and an id the bank does not have.
TEST(Assignment, TheCheckReportsEveryFaultOfTheFile) {
  TempDir dir("typos");
  write_text(dir.path() / "bank.json", R"({"id": "p", "ray": {"origin": [0, 0, 0],
    "direction": [1, 0, 0]}, "object": {"type": "sphere", "center": [3, 0, 0], "radius": 1}})");
  write_text(dir.path() / "a.json", R"({"assignment": "a", "bank": "bank.json",
    "due": "2026-13-40", "problems": [{"id": "p", "pionts": 2}, {"id": "p", "points": -1},
    "no-such"]})");
  CheckReport r = check_assignment((dir.path() / "a.json").string());
  std::multiset<std::string> found;
  for (const auto& p : r.problems) {
    for (const auto& d : p.diagnostics) {
      if (d.severity == Severity::kError) found.insert(d.path + " " + d.code);
    }
  }
  EXPECT_EQ(found, (std::multiset<std::string>{
                       "/due invalid", "/problems/0/pionts unknown-key", "/problems/1/points range",
                       "/problems/1 duplicate-id", "/problems/2 unknown-problem"}));
  // load_assignment still stops at the first, for the commands that need a whole file.
  EXPECT_THROW((void)load_assignment((dir.path() / "a.json").string()), Error);
}

// The example's triangle a = (0, 0, z), b = (s, 0, z), c = (0, s, z) and the ray from
// (px, py, 0) along +z: the hit is on the edge bc exactly when px + py = s (w_a = 0), which the
// draws px = py = 2, s = 4 give (1 draw in 12). No student gets one; with allow_degenerate,
// some do.
TEST(Assignment, NoStudentGetsADrawOnAnEdge) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  auto on_edge = [](const Problem& p) {
    return p.values.at("px").get<int>() + p.values.at("py").get<int>() ==
           p.values.at("s").get<int>();
  };
  std::size_t index = 0;
  while (spec.problems[index].id != "variant-triangle") ++index;
  int edges = 0;
  for (int s = 0; s < 120; ++s) {
    auto problems = student_problems(spec, bank.problems, fmt::format("student-{}", s));
    edges += on_edge(problems[index]);
  }
  EXPECT_EQ(edges, 0);
  spec.allow_degenerate = true;
  edges = 0;
  for (int s = 0; s < 120; ++s) {
    auto problems = student_problems(spec, bank.problems, fmt::format("student-{}", s));
    edges += on_edge(problems[index]);
  }
  EXPECT_GT(edges, 0);  // about 10 of 120
}

TEST(Assignment, PointsAreScaledKeepingTheParts) {
  GradeResult r;
  r.score = 1;
  r.max_score = 4;
  r.parts.push_back({"t", 1, 2, PartStatus::kPartial, {}});
  r.parts.push_back({"point", 0, 2, PartStatus::kWrong, {}});
  scale_points(r, 2);
  EXPECT_DOUBLE_EQ(r.score, 0.5);
  EXPECT_DOUBLE_EQ(r.max_score, 2);
  EXPECT_DOUBLE_EQ(r.parts[0].max_points, 1);
  EXPECT_DOUBLE_EQ(r.parts[0].points, 0.5);
}

TEST(Assignment, TheHandoutShowsTheStudentsNumbersAndNoAnswer) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  auto problems = student_problems(spec, bank.problems, "s001");
  StudentIdentity who{"Ada <Lovelace>", "s001", "ada@example.edu"};
  Handout h = make_handout(spec, problems, &who);
  EXPECT_NE(h.html.find("Ada &lt;Lovelace&gt;"), std::string::npos);
  EXPECT_EQ(h.html.find("Ada <Lovelace>"), std::string::npos);
  // The problems are the page's main landmark; the due date is in UTC, in a <time>.
  EXPECT_NE(h.html.find("</header>\n<main>\n<section"), std::string::npos);
  EXPECT_NE(h.html.find("Due <time datetime=\"2026-12-04T23:59:00Z\">Friday 4 December 2026, "
                        "23:59 UTC</time>"),
            std::string::npos);
  for (const auto& p : problems) {
    EXPECT_NE(h.html.find(html_escape(p.statement)), std::string::npos) << p.id;
  }
  // The figure of the sphere problem draws the sphere and the ray, and no hit.
  std::string figure = statement_figure_svg(problems[0]);
  EXPECT_NE(figure.find("<svg"), std::string::npos);
  Sketch full = problems[0].task->sketch();
  int hits = 0;
  for (const auto& item : full.items) hits += item.ink == Ink::kHit;
  EXPECT_GT(hits, 0);  // the solution's sketch has them: the figure must leave them out
  for (const auto& item : full.items) {
    if (item.ink == Ink::kHit && !item.label.empty()) {
      EXPECT_EQ(figure.find(xml_escape(item.label)), std::string::npos) << item.label;
    }
  }
  // The form is the same for a hit and a miss: it does not depend on the answer.
  EXPECT_EQ(answer_form(problems[0]).dump(),
            answer_form(student_problems(spec, bank.problems, "s002")[0]).dump());
}

// The inputs of a form, each as the part it answers ("ray/origin" answers "ray"; a column of the
// hits table its own part); the JSON catch-all is "".
std::vector<std::string> asked_inputs(const nlohmann::json& form) {
  std::vector<std::string> out;
  for (const auto& f : form["fields"]) {
    if (f["type"] == "hits") {
      for (const auto& c : f["columns"]) out.push_back(c["key"]);
      continue;
    }
    if (f["type"] == "tree") {  // the ray tree: the parts it asks
      for (const auto& part : f["asks"]) out.push_back(part);
      continue;
    }
    std::string key = f["key"];
    if (key.rfind("components/", 0) == 0) {  // components/I1/diffuse answers I1.diffuse
      std::string rest = key.substr(11);
      out.push_back(rest.replace(rest.find('/'), 1, "."));
      continue;
    }
    out.push_back(key.substr(0, key.find('/')));
  }
  return out;
}

// No kind asks for JSON: every problem of the bank, every input its kind's form can have, is
// one of the form's types (a number, a vector, a choice ... a ray tree built point by point),
// and every kind of the table is among them.
TEST(Assignment, NoKindAsksForJson) {
  Bank bundled = load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems"});
  const std::set<std::string> types = {"number",  "vector", "yesno", "choice", "set",
                                       "formula", "hits",   "rows",  "tree"};
  std::set<std::string> kinds;
  for (const auto& p : bundled.problems) {
    kinds.insert(p.kind);
    for (const nlohmann::json& form : {every_input(p), answer_form(p)}) {
      for (const auto& f : form["fields"]) {
        EXPECT_TRUE(types.count(f["type"].get<std::string>())) << p.id << ": " << f.dump();
        EXPECT_EQ(f["label"].get<std::string>().find("JSON"), std::string::npos) << p.id;
      }
    }
  }
  for (const auto& entry : kind_table()) {
    EXPECT_TRUE(kinds.count(std::string(entry.name))) << entry.name << " is not in the bank";
  }
  // The ray trees: a tree field for each ask but hit, media and components, each with its
  // objects and lights to choose from.
  int trees = 0;
  for (const auto& p : bundled.problems) {
    nlohmann::json form = every_input(p);
    for (const auto& f : form["fields"]) {
      if (f["type"] != "tree") continue;
      ++trees;
      EXPECT_FALSE(f["objects"].empty()) << p.id;
      EXPECT_GE(f["rows"].get<int>(), 1) << p.id;
    }
  }
  EXPECT_GE(trees, 9);  // the bank's trees asked as trees
}

// A part worth 0 points is not asked: no input on the handout, in the answer template or in
// PrairieLearn (all three come from the form). Every problem of the bank and of each student of
// the example assignment.
TEST(Assignment, NoInputForAPartWorthNoPoints) {
  Bank bundled = load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems"});
  std::vector<const Problem*> all;
  for (const auto& p : bundled.problems) all.push_back(&p);
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  std::vector<Problem> drawn;
  for (const char* s : {"s001", "s002", "s003"}) {
    for (auto& p : student_problems(spec, bank.problems, s)) drawn.push_back(std::move(p));
  }
  for (const auto& p : drawn) all.push_back(&p);
  // Inputs that answer another part too.
  const std::multimap<std::string, std::string> also = {{"total_internal_reflection", "direction"},
                                                        {"object", "hit"},
                                                        {"t", "hit"},
                                                        {"t", "media"},
                                                        {"n1", "media"},
                                                        {"n2", "media"}};
  auto scored_by_other = [&](const Grader& g, const std::string& input) {
    auto [from, to] = also.equal_range(input);
    for (auto it = from; it != to; ++it) {
      if (g.part_points(it->second) > 0) return true;
    }
    return false;
  };
  for (const Problem* p : all) {
    Grader g(*p);
    nlohmann::json form = answer_form(*p);
    for (const auto& part : asked_inputs(form)) {
      EXPECT_TRUE(g.part_points(part) > 0 || scored_by_other(g, part))
          << p->id << ": an input for " << part << ", worth no points";
    }
    // The answer template: each key of its answer (and of each row of its hits).
    nlohmann::json blank = blank_answer(form);
    std::vector<std::string> keys;
    for (const auto& [key, value] : blank.items()) {
      if (key == "hits") {
        for (const auto& [column, v] : value[0].items()) keys.push_back(column);
      } else if (key == "components") {  // {"I1": {"diffuse": ""}} answers I1.diffuse
        for (const auto& [label, asked] : value.items()) {
          for (const auto& [component, v] : asked.items())
            keys.push_back(fmt::format("{}.{}", label, component));
        }
      } else {
        keys.push_back(key);
      }
    }
    for (const auto& key : keys) {
      EXPECT_TRUE(g.part_points(key) > 0 || scored_by_other(g, key))
          << p->id << ": the template has " << key << ", worth no points";
    }
  }
  // By the documented defaults: a sphere asks t (2 points) and the point (1), not the normal
  // (0); a triangle with "points": {"normal": 1} asks the normal too, never the weights; a
  // refraction asks the direction (and "total internal reflection?", which answers it); a
  // Phong problem the intensity alone.
  auto inputs = [](const char* source) {
    return asked_inputs(answer_form(testing::problem(source)));
  };
  using V = std::vector<std::string>;
  EXPECT_EQ(inputs(R"({"id": "s", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})"),
            (V{"t", "point"}));
  EXPECT_EQ(inputs(R"({"id": "tri", "points": {"normal": 1},
    "ray": {"origin": [0.2, 0.2, 1], "direction": [0, 0, -1]},
    "object": {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}})"),
            (V{"t", "point", "normal"}));
  EXPECT_EQ(inputs(R"({"id": "w", "kind": "refract", "direction": [0.8660254037844386, -0.5, 0],
    "normal": [0, 1, 0], "n1": 1, "n2": 1.333})"),
            (V{"total_internal_reflection", "direction"}));
  EXPECT_EQ(inputs(testing::kTwoLightShade), (V{"intensity"}));
}

// The example's bank is "../problems": the page names the assignment one folder deep (d1/) and
// the bank's files beside that folder, so that "d1/../problems" reaches them; the grader's
// script goes in with a policy that lets it compile, and a handout without practice has neither.
TEST(Assignment, APracticePageCarriesTheGraderAndTheBank) {
  AssignmentSpec spec = load_assignment(kExample);
  AssignmentBank bank = load_assignment_bank(spec);
  auto problems = student_problems(spec, bank.problems, "s001");
  PracticeAssets assets = practice_assets(spec, "function createRaygrade() {}");
  EXPECT_EQ(assets.assignment, "d1/homework-rays.json");
  std::set<std::string> names;
  for (const auto& [name, text] : assets.files) names.insert(name);
  EXPECT_TRUE(names.count("d1/homework-rays.json"));
  EXPECT_TRUE(names.count("problems/sphere.json"));
  EXPECT_TRUE(names.count("problems/seeds/seed000-spheres.json"));
  std::vector<Diagnostic> errors;
  EXPECT_EQ(assets.files.size(),
            1 + list_bank_files({std::string(RAYGRADE_SOURCE_DIR) + "/problems"}, errors).size());
  StudentIdentity who{"", "s001", ""};
  Handout practice = make_handout(spec, problems, &who, &assets);
  EXPECT_NE(practice.html.find("<script>function createRaygrade() {}</script>"), std::string::npos);
  EXPECT_NE(practice.html.find("'wasm-unsafe-eval'"), std::string::npos);
  EXPECT_NE(practice.html.find("\"unlock_after\":3"), std::string::npos);
  Handout plain = make_handout(spec, problems, &who);
  // Every page compiles the grader's reader of typed answers (typed_reader.js).
  EXPECT_NE(plain.html.find("'wasm-unsafe-eval'"), std::string::npos);
  EXPECT_NE(plain.html.find("createTypedReader"), std::string::npos);
  EXPECT_EQ(plain.html.find("createRaygrade() {}"), std::string::npos);
  // A script that could close its element is refused, not written.
  assets.grader_js = "var s = '</script>';";
  EXPECT_THROW(make_handout(spec, problems, &who, &assets), Error);
}

// A bank named by an absolute path: the page's copy of the assignment names it relative to
// the assignment, as the page names the bank's files, so that the page's grader (which reads
// the files from a folder of their own) finds every problem. A generic page of an assignment
// whose numbers are everyone's names no student, not even a stand-in.
TEST(Assignment, APracticePageCarriesABankNamedByAnAbsolutePath) {
  namespace fs = std::filesystem;
  TempDir dir("absolute-bank");
  const std::string bank = std::string(RAYGRADE_SOURCE_DIR) + "/problems";
  fs::create_directories(dir.path() / "course" / "week1");
  const fs::path file = dir.path() / "course" / "week1" / "practice.json";
  write_text(file, R"({"assignment": "practice", "bank": [")" + bank +
                       R"("], "variants": {"per_student": false},
                       "problems": ["variant-sphere", "sphere-hit"]})");
  AssignmentSpec spec = load_assignment(file.string());
  AssignmentBank problems = load_assignment_bank(spec);
  ASSERT_TRUE(problems.errors.empty());
  PracticeAssets assets = practice_assets(spec, "function createRaygrade() {}");
  // The page's files, written where the page's grader would find them.
  TempDir page("absolute-bank-page");
  std::string assignment_text;
  for (const auto& [name, text] : assets.files) {
    ASSERT_FALSE(fs::path(name).is_absolute()) << name;
    fs::create_directories((page.path() / name).parent_path());
    write_text(page.path() / name, text);
    if (name == assets.assignment) assignment_text = text;
  }
  EXPECT_EQ(assignment_text.find("\"" + bank), std::string::npos) << assignment_text;
  AssignmentSpec in_page = load_assignment((page.path() / assets.assignment).string());
  EXPECT_EQ(in_page.id, "practice");
  EXPECT_FALSE(in_page.per_student);
  AssignmentBank found = load_assignment_bank(in_page);
  EXPECT_TRUE(found.errors.empty()) << format_diagnostic(found.errors.front());
  ASSERT_EQ(found.problems.size(), 2u);
  EXPECT_EQ(found.problems[0]->id, "variant-sphere");
  EXPECT_EQ(found.problems[1]->id, "sphere-hit");
  Handout generic =
      make_handout(spec, student_problems(spec, problems.problems, ""), nullptr, &assets);
  EXPECT_NE(generic.html.find("<script>function createRaygrade() {}</script>"), std::string::npos);
  EXPECT_EQ(generic.html.find("stand_in"), std::string::npos);
  // A bank named relative to the assignment travels as it was written.
  write_text(file, R"({"assignment": "practice", "bank": "../../problems",
                       "problems": ["sphere-hit"]})");
  fs::create_directories(dir.path() / "problems");
  fs::copy_file(bank + "/sphere.json", dir.path() / "problems" / "sphere.json");
  PracticeAssets relative = practice_assets(load_assignment(file.string()), "");
  EXPECT_EQ(relative.files.front().second, read_text(file));
}

}  // namespace
}  // namespace raygrade
