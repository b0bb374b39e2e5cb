// Grading submissions to an assignment.
#include "assignments/grading.h"

#include <fmt/format.h>

#include <filesystem>

#include "assignments/feedback.h"
#include "assignments/roster.h"
#include "assignments/variants.h"

namespace raygrade {

// One student's problems, prepared for grading.
struct AssignmentGrader::Student {
  std::vector<Problem> problems;
  std::unique_ptr<Assignment> graders;
};

AssignmentGrader::AssignmentGrader(const AssignmentSpec& spec, std::vector<const Problem*> problems,
                                   AssignmentGradeOptions options)
    : spec_(spec), problems_(std::move(problems)), options_(std::move(options)) {
  for (const auto* p : problems_) ids_.push_back(p->id);
}

AssignmentGrader::~AssignmentGrader() = default;

const AssignmentGrader::Student& AssignmentGrader::student(const std::string& key) {
  std::string k = spec_.per_student ? key : "";
  {
    std::lock_guard lock(students_mutex_);
    auto it = students_.find(k);
    if (it != students_.end()) return *it->second;
  }
  // Drawn outside the lock, so that threads grading different students draw at once; two
  // threads drawing the same student draw the same problems, and the first one kept is used.
  auto s = std::make_unique<Student>();
  s->problems = student_problems(spec_, problems_, k);
  s->graders = std::make_unique<Assignment>(s->problems);
  if (!s->graders->errors().empty()) throw Error(s->graders->errors().front());
  std::lock_guard lock(students_mutex_);
  return *students_.emplace(k, std::move(s)).first->second;
}

namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void check_uploader(const Cursor& root, const StudentIdentity& who,
                    const std::vector<StudentIdentity>& uploaders) {
  std::string accounts;
  for (const auto& u : uploaders) {
    if (!who.email.empty() ? lower(u.email) == lower(who.email)
                           : !who.name.empty() && u.name == who.name) {
      return;
    }
    accounts += fmt::format("{}'{}'", accounts.empty() ? "" : ", ", u.email);
  }
  root.at("student").fail(
      who.email.empty() && who.name.empty()
          ? fmt::format("the submission names its student by id alone; give the email of the "
                        "account that uploads it ({})",
                        accounts)
          : fmt::format("the submission names '{}', who is not the account that uploaded it ({})",
                        who.email.empty() ? who.name : who.email, accounts),
      "not-uploader");
}

}  // namespace

StudentIdentity AssignmentGrader::identify(const Cursor& root) const {
  auto who = read_student(root);
  if (!who) {
    root.fail(fmt::format("the submission names no student: add \"student\": {{\"id\": "
                          "\"...\"}} (each student of '{}' has their own numbers)",
                          spec_.id),
              "no-student");
  }
  if (!options_.uploaders.empty()) check_uploader(root, *who, options_.uploaders);
  if (options_.roster.empty()) return *who;
  const StudentIdentity* entry = find_on_roster(options_.roster, *who);
  if (!entry) {
    root.at("student").fail(fmt::format("'{}' is not on the roster", student_key(*who)),
                            "not-on-roster");
  }
  return *entry;
}

SubmissionGrade AssignmentGrader::grade_file(const std::string& path) {
  std::shared_ptr<const SourceFile> file;
  StudentIdentity who;
  SubmissionGrade g;
  try {
    file = load_json_file(path, JsonLimits::submission());
    Cursor root(file);
    if (!root.is_object()) root.fail("a submission is a JSON object", "type");
    who = identify(root);
    g = student(student_key(who)).graders->grade(file);
  } catch (const Error& e) {
    g.file = path;
    g.gradable = false;
    g.results.clear();
    Diagnostic d = e.diagnostic();
    if (d.file.empty()) d.file = path;
    if (d.line == 0 && !d.path.empty() && file)
      std::tie(d.line, d.column) = locate(file->text, d.path);
    g.fault = d;
  }
  if (!who.empty()) {
    g.identity = who;
    g.student = who.display();
  } else if (g.student.empty()) {
    g.student = std::filesystem::path(path).stem().string();
  }
  g.score = g.max_score = 0;
  for (auto& r : g.results) {
    for (std::size_t i = 0; i < spec_.problems.size(); ++i) {
      const AssignmentProblem& ap = spec_.problems[i];
      if (ap.id != r.problem_id) continue;
      if (ap.points) scale_points(r, *ap.points);
      apply_feedback_policy(
          r, options_.feedback ? *options_.feedback : spec_.policy(ap, options_.now));
    }
    g.score += r.score;
    g.max_score += r.max_score;
  }
  return g;
}

}  // namespace raygrade
