// The checks of one problem that `raygrade check` runs after reading it: the stated answer,
// the ill-posed cases, and the self-tests.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "check/compare.h"
#include "check/literals.h"
#include "core/error.h"
#include "problems/problem.h"

namespace raygrade {

// The error a grader accepts in a t near `t`: the problem's tolerance for the field "t"
// (docs/grading.md), without the widening the grader adds near a tangent, since the check
// asks whether the plain tolerance can tell the cases apart. Throws Error for a faulty
// tolerance.
double t_tolerance(const Problem& p, double t);

// A diagnostic at `relative_path` inside the problem (the problem itself when empty). Its
// line and column are left for the caller to find (check_bank does, from the problem's own
// place in the file, so that findings in a large bank file cost no scan of the whole file).
Diagnostic problem_diagnostic(const Problem& p, std::string_view relative_path, Severity severity,
                              std::string message, std::string code);

// The stated `expected` answer graded against the reference with the problem's own
// tolerance: each part the grader does not accept in full, each unknown key or wrong type,
// and a hit listed behind the origin (t < t_min) or beyond t_max.
std::vector<Diagnostic> check_expected(const Problem& p, const nlohmann::json& reference,
                                       const NumberLiterals& literals);

// What the boundary probes found about a problem.
struct BoundaryProbe {
  // The outcome changes under a shift far below any rounding a person does: a designed
  // tangent, edge or vertex case, exact in the printed numbers.
  bool exact_boundary = false;
  std::vector<Diagnostic> diagnostics;
};

// Nearly tangent rays (and rays nearly through an edge or vertex): the outcome changes when
// the ray moves sideways by the tolerance; two hits closer together than the tolerance; a
// first hit that another object nearly ties.
BoundaryProbe probe_boundaries(const Problem& p);

// The conditioning check: every rounded input moved by half a unit in its last printed
// digit, and the problem solved again. Up to kConditioningGroups inputs move one at a time;
// beyond that they move in kConditioningGroups groups (conditioning_groups), each solved once
// per direction, and a group that moves the answer too far is halved down to the input
// responsible: a constant number of solves, so that the check stays linear in the size of a
// problem of thousands of objects or vertices.
inline constexpr std::size_t kConditioningGroups = 16;
// The inputs (0 to inputs - 1) in groups: one each up to kConditioningGroups, else every
// kConditioningGroups-th input together.
std::vector<std::vector<std::size_t>> conditioning_groups(std::size_t inputs);
std::vector<Diagnostic> check_conditioning(const Problem& p, const nlohmann::json& reference,
                                           const NumberLiterals& literals, bool exact_boundary);

// Every finding of the checks `raygrade check` runs on one problem by itself: the stated answer,
// the boundary probes, the conditioning check and the self-tests (those across problems, unique ids
// and geometry, are the caller's). `literals` are keyed by JSON pointers that start with p.path.
std::vector<Diagnostic> problem_findings(const Problem& p, const NumberLiterals& literals);

}  // namespace raygrade
