// GradeResult: the grade of one answer to one problem, part by part, with the feedback and
// the named mistakes found.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace raygrade {

enum class PartStatus { kRight, kPartial, kWrong, kMissing };

const char* to_string(PartStatus s);

// A mistake of the catalogue (docs/grading.md) recognised in the student's numbers.
struct FoundMistake {
  std::string id;       // "sign-slip-d", stable
  std::string kind;     // "sign", "root-choice", "orientation", "convention", "algebra"
  std::string part;     // the part or step it was found in ("t", "steps/D")
  std::string message;  // specific, kind feedback
};

// One graded part of an answer: "t", "point", "normal", "object", "ray", "steps", or a
// quantity of a formula answer ("b").
struct PartResult {
  std::string name;
  double points = 0;
  double max_points = 0;
  PartStatus status = PartStatus::kMissing;
  std::vector<std::string> feedback;  // sentences for the student
};

// The status a student sees: "not counted" for a part that carries no points (given
// anyway, it is checked and its feedback shown, without a verdict beside a score), else
// the part's status.
const char* shown_status(const PartResult& p);

struct GradeResult {
  std::string problem_id;
  std::string title;
  double score = 0;      // points earned
  double max_score = 0;  // points available
  std::vector<PartResult> parts;
  std::vector<FoundMistake> mistakes;
  std::vector<std::string> notes;  // feedback about the answer as a whole
  bool answered = true;            // false when the submission has no answer to this problem
  bool carried_forward = false;    // some credit came from the student's own earlier values

  // score / max_score, or 1 when nothing is worth points and nothing is wrong.
  double fraction() const;
  bool has_mistake(std::string_view id) const;
};

nlohmann::json result_json(const GradeResult& r);

// The same JSON as compact text, written directly: several times faster than building the
// nlohmann::json value and dumping it, for classes of thousands.
void append_result_json(std::string& out, const GradeResult& r);

}  // namespace raygrade
