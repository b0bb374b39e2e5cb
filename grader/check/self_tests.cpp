// Self-tests: each sample answer judged, and its score and mistake compared with the stated ones.
#include "check/self_tests.h"

#include <cmath>

#include "check/problem_checks.h"
#include "derivation/number_format.h"

namespace raygrade {
namespace {

// Scores are fractions of the problem's points; two scores this close are the same score
// (a third of a point written as 0.333 matches 1/3).
constexpr double kScoreTolerance = 5e-3;

// The score of an answer: 1 when every part it gives matches the reference within the
// problem's tolerance (two decimals by default), else 0.
double judge(const Problem& p, const nlohmann::json& answer, const nlohmann::json& reference) {
  Tolerance tol = stated_tolerance(p);
  if (tol.absolute == 0 && tol.relative == 0) tol.absolute = kDefaultTTolerance;
  auto none = [](const std::string&) { return 0.0; };
  return compare_stated(answer, reference, tol, none).empty() ? 1.0 : 0.0;
}

}  // namespace

std::vector<Diagnostic> run_self_tests(const Problem& p, const nlohmann::json& reference) {
  std::vector<Diagnostic> out;
  if (p.tests.is_null()) return out;
  if (!p.tests.is_array()) {
    out.push_back(problem_diagnostic(p, "/tests", Severity::kError,
                                     "tests must be a list of {answer, score, mistake}", "type"));
    return out;
  }
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
      if (k != "answer" && k != "score" && k != "mistake" && k != "name") {
        std::string hint = closest_match(k, {"answer", "score", "mistake", "name"});
        fault("/" + pointer_token(k),
              hint.empty() ? fmt::format("unknown key '{}'", k)
                           : fmt::format("unknown key '{}' (did you mean '{}'?)", k, hint),
              "unknown-key");
        ok = false;
      }
    }
    if (!t.contains("answer") || !t["answer"].is_object()) {
      fault(t.contains("answer") ? "/answer" : "", "a test needs an answer object", "missing-key");
      ok = false;
    }
    if (!t.contains("score") || !t["score"].is_number() || t["score"].get<double>() < 0 ||
        t["score"].get<double>() > 1) {
      fault(t.contains("score") ? "/score" : "", "a test needs a score from 0 to 1",
            t.contains("score") ? "range" : "missing-key");
      ok = false;
    }
    if (!ok) continue;
    double stated = t["score"].get<double>();
    double got = judge(p, t["answer"], reference);
    if (std::abs(got - stated) > kScoreTolerance) {
      fault("/score",
            fmt::format("self-test failed: the answer scores {}, the test states {}",
                        format_number(got), format_number(stated)),
            "self-test");
    }
  }
  return out;
}

}  // namespace raygrade
