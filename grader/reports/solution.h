// A worked solution ready to render, and what every format shares: which forms of a step
// appear, how givens group, how a conclusion's numbers are written.
#pragma once

#include <string>
#include <vector>

#include "problems/problem.h"

namespace raygrade {

struct WorkedMethod {
  std::string method;
  std::vector<SolutionPart> parts;
};

struct Solution {
  const Problem* problem = nullptr;
  std::vector<WorkedMethod> methods;
  Sketch sketch;
  NumberFormat numbers;
};

// The worked solution of `problem`. `method`: empty for the problem's own method (or the
// kind's default), "all" for every method, or a method's name (a name the problem does not
// know falls back to its own method).
Solution make_solution(const Problem& problem, const std::string& method,
                       const NumberFormat& numbers);

// One step as every format shows it: "symbol = formula = numbers = value", leaving out a
// form that would repeat the one before it (r² = r², crossings = 1 = 1).
struct StepView {
  const Step* step = nullptr;
  Env before;  // the values of the steps before it, for the form with numbers
  bool show_formula = false;
  bool show_substituted = false;
};

// Steps in order, with runs of givens grouped together.
struct StepGroup {
  bool given = false;
  std::vector<StepView> steps;
};
std::vector<StepGroup> step_groups(const Derivation& d, const NumberFormat& numbers);

// True when the step's name is not what its symbol shows (d2 shown as d², discriminant as
// Δ): renderers then show the name, which students use in their submissions.
bool name_differs_from_symbol(const Step& s);

// A conclusion sentence in plain text: numbers at the format's precision, with their exact
// form where one exists (t = 9 − √3 ≈ 7.268), points as (x, y, z), minus signs as "−".
std::string sentence_text(const Sentence& s, const NumberFormat& numbers);

// A number as a person writes it in running text: format_number with "−" for the minus sign.
std::string text_number(double v, const NumberFormat& numbers);

// The heading of one part of a solution: "sphere 1 — Sphere, geometric method".
std::string part_title(const SolutionPart& part);

}  // namespace raygrade
