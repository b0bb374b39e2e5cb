// Grading one answer to one problem: the library's entry point for the grade command, bank
// checks and anything else that needs a grade.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "grading/result.h"
#include "problems/problem.h"

namespace raygrade {

struct GradeOptions {
  std::string file;  // where the answer came from, for diagnostics ("alice.json")
  std::string path;  // its JSON pointer in that file ("/answers/seed000-sphere-1")
};

class KindGrader;
class BankMistakes;

// Prepares a problem once (reference answer, derivations, mistaken variants, tolerances and
// points) and grades any number of answers to it.
class Grader {
 public:
  // Throws Error naming the problem's file and path when its tolerance or points are faulty.
  explicit Grader(const Problem& problem);

  // Grades an answer in the solver's shape (docs/submission-format.md). Any part may be left
  // out. A value a student typed that does not parse ("7.2.7") is feedback, not an error; a
  // value of the wrong JSON type (an object where a number belongs) throws Error naming
  // options.file and the JSON path.
  GradeResult grade(const nlohmann::json& answer, const GradeOptions& options = {}) const;

  // The result for a problem left unanswered: zero of its points.
  GradeResult unanswered() const;

  const Problem& problem() const { return *problem_; }
  double max_score() const;
  // The points of one part ("t", "normal"): 0 for a part the problem does not ask.
  double part_points(std::string_view part) const;

 private:
  const Problem* problem_;
  std::shared_ptr<const KindGrader> kind_;
  std::shared_ptr<const BankMistakes> bank_mistakes_;  // the problem's own "mistakes"
};

// Grades one answer; prepares the problem each time (use Grader for many answers).
GradeResult grade_answer(const Problem& problem, const nlohmann::json& answer,
                         const GradeOptions& options = {});

}  // namespace raygrade
