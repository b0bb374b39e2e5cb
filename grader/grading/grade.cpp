// Grader: preparing a problem, and grading answers to it.
#include "grading/grade.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

#include "core/internal_error.h"
#include "grading/bank_mistakes.h"
#include "grading/kind_grader.h"
#include "json/cursor.h"

namespace raygrade {

double PointsPolicy::of(std::string_view part) const {
  for (const auto& [name, pts] : parts) {
    if (name == part) return pts;
  }
  return 0;
}

double PointsPolicy::total() const {
  double t = 0;
  for (const auto& [name, pts] : parts) t += pts;
  return t;
}

PointsPolicy read_points_policy(const Problem& p,
                                const std::vector<std::pair<std::string, double>>& defaults) {
  PointsPolicy policy;
  policy.parts = defaults;
  if (!p.source.contains("points")) return policy;
  Cursor c(p.source_file, &p.source.at("points"), p.path + "/points");
  if (c.json().is_number()) {
    double total = c.number();
    if (total < 0) c.fail("points must not be negative", "range");
    double sum = policy.total();
    for (auto& [name, pts] : policy.parts) pts = sum > 0 ? pts * total / sum : 0;
    return policy;
  }
  if (!c.is_object()) c.fail("points is a number (the total) or an object of parts", "type");
  std::vector<std::string> keys = {"carried_forward"};
  for (const auto& [name, pts] : defaults) keys.push_back(name);
  c.allow_only(keys);
  for (auto& [name, pts] : policy.parts) {
    if (!c.has(name)) continue;
    pts = c.at(name).number();
    if (pts < 0) c.at(name).fail("points must not be negative", "range");
  }
  if (c.has("carried_forward")) {
    policy.carried_forward = c.at("carried_forward").number();
    if (policy.carried_forward < 0 || policy.carried_forward > 1) {
      c.at("carried_forward").fail("carried_forward is a fraction from 0 to 1", "range");
    }
  }
  return policy;
}

PartResult make_part(const GradingContext& c, const std::string& name, double credit,
                     std::vector<std::string> feedback) {
  PartResult p;
  p.name = name;
  p.max_points = c.points.of(name);
  credit = std::clamp(credit, 0.0, 1.0);
  p.points = p.max_points * credit;
  // A part worth nothing has no share to be partly earned: it is right or wrong.
  p.status = credit >= 1                      ? PartStatus::kRight
             : credit > 0 && p.max_points > 0 ? PartStatus::kPartial
                                              : PartStatus::kWrong;
  p.feedback = std::move(feedback);
  if (credit < 1 && p.feedback.empty()) {
    throw InternalError(fmt::format("part {} of {} earns {} without a reason", name,
                                    c.problem ? c.problem->id : "?", credit));
  }
  return p;
}

PartResult missing_part(const GradingContext& c, const std::string& name, std::string why) {
  PartResult p;
  p.name = name;
  p.max_points = c.points.of(name);
  p.status = PartStatus::kMissing;
  p.feedback.push_back(why.empty() ? fmt::format("No {} given.", name) : std::move(why));
  return p;
}

std::shared_ptr<const KindGrader> make_kind_grader(const Problem& p) {
  const KindEntry* entry = find_kind(p.kind);
  if (!entry) throw InternalError(fmt::format("problem {} has no kind of the table", p.id));
  switch (entry->grader) {
    case GraderFamily::kHits: return make_hits_grader(p);
    case GraderFamily::kCamera: return make_camera_grader(p);
    case GraderFamily::kFormula: return make_formula_grader(p);
    case GraderFamily::kRayTree: return make_ray_tree_grader(p);
    case GraderFamily::kFields: break;
  }
  return make_fields_grader(p);
}

Grader::Grader(const Problem& problem) : problem_(&problem), kind_(make_kind_grader(problem)) {
  auto own = std::make_shared<const BankMistakes>(problem);
  if (!own->empty()) bank_mistakes_ = std::move(own);
}

double Grader::max_score() const { return kind_->context().points.total(); }

double Grader::part_points(std::string_view part) const { return kind_->context().points.of(part); }

GradeResult Grader::unanswered() const {
  GradeResult r;
  r.problem_id = problem_->id;
  r.title = problem_->title;
  r.answered = false;
  r.max_score = max_score();
  r.notes.emplace_back("Not answered.");
  return r;
}

GradeResult Grader::grade(const nlohmann::json& answer, const GradeOptions& options) const {
  GradeResult r;
  r.problem_id = problem_->id;
  r.title = problem_->title;
  AnswerReader reader(answer, &options.file, options.path);
  if (!answer.is_object()) reader.fail("an answer is a JSON object", "type");
  kind_->grade(reader, r);
  // A mistake found in several values of one part is reported once.
  std::vector<FoundMistake> unique;
  for (auto& m : r.mistakes) {
    bool seen = std::any_of(unique.begin(), unique.end(), [&](const FoundMistake& u) {
      return u.id == m.id && u.part == m.part;
    });
    if (!seen) unique.push_back(std::move(m));
  }
  r.mistakes = std::move(unique);
  // A part that carries no points is not asked: not required when left out, and when given
  // it is checked as feedback, and the student is told that it does not count.
  std::vector<PartResult> kept;
  std::vector<std::string> unasked;
  for (auto& part : r.parts) {
    if (part.max_points == 0) {
      if (part.status == PartStatus::kMissing) continue;
      unasked.push_back(part.name);
    }
    kept.push_back(std::move(part));
  }
  r.parts = std::move(kept);
  if (!unasked.empty()) {
    r.notes.push_back(fmt::format(
        "Not asked in this problem (no points): {}. Checked and shown below, not counted.",
        fmt::join(unasked, ", ")));
  }
  for (const auto& part : r.parts) {
    r.score += part.points;
    r.max_score += part.max_points;
  }
  // Parts the kind did not list (a problem's points may name them) still count in the total.
  r.max_score = std::max(r.max_score, max_score());
  if (bank_mistakes_) bank_mistakes_->find(answer, r);
  return r;
}

GradeResult grade_answer(const Problem& problem, const nlohmann::json& answer,
                         const GradeOptions& options) {
  return Grader(problem).grade(answer, options);
}

}  // namespace raygrade
