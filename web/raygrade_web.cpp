// raygrade.js's entry points: solve and grade the files that its JavaScript side has written
// to Emscripten's in-memory file system, with the library calls the command makes, so that
// the text returned is the text `raygrade solve` and `raygrade grade --format json` print.
#include <emscripten/emscripten.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "assignments/assignment.h"
#include "assignments/grading.h"
#include "assignments/variants.h"
#include "core/error.h"
#include "grading/outputs.h"
#include "grading/submission.h"
#include "problems/problem.h"
#include "reports/solve_output.h"

namespace raygrade {
namespace {

// The reply of the last call, alive until the next one (JavaScript copies it at once).
std::string reply;

// {"out": standard output, "errors": what standard error would show, "status": the command's
// exit code (0 fine, 1 wrong answers, 2 input that cannot be read, 3 an internal error)}.
const char* answer(const std::string& out, const std::vector<Diagnostic>& errors, int status) {
  nlohmann::json lines = nlohmann::json::array();
  for (const auto& d : errors) lines.push_back(format_diagnostic(d));
  reply = nlohmann::json{{"out", out}, {"errors", lines}, {"status", status}}.dump(
      -1, ' ', false, nlohmann::json::error_handler_t::replace);
  return reply.c_str();
}

const char* internal_error(const std::exception& e) {
  Diagnostic d{"",        "", 0, 0, Severity::kError, std::string("internal error: ") + e.what(),
               "internal"};
  return answer("", {d}, 3);
}

// One submission graded, as `raygrade grade --format json` prints it: the submission's own
// fault is in the output, not on standard error, when it is the only one graded.
const char* graded(const SubmissionGrade& g, std::vector<Diagnostic> errors) {
  bool bad = !g.gradable || !errors.empty();
  errors.insert(errors.end(), g.findings.begin(), g.findings.end());
  std::ostringstream out;
  JsonArrayStream stream(out);
  stream.add(json_text(submission_json(g)));
  stream.finish();
  bool internal = !g.gradable && g.fault && g.fault->code == "internal";
  return answer(out.str(), errors, internal ? 3 : bad ? 2 : 0);
}

// What `raygrade solve` gives for `bank` in `format`.
const char* solved(Bank& bank, const char* format, bool assignment) {
  std::vector<Diagnostic> errors = bank.errors, failures;
  SolveOutputOptions options;
  options.format = format;
  options.assignment = assignment;
  std::string out = solve_output(bank, options, failures);
  errors.insert(errors.end(), failures.begin(), failures.end());
  return answer(out, errors, bank.errors.empty() ? 0 : 2);
}

// Runs one call, turning what it throws into the reply the command would give.
template <typename F>
const char* guarded(F run) {
  try {
    return run();
  } catch (const Error& e) {
    return answer("", {e.diagnostic()}, 2);
  } catch (const std::exception& e) {
    return internal_error(e);
  }
}

std::vector<std::string> paths_of(const char* json) {
  return nlohmann::json::parse(json).get<std::vector<std::string>>();
}

}  // namespace
}  // namespace raygrade

extern "C" {

// `paths`: a JSON array of problem files; `format`: json, md, html or txt.
EMSCRIPTEN_KEEPALIVE const char* raygrade_solve(const char* paths, const char* format) {
  using namespace raygrade;
  return guarded([&] {
    Bank bank = load_bank(paths_of(paths));
    return solved(bank, format, false);
  });
}

// `problem_paths`: a JSON array of problem files; `submission`: one submission file.
EMSCRIPTEN_KEEPALIVE const char* raygrade_grade(const char* problem_paths, const char* submission) {
  using namespace raygrade;
  return guarded([&] {
    Bank bank = load_bank(paths_of(problem_paths));
    Assignment assignment(bank.problems);
    std::vector<Diagnostic> errors = bank.errors;
    errors.insert(errors.end(), assignment.errors().begin(), assignment.errors().end());
    return graded(assignment.grade_file(submission), errors);
  });
}

// raygrade solve ASSIGNMENT --student STUDENT --format FORMAT; with a problem id, that
// problem's alone.
EMSCRIPTEN_KEEPALIVE const char* raygrade_solve_assignment(const char* assignment,
                                                           const char* student, const char* format,
                                                           const char* problem) {
  using namespace raygrade;
  return guarded([&] {
    Bank bank = student_bank(load_assignment(assignment), student);
    if (*problem) {
      std::erase_if(bank.problems, [&](const Problem& p) { return p.id != problem; });
      if (bank.problems.empty() && bank.errors.empty()) {
        bank.errors.push_back(Diagnostic{assignment, "", 0, 0, Severity::kError,
                                         std::string("no problem '") + problem + "' in it",
                                         "unknown-problem"});
      }
    }
    return solved(bank, format, true);
  });
}

// raygrade grade --assignment ASSIGNMENT --now NOW --format json SUBMISSION, with NOW in
// seconds since 1970 UTC (the browser's clock). With a `cache_key`, the assignment read for the
// last call with the same key (its variants drawn, its graders made) is used again while the
// feedback policy stays the same: the caller promises that the files are the same.
EMSCRIPTEN_KEEPALIVE const char* raygrade_grade_assignment(const char* assignment,
                                                           const char* submission, double now,
                                                           const char* cache_key) {
  using namespace raygrade;
  return guarded([&] {
    auto seconds = static_cast<std::int64_t>(now);
    static struct {
      std::string key;
      bool after_due = false;
      std::unique_ptr<AssignmentSpec> spec;
      std::unique_ptr<AssignmentBank> bank;
      std::unique_ptr<AssignmentGrader> grader;
    } cache;
    auto after_due = [&](const AssignmentSpec& spec) { return spec.due && seconds > *spec.due; };
    if (!*cache_key || cache.key != cache_key || !cache.grader ||
        cache.after_due != after_due(*cache.spec)) {
      cache.key.clear();
      cache.grader.reset();
      cache.spec = std::make_unique<AssignmentSpec>(load_assignment(assignment));
      cache.bank = std::make_unique<AssignmentBank>(load_assignment_bank(*cache.spec));
      if (cache.bank->problems.size() != cache.spec->problems.size())
        return answer("", cache.bank->errors, 2);
      AssignmentGradeOptions options;
      options.now = seconds;
      cache.grader = std::make_unique<AssignmentGrader>(*cache.spec, cache.bank->problems, options);
      cache.after_due = after_due(*cache.spec);
      cache.key = cache_key;
    }
    return graded(cache.grader->grade_file(submission), cache.bank->errors);
  });
}

}  // extern "C"
