// Handouts: a student's problems as a self-contained page with one input per part and a
// download of answers.json, and the same answers as a JSON template.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "assignments/assignment.h"
#include "grading/submission.h"
#include "problems/problem.h"

namespace raygrade {

// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct Handout {
  std::string html;              // index.html: statements, figures, inputs; no external reference
  nlohmann::json template_json;  // answers-template.json: the submission with every input blank
};

// What a practice page carries besides the handout: raygrade.js, and the files its grader
// reads (the assignment and every file of its bank), named so that the bank's paths relative
// to the assignment still hold in the page's in-memory file system (docs/web.md); a bank named
// by an absolute path is named relative to the assignment in the page's copy of it.
struct PracticeAssets {
  std::string grader_js;                                   // raygrade.js
  std::string assignment;                                  // the assignment's name among `files`
  std::vector<std::pair<std::string, std::string>> files;  // name, text
  // When the page is a platform's package and reports to the LMS around it: what the platform's
  // script reads under the page's "practice" data, the script (run before the page's own), and
  // the sentence that says where answers are kept. Empty: the page talks to nobody.
  nlohmann::json lms_data = nlohmann::json::object();
  std::string_view lms_script;
  std::string kept;
};

// The assets of `spec`'s practice pages. Throws Error when a file cannot be read, or when its
// bank lies where no relative name reaches (another drive, say).
PracticeAssets practice_assets(const AssignmentSpec& spec, std::string grader_js);

// Attempts after which a practice page shows a problem's worked solution, if no attempt got
// full marks before.
inline constexpr int kPracticeUnlockAfter = 3;

// The handout of `problems` (one student's variant, in the assignment's order) for `student`
// (nobody: the generic handout, whose downloads name no student). With `practice`, the page
// grades in the browser: a Check button per problem, feedback under the assignment's policy,
// attempts counted, the worked solution after kPracticeUnlockAfter attempts or full marks.
Handout make_handout(const AssignmentSpec& spec, const std::vector<Problem>& problems,
                     const StudentIdentity* student, const PracticeAssets* practice = nullptr);

// The figure of a problem's statement: its sketch without hit points, rejected candidates or
// any label that states a result. Empty when the kind draws no sketch.
std::string statement_figure_svg(const Problem& p);

}  // namespace raygrade
