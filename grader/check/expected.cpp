// The stated answer of a problem graded against the reference, and the helpers every
// problem check shares.
#include <algorithm>
#include <cmath>
#include <limits>

#include "check/problem_checks.h"
#include "derivation/number_format.h"
#include "grading/grade.h"
#include "grading/tolerance.h"
#include "kinds/part_names.h"
#include "problems/ray_cast.h"

namespace raygrade {
namespace {

// A stated answer must earn full marks; scores are sums of fractions of points, so allow
// their rounding.
constexpr double kFullMarks = 1 - 1e-9;

const Ray* ray_of(const Problem& p) {
  const RayCast* cast = p.task->ray_cast();
  return cast ? &cast->cast_ray() : nullptr;
}

// Where in the stated answer a graded part lives.
std::string part_path(const nlohmann::json& stated, const std::string& part) {
  if ((part == part_names::kT || part == part_names::kPoint || part == part_names::kNormal) &&
      stated.contains("hits")) {
    return "/expected/hits";
  }
  if (stated.contains(part)) return "/expected/" + pointer_token(part);
  return "/expected";
}

void check_range(const Problem& p, const nlohmann::json& stated, std::vector<Diagnostic>& out) {
  const Ray* ray = ray_of(p);
  if (!ray || !stated.contains("hits") || !stated["hits"].is_array()) return;
  for (std::size_t i = 0; i < stated["hits"].size(); ++i) {
    const auto& h = stated["hits"][i];
    if (!h.is_object() || !h.contains(part_names::kT) || !h[part_names::kT].is_number()) continue;
    double t = h[part_names::kT].get<double>();
    std::string where = fmt::format("/expected/hits/{}/{}", i, part_names::kT);
    if (t < ray->t_min) {
      out.push_back(problem_diagnostic(
          p, where, Severity::kError,
          fmt::format("a hit at t = {} is listed, but t < t_min = {}: the point lies behind the "
                      "ray's origin and is not a hit",
                      format_number(t), format_number(ray->t_min)),
          "negative-t"));
    } else if (t > ray->t_max) {
      out.push_back(problem_diagnostic(p, where, Severity::kError,
                                       fmt::format("a hit at t = {} is listed, but t > t_max = {}",
                                                   format_number(t), format_number(ray->t_max)),
                                       "beyond-t-max"));
    }
  }
}

}  // namespace

double t_tolerance(const Problem& p, double t) {
  TolerancePolicy policy = read_tolerance_policy(p);
  return allowed_error(t, std::abs(t), policy.for_field(part_names::kT));
}

Diagnostic problem_diagnostic(const Problem& p, std::string_view relative_path, Severity severity,
                              std::string message, std::string code) {
  return Diagnostic{
      p.file,         p.path + std::string(relative_path), 0, 0, severity, std::move(message),
      std::move(code)};
}

std::vector<Diagnostic> check_expected(const Problem& p, const nlohmann::json& reference,
                                       const NumberLiterals& /*literals*/) {
  std::vector<Diagnostic> out;
  if (!p.expected) return out;
  const nlohmann::json& stated = *p.expected;
  if (!stated.is_object()) {
    out.push_back(problem_diagnostic(p, "/expected", Severity::kError,
                                     "the expected answer must be an object, like the answer",
                                     "type"));
    return out;
  }
  // The shape first: keys the answer does not have, values of the wrong type.
  CompareTolerance any{std::numeric_limits<double>::infinity(), 0};
  auto no_digits = [](const std::string&) { return 0.0; };
  for (const auto& m : compare_stated(stated, reference, any, no_digits)) {
    if (m.code == "wrong-expected") continue;
    out.push_back(problem_diagnostic(p, "/expected" + m.path, Severity::kError, m.message, m.code));
  }
  check_range(p, stated, out);
  if (!out.empty()) return out;
  // Then the values, graded as a student's answer with the problem's own tolerance.
  GradeResult r;
  try {
    r = grade_answer(p, stated, GradeOptions{p.file, p.path + "/expected"});
  } catch (const Error& e) {
    out.push_back(e.diagnostic());
    return out;
  }
  // Full marks are not enough: a part that carries no points is still checked when the
  // stated answer gives it (barycentric weights, a flag nobody asked for).
  bool every_part_right = std::all_of(r.parts.begin(), r.parts.end(), [](const PartResult& x) {
    return x.status == PartStatus::kRight || x.status == PartStatus::kMissing;
  });
  if (r.fraction() >= kFullMarks && every_part_right) return out;
  // A stated answer may leave parts out (the seeds give t and the point, not the normal):
  // it is right when every part it gives is right.
  bool all_right = !r.parts.empty();
  for (const auto& part : r.parts) {
    if (part.status == PartStatus::kMissing) continue;
    if (part.status == PartStatus::kRight) continue;
    all_right = false;
    std::string feedback = fmt::format("{}", fmt::join(part.feedback, " "));
    out.push_back(problem_diagnostic(
        p, part_path(stated, part.name), Severity::kError,
        fmt::format("the stated answer is wrong: {} scores {} of {} against the reference {}{}",
                    part.name, format_number(part.points), format_number(part.max_points),
                    describe_answer(reference), feedback.empty() ? "" : ": " + feedback),
        "wrong-expected"));
  }
  if (all_right) return out;
  if (out.empty()) {
    out.push_back(problem_diagnostic(
        p, "/expected", Severity::kError,
        fmt::format("the stated answer scores {} of {} against the reference {}",
                    format_number(r.score), format_number(r.max_score), describe_answer(reference)),
        "wrong-expected"));
  }
  return out;
}

}  // namespace raygrade
