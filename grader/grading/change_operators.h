// The operators of the mistake search (docs/report.md, "The operators"): each makes single
// changes to one node of a step's formula, the way mutation testing makes its mutants. A
// change is a slip a student makes in one place: an operator for another, a constant off by a
// factor, one quantity for another, a factor or a term left out, a negation, square, root,
// absolute value or normalisation put in or left out, a function for its sibling, a clamp
// forgotten, two quantities exchanged throughout the step, a family's quantities given to each
// other's vertices, a number in [0, 1] for its complement.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
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
  // The node changed and what it became (empty for a change of the whole step): the change
  // made again wherever the step's form recurs (change_everywhere).
  E from, to;
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

// The changes of the whole step's formula: negated, and 1 − x for a value strictly between 0 and
// 1 (kOperators); each pair of quantities of the same type in it exchanged, each quantity used
// more than once replaced throughout by another in scope, and the renamings of families of three
// or more (w_a, w_b, w_c; S_1, S_2, S_3) that it names whole: rotated by one either way, or
// exchanged member by member with another family of the same indices (kOperands). Made and
// counted as each_change's.
bool each_step_change(const E& e, const ChangeScope& scope, ChangeTier tier, std::size_t& left,
                      const std::function<void(FormulaChange&&)>& sink);
std::size_t count_step_changes(const E& e, const ChangeScope& scope, ChangeTier tier);

// A slip a student makes in a formula they apply more than once (the root's denominator 2a in
// both roots, the light vector of every light) is made every time. The form of a node: its
// operators and numbers, with the quantities of one indexed family (S_1, S_2, …) alike. Equal
// forms have equal hashes.
std::size_t form_hash(const E& e);
// `formula` with every node of the form of `from` replaced by `to`, the quantities of `to` that
// `from` names renamed to the ones of the node it replaces (S_1 − P → S_2 − P in L_2). Nothing
// when no node of `formula` has that form. `hash` is form_hash(from).
std::optional<E> change_everywhere(const E& formula, const E& from, const E& to, std::size_t hash);
// Whether `c` is made again wherever its node's form recurs: a change of a node that is not a
// number, nor a quantity without an index (the index carries over: c_1 → r_1 is c_2 → r_2).
bool made_everywhere(const FormulaChange& c);
// Every node's form_hash in `e` (not in how symbols are shown).
void form_hashes(const E& e, std::vector<std::size_t>& out);

// A slip in which quantity belongs to which vertex (or light) is made wherever they are used:
// whether `c` renames quantities (a family rotated, two exchanged), its `from` and `to` the
// lists of what is renamed and into what. `formula` with them renamed; nothing when it names
// none of them.
bool renames(const FormulaChange& c);
bool renaming_kind(std::string_view kind);  // StepChange::kind of a renaming
std::optional<E> rename_everywhere(const E& formula, const E& from, const E& to);

}  // namespace raygrade
