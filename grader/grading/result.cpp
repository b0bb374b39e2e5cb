// GradeResult helpers and its JSON form.
#include "grading/result.h"

namespace raygrade {

const char* to_string(PartStatus s) {
  switch (s) {
    case PartStatus::kRight: return "right";
    case PartStatus::kPartial: return "partial";
    case PartStatus::kWrong: return "wrong";
    case PartStatus::kMissing: return "missing";
  }
  return "missing";
}

double GradeResult::fraction() const {
  if (max_score > 0) return score / max_score;
  for (const auto& p : parts) {
    if (p.status != PartStatus::kRight) return 0;
  }
  return answered ? 1 : 0;
}

bool GradeResult::has_mistake(std::string_view id) const {
  for (const auto& m : mistakes) {
    if (m.id == id) return true;
  }
  return false;
}

nlohmann::json result_json(const GradeResult& r) {
  nlohmann::json parts = nlohmann::json::array();
  for (const auto& p : r.parts) {
    parts.push_back({{"name", p.name},
                     {"points", p.points},
                     {"max_points", p.max_points},
                     {"status", to_string(p.status)},
                     {"feedback", p.feedback}});
  }
  nlohmann::json mistakes = nlohmann::json::array();
  for (const auto& m : r.mistakes) {
    mistakes.push_back({{"id", m.id}, {"kind", m.kind}, {"part", m.part}, {"message", m.message}});
  }
  return {
      {"problem", r.problem_id},  {"title", r.title},       {"score", r.score},
      {"max_score", r.max_score}, {"answered", r.answered}, {"parts", parts},
      {"mistakes", mistakes},     {"notes", r.notes},       {"carried_forward", r.carried_forward}};
}

}  // namespace raygrade
