// Feedback policies and points.
#include "assignments/feedback.h"

#include <fmt/format.h>

#include <cctype>

#include "grading/mistakes.h"

namespace raygrade {
namespace {

// What a part's status says under the "mistakes" policy: no number, no name from the answer.
std::string status_sentence(PartStatus s) {
  switch (s) {
    case PartStatus::kRight: return "Right.";
    case PartStatus::kPartial: return "Partly right: check this part again.";
    case PartStatus::kWrong: return "Not right: check this part again.";
    case PartStatus::kMissing: return "Not given.";
  }
  return "";
}

// A sentence about what the student typed and the grader could not read quotes only the
// student's own text, so it stays; the graders may start it with the name of the value ("t: ",
// "I1.reflected: ", "intensity channel r: "). A name with other characters may hold a reference
// value ("Hit 1 (ball at t = 5): "), so its sentence goes.
bool quotes_only_the_student(std::string_view s) {
  constexpr std::string_view kUnreadable = "could not read '";
  auto in_name = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == ' ';
  };
  std::size_t name = 0;
  while (name < s.size() && in_name(s[name])) ++name;
  if (name > 0 && s.substr(name).starts_with(": ")) s.remove_prefix(name + 2);
  return s.starts_with(kUnreadable);
}

}  // namespace

void apply_feedback_policy(GradeResult& r, FeedbackPolicy policy) {
  if (policy == FeedbackPolicy::kFull) return;
  if (policy == FeedbackPolicy::kScore) {
    for (auto& p : r.parts) p.feedback.clear();
    r.mistakes.clear();
    r.notes.clear();
    return;
  }
  for (auto& p : r.parts) {
    std::vector<std::string> kept;
    if (p.max_points == 0) {
      kept.emplace_back("Checked, not counted: this problem gives it no points.");
    } else if (p.status != PartStatus::kRight) {
      kept.push_back(status_sentence(p.status));
    }
    for (const auto& s : p.feedback) {
      if (quotes_only_the_student(s)) kept.push_back(s);
    }
    p.feedback = std::move(kept);
  }
  for (auto& m : r.mistakes) {
    if (m.kind == "bank") continue;  // the bank's own mistake: its message is the lesson
    const MistakeInfo& info = mistake_info(m.id);
    m.message = fmt::format("{}. {}", info.title, info.explanation);
  }
  std::vector<std::string> notes;
  if (!r.answered) notes.emplace_back("Not answered.");
  if (r.carried_forward) {
    notes.emplace_back("Some credit is carried forward from your own earlier values.");
  }
  r.notes = std::move(notes);
}

void scale_points(GradeResult& r, double points) {
  if (r.max_score <= 0) return;
  double k = points / r.max_score;
  r.score *= k;
  r.max_score = points;
  for (auto& p : r.parts) {
    p.points *= k;
    p.max_points *= k;
  }
}

}  // namespace raygrade
