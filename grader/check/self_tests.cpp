// Self-tests: each sample answer graded, and its score and mistake compared with the stated
// ones.
#include "check/self_tests.h"

#include <algorithm>
#include <cmath>

#include "check/problem_checks.h"
#include "derivation/number_format.h"
#include "grading/grade.h"

namespace raygrade {
namespace {

// Scores are fractions of the problem's points; two scores this close are the same score
// (a third of the points written as 0.333 matches 1/3).
constexpr double kScoreTolerance = 5e-3;

const std::vector<std::string>& test_keys() {
  static const std::vector<std::string> keys = {"answer", "score", "mistake", "name"};
  return keys;
}

}  // namespace

std::vector<Diagnostic> run_self_tests(const Problem& p, const nlohmann::json& /*reference*/) {
  std::vector<Diagnostic> out;
  if (p.tests.is_null()) return out;
  if (!p.tests.is_array()) {
    out.push_back(problem_diagnostic(p, "/tests", Severity::kError,
                                     "tests must be a list of {answer, score, mistake}", "type"));
    return out;
  }
  std::unique_ptr<Grader> grader;
  for (std::size_t i = 0; i < p.tests.size(); ++i) {
    const auto& t = p.tests[i];
    std::string where = fmt::format("/tests/{}", i);
    auto fault = [&](const std::string& sub, std::string message, std::string code) {
      out.push_back(problem_diagnostic(p, where + sub, Severity::kError, std::move(message),
                                       std::move(code)));
    };
    if (!t.is_object()) {
      fault("", "a test must be an object {answer, score, mistake}", "type");
      continue;
    }
    bool ok = true;
    for (const auto& [k, v] : t.items()) {
      if (std::find(test_keys().begin(), test_keys().end(), k) != test_keys().end()) continue;
      std::string hint = closest_match(k, test_keys());
      fault("/" + pointer_token(k),
            hint.empty() ? fmt::format("unknown key '{}'", k)
                         : fmt::format("unknown key '{}' (did you mean '{}'?)", k, hint),
            "unknown-key");
      ok = false;
    }
    if (!t.contains("answer") || !t["answer"].is_object()) {
      fault(t.contains("answer") ? "/answer" : "", "a test needs an answer object",
            t.contains("answer") ? "type" : "missing-key");
      ok = false;
    }
    if (!t.contains("score") || !t["score"].is_number() || t["score"].get<double>() < 0 ||
        t["score"].get<double>() > 1) {
      fault(t.contains("score") ? "/score" : "",
            "a test needs a score from 0 to 1 (the fraction of the problem's points)",
            t.contains("score") ? "range" : "missing-key");
      ok = false;
    }
    if (t.contains("mistake") && !t["mistake"].is_string()) {
      fault("/mistake", "a mistake is named by its id, a string", "type");
      ok = false;
    }
    if (!ok) continue;
    GradeResult r;
    try {
      if (!grader) grader = std::make_unique<Grader>(p);
      r = grader->grade(t["answer"], GradeOptions{p.file, p.path + where + "/answer"});
    } catch (const Error& e) {
      out.push_back(e.diagnostic());
      continue;
    }
    double stated = t["score"].get<double>();
    if (std::abs(r.fraction() - stated) > kScoreTolerance) {
      std::vector<std::string> found;
      for (const auto& m : r.mistakes) found.push_back(m.id);
      fault("/score",
            fmt::format(
                "self-test failed: the answer scores {}, the test states {}{}",
                format_number(r.fraction()), format_number(stated),
                found.empty() ? "" : fmt::format(" (mistakes found: {})", fmt::join(found, ", "))),
            "self-test");
    }
    if (t.contains("mistake")) {
      std::string id = t["mistake"].get<std::string>();
      if (!r.has_mistake(id)) {
        std::vector<std::string> found;
        for (const auto& m : r.mistakes) found.push_back(m.id);
        fault("/mistake",
              fmt::format("self-test failed: the grader does not find the mistake '{}' in this "
                          "answer ({})",
                          id,
                          found.empty() ? "it finds none"
                                        : fmt::format("it finds {}", fmt::join(found, ", "))),
              "self-test");
      }
    }
  }
  return out;
}

}  // namespace raygrade
