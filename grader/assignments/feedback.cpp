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
// "intensity: ").
bool quotes_only_the_student(std::string_view s) {
  constexpr std::string_view kUnreadable = "could not read '";
  std::size_t name = 0;
  while (name < s.size() && (std::isalnum(static_cast<unsigned char>(s[name])) || s[name] == '_'))
    ++name;
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
    if (p.status != PartStatus::kRight) kept.push_back(status_sentence(p.status));
    for (const auto& s : p.feedback) {
      if (quotes_only_the_student(s)) kept.push_back(s);
    }
    p.feedback = std::move(kept);
  }
  for (auto& m : r.mistakes) {
    const MistakeInfo& info = mistake_info(m.id);
    m.message = fmt::format("{}. {}", info.title, info.explanation);
  }
  std::vector<std::string> notes;
  if (!r.answered) notes.push_back("Not answered.");
  if (r.carried_forward) {
    notes.push_back("Some credit is carried forward from your own earlier values.");
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
