// Per-student variants: each student's numbers for the problems of an assignment, a pure
// function of (assignment id, variant seed, student, problem id).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "assignments/assignment.h"
#include "grading/submission.h"
#include "problems/problem.h"

namespace raygrade {

// The key a student's variant is drawn with: the id, else the email (lower case), else the
// name; surrounding spaces removed.
std::string student_key(const StudentIdentity& s);

// `s` without the spaces and tabs at either end: how student_key and a roster's cells read text.
std::string trimmed(const std::string& s);
// An email as compared: trimmed, ASCII letters in lower case.
std::string email_key(const std::string& email);

// The seed of one student's variant of one problem: 64-bit FNV-1a over the assignment's id,
// its seed, the student's key and the problem's id (docs/assignments.md).
std::uint64_t variant_seed(const std::string& assignment, std::uint64_t seed,
                           const std::string& student, const std::string& problem);

// Draws tried for one variant before the problem is reported as unable to give one.
constexpr int kMaxVariantDraws = 100;

// The first draw from `seed` whose problem passes every check `raygrade check` runs on one
// problem (stated answer, boundaries, conditioning) and the problem's nice-number rule. A
// problem without parameters is read again as it is. Throws Error at the problem's place when
// no draw passes.
// Unless `allow_degenerate`, a draw whose ray meets an edge, a vertex, a rim or a tangent
// exactly (a hit that one rounding turns into a miss: a barycentric weight of 0) is drawn again.
Problem draw_variant(const Problem& base, std::uint64_t seed, bool allow_degenerate = false);

// Why one set of values is not a usable variant: the findings of the checks, and a note when
// the nice-number rule fails. Empty for a usable one.
std::vector<Diagnostic> variant_findings(const Problem& variant, bool allow_degenerate = false);

// The problems of an assignment for one student (an empty key: the generic set, every
// problem with its default numbers), in the assignment's order.
std::vector<Problem> student_problems(const AssignmentSpec& spec,
                                      const std::vector<const Problem*>& bank_problems,
                                      const std::string& student);

// Whether students' numbers differ: the assignment draws per student, and some problem it
// draws for has parameters to draw. Without, every student's problems are the generic set's.
bool has_per_student_numbers(const AssignmentSpec& spec,
                             const std::vector<const Problem*>& bank_problems);

// What `raygrade solve ASSIGNMENT --student KEY` solves: load_assignment_bank, then
// student_problems; no problems when an id of the assignment is missing from its bank (the
// errors say which).
Bank student_bank(const AssignmentSpec& spec, const std::string& student);

}  // namespace raygrade
