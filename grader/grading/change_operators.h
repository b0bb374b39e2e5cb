// The operators of the mistake search (docs/report.md, "The operators"): each makes single
// changes to one node of a step's formula, the way mutation testing makes its mutants. A
// change is a slip a student makes in one place: an operator for another, a constant off by a
// factor, one quantity for another, a factor or a term left out, a negation, square, root,
// absolute value or normalisation put in or left out, a function for its sibling, a clamp
// forgotten, two quantities exchanged throughout the step.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "derivation/expr.h"

namespace raygrade {

// A changed formula: what is evaluated, how it is shown, and the operator that made it.
struct FormulaChange {
  E eval;
  E shown;
  std::string_view kind;
};

// What the changes of one step may use: the quantities in scope when the step is worked (the
// givens and earlier steps of its part), with their values and how each is shown.
struct ChangeScope {
  const Env* values = nullptr;
  const std::map<std::string, E, std::less<>>* symbols = nullptr;
};

// Which changes: those of an operator, a constant, a function or a sign, and the insertions
// (tier kOperators: a few per node of the formula); those that put another quantity in scope
// for one (tier kOperands: one per quantity of the same type, so as many as the problem has
// vertices); or both.
enum class ChangeTier { kOperators, kOperands, kAll };

// The operators' names (StepChange::kind), simplest first: of changes that give the same
// numbers, the one of the lowest rank names them.
const std::vector<std::string_view>& change_kinds();
std::size_t change_rank(std::string_view kind);

// Calls `sink` with each single change of `tier` of the formula `e`, anywhere in its tree (a
// node's own changes first, then each operand's), until `left` of them have been made;
// returns false when it stopped for `left`. The changes of the whole step (negated, two
// quantities exchanged throughout it) are step_changes'.
bool each_change(const E& e, const ChangeScope& scope, ChangeTier tier, std::size_t& left,
                 const std::function<void(FormulaChange&&)>& sink);
// How many changes each_change makes, without making them.
std::size_t count_changes(const E& e, const ChangeScope& scope, ChangeTier tier);

// The changes of the whole step's formula: negated (kOperators); each pair of quantities of the
// same type in it exchanged, and each quantity used more than once replaced throughout by
// another in scope (kOperands). Made and counted as each_change's.
bool each_step_change(const E& e, const ChangeScope& scope, ChangeTier tier, std::size_t& left,
                      const std::function<void(FormulaChange&&)>& sink);
std::size_t count_step_changes(const E& e, const ChangeScope& scope, ChangeTier tier);

}  // namespace raygrade
