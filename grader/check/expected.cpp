// The stated answer of a problem against the reference, and the helpers every problem check
// shares.
#include <cmath>

#include "check/problem_checks.h"
#include "derivation/number_format.h"
#include "kinds/intersect.h"

namespace raygrade {
namespace {

const Ray* ray_of(const Problem& p) {
  if (auto* t = dynamic_cast<const IntersectTask*>(p.task.get())) return &t->ray();
  if (auto* t = dynamic_cast<const FirstHitTask*>(p.task.get())) return &t->ray();
  return nullptr;
}

double number_in(const nlohmann::json& tol, std::initializer_list<const char*> keys) {
  for (const char* k : keys) {
    if (tol.contains(k) && tol[k].is_number()) return tol[k].get<double>();
  }
  return 0;
}

}  // namespace

Tolerance stated_tolerance(const Problem& p) {
  Tolerance t;
  if (p.tolerance.is_number()) {
    t.absolute = p.tolerance.get<double>();
  } else if (p.tolerance.is_object()) {
    t.absolute = number_in(p.tolerance, {"abs", "absolute"});
    t.relative = number_in(p.tolerance, {"rel", "relative"});
  }
  return t;
}

double t_tolerance(const Problem& p) {
  Tolerance t = stated_tolerance(p);
  return t.absolute > 0 ? t.absolute : kDefaultTTolerance;
}

Diagnostic problem_diagnostic(const Problem& p, std::string_view relative_path, Severity severity,
                              std::string message, std::string code) {
  std::string path = p.path + std::string(relative_path);
  auto [line, column] = p.source_file ? locate(p.source_file->text, path) : std::pair{0, 0};
  if (line == 0 && p.source_file) std::tie(line, column) = locate(p.source_file->text, p.path);
  return Diagnostic{p.file, path, line, column, severity, std::move(message), std::move(code)};
}

std::vector<Diagnostic> check_expected(const Problem& p, const nlohmann::json& reference,
                                       const NumberLiterals& literals) {
  std::vector<Diagnostic> out;
  if (!p.expected) return out;
  const nlohmann::json& stated = *p.expected;
  if (!stated.is_object()) {
    out.push_back(problem_diagnostic(p, "/expected", Severity::kError,
                                     "the expected answer must be an object, like the answer",
                                     "type"));
    return out;
  }
  std::string base = p.path + "/expected";
  auto half_unit_at = [&](const std::string& path) {
    auto it = literals.find(base + path);
    return it == literals.end() ? 0.0 : half_unit(it->second);
  };
  for (const auto& m : compare_stated(stated, reference, stated_tolerance(p), half_unit_at)) {
    out.push_back(problem_diagnostic(
        p, "/expected" + m.path, Severity::kError,
        m.code == "wrong-expected" ? "the stated answer is wrong: " + m.message : m.message,
        m.code));
  }
  // A hit outside [t_min, t_max]: behind the origin, most often a negative root kept.
  const Ray* ray = ray_of(p);
  if (ray && stated.contains("hits") && stated["hits"].is_array()) {
    for (std::size_t i = 0; i < stated["hits"].size(); ++i) {
      const auto& h = stated["hits"][i];
      if (!h.is_object() || !h.contains("t") || !h["t"].is_number()) continue;
      double t = h["t"].get<double>();
      std::string where = fmt::format("/expected/hits/{}/t", i);
      if (t < ray->t_min) {
        out.push_back(problem_diagnostic(
            p, where, Severity::kError,
            fmt::format("a hit at t = {} is listed, but t < t_min = {}: the point lies behind the "
                        "ray's origin and is not a hit",
                        format_number(t), format_number(ray->t_min)),
            "negative-t"));
      } else if (t > ray->t_max) {
        out.push_back(
            problem_diagnostic(p, where, Severity::kError,
                               fmt::format("a hit at t = {} is listed, but t > t_max = {}",
                                           format_number(t), format_number(ray->t_max)),
                               "beyond-t-max"));
      }
    }
  }
  return out;
}

}  // namespace raygrade
