// The catalogue of named mistakes (docs/grading.md), and derivations recomputed with a
// mistake: a student's numbers that match a mistaken derivation and not the right one name
// the mistake.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "derivation/derivation.h"
#include "derivation/mistake.h"
#include "grading/result.h"
#include "problems/problem.h"

namespace raygrade {

// The catalogue: grading's own mistakes, then each primitive's own (its `mistakes()`), in the
// list's order.
const std::vector<MistakeInfo>& mistake_catalogue();
// The entry for `id` (a defect if unknown: throws Error).
const MistakeInfo& mistake_info(std::string_view id);

// A found mistake: `specific` says what the student wrote; the catalogue adds the lesson.
FoundMistake make_mistake(std::string_view id, std::string part, const std::string& specific);

// The formula mistakes, in the order they are tried: grading's own, then the primitives'.
const std::vector<FormulaMistake>& formula_mistakes();

// Copies a formula tree, replacing every subtree for which `replace` returns a value.
E rewrite_tree(const E& e, const std::function<std::optional<E>(const E&)>& replace);

// The worked solution recomputed with one formula mistake, by one method.
struct MistakenSolution {
  std::string id;
  std::string method;
  std::vector<SolutionPart> parts;
};

// Every formula mistake that changes something in some method of the task's solution.
std::vector<MistakenSolution> mistaken_solutions(const Task& task);

// The computed step whose value is a number of the reference answer (a number, or a triple as
// a vector): the last such step of the solution, or null when no step computes it.
const Step* find_answer_step(const std::vector<SolutionPart>& parts, const nlohmann::json& value);
// The last step named `name` in a solution's parts, or null.
const Step* find_step(const std::vector<SolutionPart>& parts, std::string_view name);
// Two values of one step agree (a mistaken derivation leaves it as it was).
bool same_step_value(const Value& a, const Value& b);

// The roots a derivation computes (steps t0, t1, t, t_enter, t_exit, t_bottom, t_top).
std::vector<double> derivation_roots(const Derivation& d);

}  // namespace raygrade
