// Discovering mistakes nobody named: single changes to a variant's derivation (a sign flipped,
// a term dropped, operands swapped, r for r², ...) whose numbers reproduce a wrong answer that
// no named mistake explains, with a guard against explaining random numbers.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grading/tolerance.h"
#include "problems/problem.h"

namespace raygrade {

// The methods of a problem whose derivations are searched, the default first: a student may
// have worked by any of them, and the search's time grows with each.
constexpr std::size_t kMaxSearchedMethods = 4;

// The share of random answers that the changes of one variant may fit between them before no
// fit on that variant is claimed. Random here means every number drawn uniformly within
// max(1, |reference|) of the reference; the acceptance test of docs/report.md asks that at most
// 5% of such answers be claimed, and 2% leaves room for answers that are partly right.
constexpr double kMaxRandomFit = 0.02;

// The search's budget: the steps and formula nodes that all changed derivations of a variant
// work through, shared equally by its methods. Every problem of the bundled bank and of the
// tests stays below it (they are searched whole); a polygon of 200 vertices would need 10⁸
// (its Newell sum alone has 80,000 changes, each derivation 3,000 nodes), and is searched in
// part: every step's operators first, then its operands (docs/report.md).
constexpr std::size_t kSearchWork = 4'000'000;
// Changed derivations worked per method however large one is.
constexpr std::size_t kMinSearchedChanges = 64;

// One change to one step of a derivation.
struct StepChange {
  std::string method;  // the derivation's method ("algebraic")
  std::string step;    // the step changed ("b")
  std::string kind;    // sign, drop-term, swap, square, sqrt, normalise, other-root, degrees,
                       // vector-swap, component, …: change_kinds()
  std::string before;  // the step's formula as the worked solution writes it ("2·(D · f)")
  std::string after;   // the changed formula ("2·(D · C)")
  // The change made in every step where the changed part's form recurs (the same slip in both
  // roots, for every light): change_operators.h, change_everywhere; a renaming made in every
  // step that uses the renamed quantities (rename_everywhere).
  bool everywhere = false;
  // "b = 2·(D · f) → b = 2·(D · C)", and "…, and alike in every step of its form"
  std::string text() const;
  // The same for every variant of a problem: the step and its changed formula in symbols.
  std::string key() const { return step + " = " + after + (everywhere ? " (everywhere)" : ""); }
};

// What the search made of one wrong answer.
struct Discovery {
  enum class Verdict {
    kExplained,  // exactly one change (or several that agree on every number) fits
    kAmbiguous,  // changes that give different numbers fit: none is claimed
    kNoisy,      // this variant's changes fit too many random answers: none is claimed
    kNone,       // no single change fits
  };
  Verdict verdict = Verdict::kNone;
  // kExplained: the changes that fit, all giving the same numbers (the first is the simplest).
  std::vector<StepChange> changes;
  std::size_t fitting = 0;  // how many different answers fitted, on the numbers given
  // The chance that random numbers in place of the student's fit some change: each number
  // drawn uniformly within max(1, |reference|) of the reference.
  double random_fit = 0;
};

const char* to_string(Discovery::Verdict v);

// The changed derivations of one variant, computed once and matched against any number of
// answers. Safe to share between threads once built.
class ChangeSearch {
 public:
  // Derives `problem` by its default method and by each other method of its kind (at most
  // kMaxSearchedMethods in all), maps each number of the reference answer to the step that
  // computes it in each, and derives again with every single change of each.
  explicit ChangeSearch(const Problem& problem);
  ~ChangeSearch();

  // Which change explains `answer` (in the solver's shape). An answer with no number to
  // compare, or right in every number compared, is kNone.
  Discovery explain(const nlohmann::json& answer) const;

  std::size_t changes() const;  // changes tried that moved some number of the answer
  // The changed derivations worked, and their cost: for each, the steps and formula nodes of
  // its method's derivation. The cost is at most kSearchWork, or kMinSearchedChanges
  // derivations per method when one derivation costs more: linear in the problem's size.
  std::size_t derivations() const;
  std::size_t work() const;
  bool truncated() const;  // some changes were left out for the budget

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace raygrade
