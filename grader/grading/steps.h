// Grading a submission's intermediate `steps` by the derivation's step names, with error
// carried forward: a step that is wrong only because of the student's own earlier wrong
// value is recognised as such, as a human grader does.
#pragma once

#include <string>
#include <vector>

#include "grading/kind_grader.h"
#include "grading/mistakes.h"

namespace raygrade {

// A problem's worked solution by each of its methods (the first part of each). Not named
// MethodSolution: reports/solution.h has that name, and one name for two types breaks the
// one-definition rule (their std::vector code is shared at link time).
struct MethodDerivation {
  std::string method;
  Derivation derivation;
};
std::vector<MethodDerivation> solutions_by_method(const Task& task);

struct StepsGrade {
  PartResult part;  // "steps"
  std::vector<FoundMistake> mistakes;
  std::string method;                 // the method whose steps the student followed
  std::vector<std::string> wrong;     // names of the wrong steps, in order
  std::optional<Derivation> carried;  // recomputed from the student's values, when some are wrong
};

// Grades `steps` (an object: step name → number or [x, y, z]).
StepsGrade grade_steps(const GradingContext& c, const Task& task,
                       const std::vector<MethodDerivation>& reference,
                       const std::vector<MistakenSolution>& mistaken, const AnswerReader& steps);

// Whether a student's value matches a derivation's value of a step, by a tolerance.
Match match_value(const AnswerReader& student, const Value& reference, const Tolerance& t,
                  std::string* message = nullptr);

}  // namespace raygrade
