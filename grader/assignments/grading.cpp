// Grading submissions to an assignment.
#include "assignments/grading.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "assignments/feedback.h"
#include "assignments/roster.h"
#include "assignments/variants.h"
#include "core/internal_error.h"

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
  per_student_numbers_ = has_per_student_numbers(spec_, problems_);
}

AssignmentGrader::~AssignmentGrader() = default;

std::shared_ptr<const AssignmentGrader::Student> AssignmentGrader::student(const std::string& key) {
  std::string k = per_student_numbers_ ? key : "";
  {
    std::lock_guard lock(students_mutex_);
    auto it = students_.find(k);
    if (it != students_.end()) {
      recent_.splice(recent_.begin(), recent_, it->second.second);
      return it->second.first;
    }
  }
  // Drawn outside the lock, so that threads grading different students draw at once; two
  // threads drawing the same student draw the same problems, and the first one kept is used.
  auto s = std::make_shared<Student>();
  s->problems = student_problems(spec_, problems_, k);
  s->graders = std::make_unique<Assignment>(s->problems);
  if (!s->graders->errors().empty()) throw Error(s->graders->errors().front());
  std::lock_guard lock(students_mutex_);
  auto [it, added] = students_.try_emplace(k, s, recent_.end());
  if (!added) return it->second.first;
  recent_.push_front(k);
  it->second.second = recent_.begin();
  // A class's submissions come one or two per student: keep the few most recent, so that
  // memory stays flat in the number of students (a thread grading one holds its own pointer).
  while (students_.size() > kCachedStudents) {
    students_.erase(recent_.back());
    recent_.pop_back();
  }
  return s;
}

namespace {

// The submission's "submitted" time, when it gives one that reads as a date and time; one
// that does not is a warning, and the file's time orders it instead.
std::optional<std::int64_t> submitted_time(const Cursor& root, SubmissionGrade& g) {
  auto at = root.find("submitted");
  if (!at) return std::nullopt;
  std::optional<std::int64_t> t =
      at->json().is_string() ? parse_time(at->json().get<std::string>()) : std::nullopt;
  if (!t) {
    Diagnostic d{g.file,
                 "/submitted",
                 0,
                 0,
                 Severity::kWarning,
                 "submitted is not a date and time with its zone (2026-12-04T23:59:00Z): the "
                 "file's time orders this submission",
                 "invalid"};
    g.findings.push_back(std::move(d));
  }
  return t;
}

}  // namespace

StudentIdentity AssignmentGrader::identify(const Cursor& root) const {
  std::optional<StudentIdentity> claimed = read_student(root);
  if (!options_.uploaders.empty()) return identify_uploader(root, claimed);
  if (!claimed) {
    // Numbers that are the same for everyone are graded without a name (the generic set),
    // unless a roster says who may hand in.
    if (!per_student_numbers_ && options_.roster.empty()) return StudentIdentity{};
    root.fail(fmt::format("the submission names no student: add \"student\": {{\"id\": "
                          "\"...\"}} ({})",
                          per_student_numbers_
                              ? fmt::format("each student of '{}' has their own numbers", spec_.id)
                              : "only the roster's students may hand in"),
              "no-student");
  }
  if (options_.roster.empty()) return *claimed;
  RosterMatch m = match_on_roster(options_.roster, *claimed);
  if (!m.entry) root.at("student").fail(m.problem, m.code);
  return *m.entry;
}

