// raygrade report: what a class got wrong, and why (docs/report.md): report.json, report.html
// and each student's feedback page in --out.
#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <set>

#include "assignments/feedback.h"
#include "assignments/grading.h"
#include "assignments/platforms/platforms.h"
#include "assignments/roster.h"
#include "assignments/variants.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "core/parallel.h"
#include "grading/outputs.h"
#include "reports/class_report.h"

namespace raygrade::cli {
// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace report_internal {

struct ReportOptions {
  std::vector<std::string> problems = {"problems"};
  std::vector<std::string> submissions;
  std::string assignment;
  std::string roster;
  std::string out;
  unsigned jobs = 0;
};

// One graded submission with what the report needs besides the grade.
// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct Handed {
  SubmissionGrade grade;
  nlohmann::json answers;                          // the submission's "answers"
  std::shared_ptr<std::vector<Problem>> problems;  // the student's variants (assignment)
};

// Grades submissions to an assignment, each as its student's variant, with full feedback.
class AssignmentSource {
 public:
  AssignmentSource(const ReportOptions& o, std::vector<Diagnostic>& errors)
      : spec_(load_assignment(o.assignment)), bank_(load_assignment_bank(spec_)) {
    errors = bank_.errors;
    AssignmentGradeOptions options;
    options.feedback = FeedbackPolicy::kFull;
    if (!o.roster.empty()) options.roster = load_roster(o.roster);
    grader_ = std::make_unique<AssignmentGrader>(spec_, bank_.problems, options);
  }
  bool complete() const { return bank_.problems.size() == spec_.problems.size(); }
  std::string title() const { return spec_.title.empty() ? spec_.id : spec_.title; }
  std::vector<const Problem*> problems() const { return bank_.problems; }

  Handed grade(const std::string& path, std::optional<FileIdentity> seen) const {
    Handed h;
    JsonLimits limits = JsonLimits::submission();
    limits.expected = seen;
    auto file = load_json_file(path, limits);
    Cursor root(file);
    if (!root.is_object()) root.fail("a submission is a JSON object", "type");
    StudentIdentity who = grader_->identify(root);
    h.problems = std::make_shared<std::vector<Problem>>(
        student_problems(spec_, bank_.problems, student_key(who)));
    Assignment graders(*h.problems);
    if (!graders.errors().empty()) throw Error(graders.errors().front());
    h.grade = graders.grade(file);
    h.grade.identity = who;
    // A submission that names nobody (numbers that are everyone's) is its file.
    h.grade.student = who.empty() ? student_of_file(path) : who.display();
    h.grade.score = h.grade.max_score = 0;
    for (auto& r : h.grade.results) {
      for (const auto& ap : spec_.problems)
        if (ap.id == r.problem_id && ap.points) scale_points(r, *ap.points);
      h.grade.score += r.score;
      h.grade.max_score += r.max_score;
    }
    if (auto a = root.find("answers"); a && a->json().is_object()) h.answers = a->json();
    return h;
  }

 private:
  AssignmentSpec spec_;
  AssignmentBank bank_;
  std::unique_ptr<AssignmentGrader> grader_;
};

// One student of the report from a graded submission: an answer per problem, in the problems'
// order. Its variants are the submission's and live as long as `h`.
ClassStudent class_student(const Handed& h, const std::vector<const Problem*>& problems,
                           std::string id, std::string page) {
  ClassStudent s{std::move(id), h.grade.identity.name, std::move(page), {}};
  for (std::size_t p = 0; p < problems.size(); ++p) {
    ClassAnswer a;
    for (const auto& r : h.grade.results)
      if (r.problem_id == problems[p]->id) a.result = r;
    if (a.result.problem_id.empty()) {
      a.result.problem_id = problems[p]->id;
      a.result.answered = false;
    }
    if (h.answers.contains(problems[p]->id)) a.answer = h.answers[problems[p]->id];
    a.variant = h.problems ? &(*h.problems)[p] : problems[p];
    s.answers.push_back(std::move(a));
  }
  return s;
}

// A graded submission and its student's feedback page.
// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct Graded {
  Handed handed;
  std::string page;  // the page's HTML
};

