// The instructor's report, gradebook and regrade over the stored submissions.
#include "serve/instructor.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "assignments/feedback.h"
#include "assignments/variants.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "grading/outputs.h"
#include "json/source.h"
#include "reports/class_report.h"
#include "serve/jwt.h"
#include "serve/lti.h"
#include "serve/roster.h"

namespace raygrade::serve {

namespace {

nlohmann::json answers_of(const SubmissionRecord& r) {
  nlohmann::json a = nlohmann::json::parse(r.answers, nullptr, false);
  return a.is_object() ? a : nlohmann::json::object();
}

// One student of the report: their last answers graded again as their own variant,
// `problems` (which the student's answers point into: they must outlive the report's add).
ClassStudent report_student(const CatalogEntry& e, const SubmissionRecord& r,
                            const std::vector<Problem>& problems) {
  std::string key = student_key_of(r.issuer, r.sub);
  Assignment graders(problems);
  nlohmann::json answers = answers_of(r);
  auto file = parse_json_text("answers.json", nlohmann::json{{"answers", answers}}.dump(),
                              JsonLimits::submission());
  SubmissionGrade g = graders.grade(file);
  ClassStudent s{key, r.sub, "", {}};
  for (std::size_t p = 0; p < problems.size(); ++p) {
    ClassAnswer a;
    for (const auto& res : g.results)
      if (res.problem_id == problems[p].id) a.result = res;
    if (a.result.problem_id.empty()) {
      a.result.problem_id = problems[p].id;
      a.result.answered = false;
    }
    const AssignmentProblem& ap = e.spec.problems[p];
    if (ap.points) scale_points(a.result, *ap.points);
    if (answers.contains(problems[p].id)) a.answer = answers[problems[p].id];
    a.variant = &problems[p];
    s.answers.push_back(std::move(a));
  }
  return s;
}

// On the class list: a learner of the course who has not left it.
bool enrolled(const Member& m) {
  return !m.user_id.empty() && m.status != "Deleted" && is_learner(m);
}

// The class list's members by user_id (the first of a user_id given twice); an empty user_id
// names nobody.
std::map<std::string, const Member*> members_by_id(const ClassList& list) {
  std::map<std::string, const Member*> out;
  for (const auto& m : list.members)
    if (!m.user_id.empty()) out.emplace(m.user_id, &m);
  return out;
}

const Member* find_member(const std::map<std::string, const Member*>& members,
                          const std::string& sub) {
  auto it = members.find(sub);
  return it == members.end() ? nullptr : it->second;
}

std::string status_note(const Member& m) {
  return m.status == "Inactive" ? "inactive in the LMS" : "";
}

// The row of an enrolled learner who handed in nothing, as RosterGradebook writes one.
std::string absent_row(const CatalogEntry& e, const std::string& issuer, const Member& m) {
  std::string s = csv_cell(m.name.empty() ? m.user_id : m.name) + "," +
                  csv_cell(student_key_of(issuer, m.user_id)) + "," + csv_cell(m.email) + ",";
  for (std::size_t p = 0; p < e.grader->problem_ids().size(); ++p) s += "," + format_points(0.0);
  std::string note = status_note(m);
  return s + fmt::format(",{},{},{}\n", format_points(0.0), format_points(e.points()),
                         csv_cell(note.empty() ? "no submission" : "no submission; " + note));
}

}  // namespace

std::vector<SubmissionRecord> last_per_student(const std::vector<SubmissionRecord>& all) {
  std::vector<SubmissionRecord> out;
  std::map<std::string, std::size_t> at;
  for (const auto& r : all) {
    auto [it, fresh] = at.emplace(r.sub, out.size());
    if (fresh) {
      out.push_back(r);
    } else {
      out[it->second] = r;
    }
  }
  return out;
}

std::string class_report_page(const CatalogEntry& e, const std::vector<SubmissionRecord>& all,
                              const ClassList& list) {
  std::vector<std::string> ids, titles;
  for (const Problem* p : e.bank.problems) {
    ids.push_back(p->id);
    titles.push_back(p->title);
  }
  ClassReportBuilder report(e.title(), ids, titles, e.bank.problems);
  // The variants of a student live while they are added: the builder keeps their numbers.
  std::set<std::string> handed_in;
  std::map<std::string, const Member*> members = members_by_id(list);
  for (const auto& r : last_per_student(all)) {
    std::vector<Problem> problems =
        student_problems(e.spec, e.bank.problems, student_key_of(r.issuer, r.sub));
    ClassStudent s = report_student(e, r, problems);
    const Member* m = find_member(members, r.sub);
    if (m && !m->name.empty()) s.name = m->name;
    report.add(s);
    handed_in.insert(r.sub);
  }
  std::vector<AbsentStudent> absent;
  for (const auto& m : list.members) {
    if (!enrolled(m) || handed_in.count(m.user_id)) continue;
    std::string note = status_note(m);
    absent.push_back({m.user_id, m.name.empty() ? note
                                 : note.empty() ? m.name
                                                : m.name + ", " + note});
  }
  report.set_no_submission(std::move(absent));
  std::string page = class_report_html(report.json(1));
  std::size_t main = page.find("<main>");
  if (!list.note.empty() && main != std::string::npos)
    page.insert(main + 6,
                "<p id=\"roster-note\" role=\"status\">" + html_escape(list.note) + "</p>");
  return page;
}

std::string gradebook_of(const CatalogEntry& e, const std::vector<SubmissionRecord>& all,
                         const ClassList& list) {
  std::string csv = gradebook_csv_header(e.grader->problem_ids());
  std::vector<SubmissionRecord> last = last_per_student(all);
  std::map<std::string, const Member*> members = members_by_id(list);
  std::map<std::string, const SubmissionRecord*> last_of;
  for (const auto& r : last) last_of.emplace(r.sub, &r);
  auto row = [&](const SubmissionRecord& r) {
    const Member* m = find_member(members, r.sub);
    StudentIdentity who{m ? m->name : "", student_key_of(r.issuer, r.sub), m ? m->email : ""};
    SubmissionGrade g = grade_answers(e, who, answers_of(r), r.created);
    csv += gradebook_csv_row(g, e.grader->problem_ids());
  };
  // The roster's learners first, in its order; then whoever else submitted.
  std::set<std::string> written;
  for (const auto& m : list.members) {
    if (!enrolled(m) || !written.insert(m.user_id).second) continue;
    if (auto it = last_of.find(m.user_id); it != last_of.end()) {
      row(*it->second);
    } else {
      csv += absent_row(e, list.issuer, m);
    }
  }
  for (const auto& r : last)
    if (!written.count(r.sub)) row(r);
  return csv;
}

std::vector<Regraded> regrade_with(const CatalogEntry& e, const std::vector<SubmissionRecord>& all,
                                   const std::vector<BankFile>& files,
                                   const std::string& data_dir) {
  std::filesystem::path folder = std::filesystem::path(data_dir) / "banks" / random_token(9);
  std::filesystem::create_directories(folder);
  std::set<std::string> taken;
  for (const auto& f : files) {
    std::string name = f.name.ends_with(".json") ? f.name.substr(0, f.name.size() - 5) : f.name;
    write_file_atomically(folder / (unique_file_name(name, taken) + ".json"), f.text, false);
  }
  AssignmentSpec spec = e.spec;
  spec.bank = {folder.string()};
  AssignmentBank bank = load_assignment_bank(spec);
  if (bank.problems.size() != spec.problems.size()) {
    std::string why =
        bank.errors.empty() ? "it lacks a problem of the assignment" : bank.errors.front().message;
    throw Refusal(400, "the new bank cannot grade this assignment: " + why);
  }
  AssignmentGradeOptions options;
  options.feedback = FeedbackPolicy::kFull;
  AssignmentGrader grader(spec, bank.problems, options);
  std::vector<Regraded> changed;
  for (const auto& r : last_per_student(all)) {
    StudentIdentity who{"", student_key_of(r.issuer, r.sub), ""};
    nlohmann::json submission = {{"answers", answers_of(r)}};
    SubmissionGrade g =
        grader.grade_handed_in("answers.json", submission.dump(), r.created, who, "the LTI launch");
    // Points are sums of a few parts' points: a change below a millionth is rounding.
    if (g.gradable && std::abs(g.score - r.score) > 1e-6)
      changed.push_back({r.sub, r.score, g.score, g.max_score});
  }
  return changed;
}

}  // namespace raygrade::serve