StudentIdentity AssignmentGrader::identify_uploader(
    const Cursor& root, const std::optional<StudentIdentity>& claimed) const {
  const auto& uploaders = options_.uploaders;
  std::string accounts;
  for (const auto& u : uploaders)
    accounts += fmt::format("{}'{}'", accounts.empty() ? "" : ", ", u.email);
  // An empty address is nobody's: not that of an account whose address is empty too.
  auto uploaded_by = [&](const std::string& email) {
    std::string key = email_key(email);
    return !key.empty() && std::any_of(uploaders.begin(), uploaders.end(),
                                       [&](const auto& u) { return email_key(u.email) == key; });
  };
  if (options_.roster.empty()) {
    // No roster: an account cannot be tied to a student id, so nothing may depend on one.
    if (per_student_numbers_) {
      root.fail(fmt::format("this autograder has no roster, so it cannot tell which student's "
                            "numbers the account {} was given; please tell your instructor "
                            "(raygrade export {} --roster)",
                            accounts, options_.uploads_platform),
                "no-roster");
    }
    if (claimed && !email_key(claimed->email).empty() && !uploaded_by(claimed->email)) {
      root.at("student").fail(
          fmt::format("the submission names '{}', who is not the account that uploaded it ({})",
                      claimed->email, accounts),
          "not-uploader");
    }
    for (const auto& u : uploaders) {
      if (!claimed || email_key(claimed->email).empty() ||
          email_key(u.email) == email_key(claimed->email))
        return StudentIdentity{u.name, "", u.email};
    }
    // uploaded_by(claimed->email) held above, so one of the accounts matched.
    throw InternalError("identify_uploader: no uploading account matched the one it named");
  }
  // The roster entries of the accounts that uploaded the submission: who it is from.
  std::vector<const StudentIdentity*> own;
  for (const auto& s : options_.roster) {
    if (!trimmed(s.email).empty() && uploaded_by(s.email)) own.push_back(&s);
  }
  if (own.empty()) {
    root.fail(fmt::format("the account that uploaded this submission ({}) is not on the "
                          "course's roster; please tell your instructor",
                          accounts),
              "not-on-roster");
  }
  if (!claimed) {
    if (own.size() == 1) return *own.front();
    root.fail(fmt::format("a group upload ({}) must name its student: add \"student\": "
                          "{{\"id\": \"...\"}}",
                          accounts),
              "no-student");
  }
  RosterMatch m = match_on_roster(options_.roster, *claimed);
  if (!m.entry) root.at("student").fail(m.problem, m.code);
  if (std::find(own.begin(), own.end(), m.entry) == own.end()) {
    root.at("student").fail(
        fmt::format("the submission names student '{}', who is not the account that uploaded "
                    "it ({}, student '{}'): upload your own answers",
                    m.entry->id, accounts, own.front()->id),
        "not-uploader");
  }
  return *m.entry;
}

SubmissionGrade AssignmentGrader::grade_file(const std::string& path,
                                             std::optional<FileIdentity> seen) {
  JsonLimits limits = JsonLimits::submission();
  limits.expected = seen;
  SubmissionGrade g = grade_loaded(
      path, [&] { return load_json_file(path, limits); },
      [this](const Cursor& root) { return identify(root); });
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) g.file_time = st.st_mtim.tv_sec;
  return g;
}

SubmissionGrade AssignmentGrader::grade_handed_in(const std::string& name, std::string text,
                                                  std::int64_t modified,
                                                  const StudentIdentity& owner,
                                                  std::string_view platform) {
  auto who = [&](const Cursor& root) {
    std::optional<StudentIdentity> claimed = read_student(root);
    if (!claimed) return owner;
    RosterMatch m = match_on_roster(options_.roster, *claimed);
    if (m.entry != &owner && (!m.entry || m.entry->id != owner.id)) {
      root.at("student").fail(
          fmt::format("the submission names {}, but {} says student '{}' ({}) handed it in: "
                      "hand in your own answers",
                      m.entry ? fmt::format("student '{}'", m.entry->id) : "someone else", platform,
                      owner.id, owner.display()),
          "not-uploader");
    }
    return owner;
  };
  SubmissionGrade g = grade_loaded(
      name, [&] { return parse_json_text(name, std::move(text), JsonLimits::submission()); }, who);
  g.file_time = modified;
  // The platform says who handed the file in: a file that will not parse, or that names someone
  // else, is that student's rejected submission, not "no submission".
  if (!g.gradable) g.claimed = owner;
  return g;
}

SubmissionGrade AssignmentGrader::grade_loaded(
    const std::string& path, const std::function<std::shared_ptr<const SourceFile>()>& load,
    const std::function<StudentIdentity(const Cursor&)>& identify_student) {
  std::shared_ptr<const SourceFile> file;
  StudentIdentity who;
  SubmissionGrade g;
  try {
    file = load();
    Cursor root(file);
    if (!root.is_object()) root.fail("a submission is a JSON object", "type");
    who = identify_student(root);
    g = student(student_key(who))->graders->grade(file);
    g.submitted = submitted_time(root, g);
  } catch (const Error& e) {
    g.file = path;
    g.gradable = false;
    g.results.clear();
    Diagnostic d = e.diagnostic();
    if (d.file.empty()) d.file = path;
    if (d.line == 0 && !d.path.empty() && file)
      std::tie(d.line, d.column) = locate(file->text, d.path);
    g.fault = d;
    if (who.empty() && file) {
      try {
        if (auto c = read_student(Cursor(file))) g.claimed = *c;
      } catch (const Error&) {
        // It names nobody readable: no row shows the rejection.
      }
    }
  } catch (const std::bad_alloc&) {
    // Out of memory costs this submission alone; the batch goes on, and its exit code says so.
    g = SubmissionGrade{};
    g.file = path;
    g.gradable = false;
    g.fault = Diagnostic{path,
                         "",
                         0,
                         0,
                         Severity::kError,
                         "not graded: out of memory while grading this submission",
                         "resource"};
  }
  if (!who.empty()) {
    g.identity = who;
    g.student = who.display();
  } else if (g.student.empty()) {
    g.student = student_of_file(path);
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
