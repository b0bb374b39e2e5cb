// Handouts: a student's problems as a self-contained page with one input per part and a
// download of answers.json, and the same answers as a JSON template.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "assignments/assignment.h"
#include "grading/submission.h"
#include "problems/problem.h"

namespace raygrade {

struct Handout {
  std::string html;              // index.html: statements, figures, inputs; no external reference
  nlohmann::json template_json;  // answers-template.json: the submission with every input blank
};

// The handout of `problems` (one student's variant, in the assignment's order) for `student`
// (nobody: the generic handout, whose downloads name no student).
Handout make_handout(const AssignmentSpec& spec, const std::vector<Problem>& problems,
                     const StudentIdentity* student);

// The figure of a problem's statement: its sketch without hit points, rejected candidates or
// any label that states a result. Empty when the kind draws no sketch.
std::string statement_figure_svg(const Problem& p);

}  // namespace raygrade
