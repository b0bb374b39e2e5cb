// A named mistake of the catalogue (docs/grading.md), and the mistakes that are a change to a
// step's formula: grading recomputes a derivation with the change and matches the student's
// numbers. The catalogue is grading's (grading/mistakes.h); a primitive whose own steps have a
// mistake of their own provides it with its rewrite (`mistakes()`, in its own files).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "derivation/expr.h"

namespace raygrade {

struct MistakeInfo {
  std::string_view id;
  std::string_view kind;  // sign, root-choice, convention, orientation, algebra, ...
  std::string_view title;
  std::string_view explanation;  // the general lesson, appended to the specific message
  double credit;                 // the fraction of the part's points it still earns
};

// A mistake that is a change to a step's formula.
struct FormulaMistake {
  std::string_view id;
  // The mistaken formula for `step`, or nothing when the mistake does not touch it.
  std::optional<E> (*rewrite)(std::string_view step, const E& formula);
};

// A primitive's own formula mistake: its entry of the catalogue and its rewrite.
struct PrimitiveMistake {
  MistakeInfo info;
  std::optional<E> (*rewrite)(std::string_view step, const E& formula);
};

// Does the formula name the symbol `name` anywhere?
inline bool mentions_symbol(const E& e, std::string_view name) {
  if (e.empty()) return false;
  if (e.node().op == Op::kSymbol && e.node().name == name) return true;
  for (const auto& a : e.node().args) {
    if (mentions_symbol(a, name)) return true;
  }
  return false;
}

}  // namespace raygrade