int run_report(const ReportOptions& o, bool problems_given) {
  if (problems_given && !o.assignment.empty()) {
    fmt::print(stderr, "raygrade report: --problems does not go with --assignment\n");
    return kExitBadInput;
  }
  std::vector<Diagnostic> errors;
  std::unique_ptr<AssignmentSource> source;
  Bank bank;
  std::unique_ptr<Assignment> plain;
  std::vector<const Problem*> problems;
  std::string title = "problems";
  if (!o.assignment.empty()) {
    source = std::make_unique<AssignmentSource>(o, errors);
    for (const auto& e : errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
    if (!source->complete()) return kExitBadInput;
    problems = source->problems();
    title = source->title();
  } else {
    bank = load_bank(o.problems);
    errors = bank.errors;
    for (const auto& e : errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
    plain = std::make_unique<Assignment>(bank.problems);
    for (const auto& g : plain->graders()) problems.push_back(&g.problem());
  }
  std::vector<StudentIdentity> roster;
  if (!o.roster.empty()) roster = load_roster(o.roster);
  std::vector<Diagnostic> file_errors;
  std::vector<std::optional<FileIdentity>> seen;
  std::vector<std::string> files = submission_files(o.submissions, file_errors, &seen);
  for (const auto& e : file_errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  unsigned jobs = o.jobs > 0 ? o.jobs : default_jobs();
  std::filesystem::path out(o.out);
  std::filesystem::create_directories(out / "students");
  const GradeFormat* html = find_grade_format("html");
  std::vector<std::string> ids, titles;
  for (const Problem* p : problems) {
    ids.push_back(p->id);
    titles.push_back(p->title);
  }
  // The report keeps of each student what it shows (ClassReportBuilder); the submissions are
  // graded a chunk at a time, each page written as soon as its chunk is graded, so that
  // memory does not grow with the class.
  ClassReportBuilder report(title, ids, titles, problems);
  std::map<std::string, std::string> page_of;  // student → page, by the first submission
  std::set<std::string> names = {"report"};
  std::set<const StudentIdentity*> handed_in;
  std::size_t handed = 0;
  const std::size_t chunk = std::max<std::size_t>(64, 16 * std::size_t{jobs});
  for (std::size_t from = 0; from < files.size(); from += chunk) {
    std::size_t n = std::min(chunk, files.size() - from);
    auto graded =
        parallel_map<std::optional<Graded>>(n, jobs, [&](std::size_t k) -> std::optional<Graded> {
          const std::string& file = files[from + k];
          try {
            Graded g;
            const std::optional<FileIdentity>& expected = seen[from + k];
            if (source) {
              g.handed = source->grade(file, expected);
            } else {
              g.handed = Handed{plain->grade_file(file, expected), {}, nullptr};
              if (!g.handed.grade.gradable) throw Error(*g.handed.grade.fault);
              JsonLimits limits = JsonLimits::submission();
              limits.expected = expected;
              auto json = load_json_file(file, limits);
              if (json->root.contains("answers")) g.handed.answers = json->root["answers"];
            }
            g.page = html->render(g.handed.grade, 0);
            return g;
          } catch (const Error& e) {
            fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
            return std::nullopt;
          }
        });
    // A student who handed in several submissions is counted once, by the last in the order
    // the files are listed, at the place of the first.
    for (auto& g : graded) {
      if (!g) continue;
      ++handed;
      const Handed& h = g->handed;
      std::string id = h.grade.identity.id.empty() ? h.grade.student : h.grade.identity.id;
      auto [it, fresh] = page_of.emplace(id, "");
      if (fresh) it->second = "students/" + unique_file_name(id, names) + ".html";
      write_file_atomically(out / it->second, g->page, false);
      report.add(class_student(h, problems, id, it->second));
      if (!roster.empty())
        if (const StudentIdentity* e = find_on_roster(roster, h.grade.identity))
          handed_in.insert(e);
      g.reset();
    }
  }
  // The roster's students whom no graded submission is from, in the roster's order. A
  // submission that could not be read counts for nobody: its student is listed too, and the
  // exit code says that a file was left out.
  std::vector<AbsentStudent> absent;
  for (const auto& e : roster)
    if (!handed_in.count(&e)) absent.push_back({e.id, e.name});
  report.set_no_submission(std::move(absent));
  nlohmann::json json = report.json(jobs);
  write_file_atomically(out / "report.json", json.dump(1) + "\n", false);
  write_file_atomically(out / "report.html", class_report_html(json), false);
  flush_folder(o.out);
  fmt::print(stderr, "Reported {} students on {} problems into {}.\n", report.students(),
             problems.size(), o.out);
  if (!o.roster.empty())
    fmt::print(stderr, "No submission from {} students of the roster.\n",
               json["no_submission"].size());
  bool bad = handed != files.size() || !errors.empty() || !file_errors.empty();
  return bad ? kExitBadInput : kExitOk;
}

}  // namespace report_internal

Runner setup_report(CLI::App& sub) {
  using namespace report_internal;  // NOLINT: this file's own functions
  auto o = std::make_shared<ReportOptions>();
  auto* problems =
      sub.add_option("--problems", o->problems, "the bank: a file or folder (repeat for more)")
          ->allow_extra_args(false)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub.add_option("submissions", o->submissions, "submission files or folders")->required();
  sub.add_option("--assignment", o->assignment,
                 "an assignment file: each submission is graded as the variant of its student");
  sub.add_option("--roster", o->roster,
                 "a roster CSV (id, name, email): its students who handed in nothing are listed "
                 "apart; with --assignment, every student must be on it");
  sub.add_option("--out", o->out, "the folder for report.html, report.json and students/")
      ->required();
  sub.add_option("-j,--jobs", o->jobs, "threads (default: one per core); the report is the same");
  return [o, problems] { return run_report(*o, problems->count() > 0); };
}

}  // namespace raygrade::cli
