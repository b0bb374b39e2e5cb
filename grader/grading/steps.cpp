// Steps and error carried forward.
#include "grading/steps.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "derivation/number_format.h"
#include "json/cursor.h"
#include "kinds/part_names.h"

namespace raygrade {

std::vector<MethodDerivation> solutions_by_method(const Task& task) {
  std::vector<MethodDerivation> out;
  for (const auto& m : task.methods()) {
    try {
      auto parts = task.derive(m, nullptr);
      if (!parts.empty()) out.push_back({m, std::move(parts.front().derivation)});
    } catch (const Error&) {
      // A method that does not apply to this problem's data.
    }
  }
  return out;
}

namespace {

// The student's value as a derivation Value (scalar or vector); nullopt with a fault.
std::optional<Value> student_value(const AnswerReader& s, std::string* fault) {
  if (s.json().is_array()) {
    auto v = s.vector();
    if (!v.ok) {
      *fault = v.fault;
      return std::nullopt;
    }
    return Value(v.value());
  }
  auto n = s.number();
  if (!n.value) {
    *fault = n.fault;
    return std::nullopt;
  }
  return Value(n.value->value);
}

// The derivation from the student's own values; nothing when they make it meaningless.
std::vector<SolutionPart> derive_or_nothing(const Task& task, const std::string& method,
                                            const Overrides& own) {
  try {
    return task.derive(method, &own);
  } catch (const Error&) {
    return {};
  } catch (const EvaluationFault&) {
    return {};
  }
}

}  // namespace

Match match_value(const AnswerReader& student, const Value& reference, const Tolerance& t,
                  std::string* message) {
  if (reference.is_vector()) {
    if (!student.json().is_array()) return Match::kWrong;
    auto v = student.vector();
    if (!v.ok) return Match::kWrong;
    NumberVerdict r = compare_vector(v.c, reference.vector, t);
    if (message) *message = r.message;
    return r.match;
  }
  if (!reference.is_scalar() || student.json().is_array()) return Match::kWrong;
  auto n = student.number();
  if (!n.value) return Match::kWrong;
  NumberVerdict r = compare_number(*n.value, reference.scalar, reference.scalar, t);
  if (message) *message = r.message;
  return r.match;
}

namespace {

// A wrong value that is zero (0, or the zero vector) is trivial: what follows from it
// follows for free (f = 0 makes b = 2 D·f = 0), so nothing is carried forward from it. A
// value equal to a given is not trivial: f = C − O = C when O is the origin is a sign slip.
std::optional<std::string> trivial_value(const Value& v) {
  if (v.is_scalar() && v.scalar == 0) return "zero";
  if (v.is_vector() && v.vector == Vec3d{}) return "the zero vector";
  return std::nullopt;
}

// The method whose derivation has the most of the student's step names.
const MethodDerivation* closest_method(const std::vector<MethodDerivation>& reference,
                                       const nlohmann::json& steps) {
  const MethodDerivation* best = nullptr;
  std::size_t best_count = 0;
  for (const auto& m : reference) {
    std::size_t count = 0;
    for (const auto& [name, v] : steps.items()) count += m.derivation.find(name) != nullptr;
    if (!best || count > best_count) {
      best = &m;
      best_count = count;
    }
  }
  return best;
}

// Why a step is wrong that does not follow from the student's own earlier values: a named
// mistake when exactly one gives the value, else the right value.
void explain_wrong_step(const std::vector<MistakenSolution>& mistaken, const std::string& method,
                        const Step& step, const AnswerReader& s, const Value& mine,
                        const Tolerance& tol, const NumberFormat& fmt_numbers, StepsGrade& out,
                        std::vector<std::string>& feedback) {
  // A mistake is named only when it is the one that gives this value.
  std::vector<std::string_view> fit;
  for (const auto& ms : mistaken) {
    if (ms.method != method || ms.parts.empty()) continue;
    const Step* wrong = ms.parts.front().derivation.find(step.name);
    if (!wrong || match_value(s, wrong->value, tol) != Match::kRight) continue;
    if (std::find(fit.begin(), fit.end(), ms.id) == fit.end()) fit.push_back(ms.id);
  }
  if (fit.size() == 1) {
    out.mistakes.push_back(make_mistake(
        fit.front(), "steps/" + step.name,
        fmt::format("you have {} = {}; the right value is {}.", step.name,
                    format_value(mine, fmt_numbers), format_value(step.value, fmt_numbers))));
    feedback.push_back(fmt::format("{} is wrong: see the named mistake.", step.name));
  } else if (fit.size() > 1) {
    std::vector<std::string> titles;
    titles.reserve(fit.size());
    for (std::string_view id : fit) titles.emplace_back(mistake_info(id).title);
    feedback.push_back(fmt::format(
        "{} = {} is not right: it is {}. More than one slip gives your value, so none is "
        "named: {}.",
        step.name, format_value(mine, fmt_numbers), format_value(step.value, fmt_numbers),
        fmt::join(titles, "; or ")));
  } else {
    feedback.push_back(fmt::format("{} = {} is not right: it is {}.", step.name,
                                   format_value(mine, fmt_numbers),
                                   format_value(step.value, fmt_numbers)));
  }
}

}  // namespace

StepsGrade grade_steps(const GradingContext& c, const Task& task,
                       const std::vector<MethodDerivation>& reference,
                       const std::vector<MistakenSolution>& mistaken, const AnswerReader& steps) {
  StepsGrade out;
  if (!steps.json().is_object()) steps.fail("steps is an object: step name → value", "type");
  const Tolerance& tol = c.tolerance.for_field(part_names::kSteps);
  NumberFormat fmt_numbers;
  if (c.problem->precision >= 0) fmt_numbers.decimals = c.problem->precision;
  const MethodDerivation* best = closest_method(reference, steps.json());
  std::vector<std::string> feedback;
  if (!best) {
    out.part =
        make_part(c, part_names::kSteps, 0, {"This problem has no worked steps to compare with."});
    return out;
  }
  out.method = best->method;
  std::vector<std::string> known;
  for (const auto& s : best->derivation.steps) known.push_back(s.name);
  if (steps.json().empty()) {
    out.part = missing_part(
        c, part_names::kSteps,
        fmt::format("No steps given: the steps object is empty (its steps are named as in the "
                    "worked solution: {}).",
                    fmt::join(known, ", ")));
    return out;
  }
  for (const auto& [name, v] : steps.json().items()) {
    if (best->derivation.find(name)) continue;
    std::string hint = closest_match(name, known);
    feedback.push_back(
        hint.empty() ? fmt::format("There is no step '{}' in this solution.", name)
                     : fmt::format("There is no step '{}' (did you mean '{}'?).", name, hint));
  }
  Overrides own;  // the student's values of the wrong steps so far
  double credit = 0;
  int graded = 0;
  for (const auto& step : best->derivation.steps) {
    if (!steps.has(step.name)) continue;
    AnswerReader s = steps.at(step.name);
    ++graded;
    std::string fault, precision;
    if (s.json().is_boolean()) {  // a yes/no step (a comparison)
      bool right = step.value.is_bool() && step.value.truth == s.json().get<bool>();
      credit += right ? 1 : 0;
      if (!right) feedback.push_back(fmt::format("{} is not right.", step.name));
      continue;
    }
    std::optional<Value> mine = student_value(s, &fault);
    if (!mine) {
      feedback.push_back(fmt::format("{}: {}", step.name, fault));
      continue;
    }
    if (mine->kind != step.value.kind) {
      feedback.push_back(fmt::format("{} is {}, not {}.", step.name,
                                     step.value.is_vector() ? "a vector [x, y, z]" : "a number",
                                     mine->is_vector() ? "a vector" : "a number"));
      continue;
    }
    Match m = match_value(s, step.value, tol, &precision);
    if (m == Match::kRight) {
      credit += 1;
      continue;
    }
    if (m == Match::kInsufficientPrecision) {
      credit += tol.precision_credit;
      feedback.push_back(fmt::format("{}: {}", step.name, precision));
      continue;
    }
    // Wrong by the right solution: does it follow from the student's own earlier values?
    bool carried = false;
    if (!own.values.empty()) {
      auto parts = derive_or_nothing(task, best->method, own);
      const Step* ecf = parts.empty() ? nullptr : parts.front().derivation.find(step.name);
      if (ecf && match_value(s, ecf->value, tol) == Match::kRight) {
        carried = true;
        credit += c.points.carried_forward;
        feedback.push_back(fmt::format(
            "{} = {} follows correctly from your earlier values (error carried forward); "
            "with the right values it is {}.",
            step.name, format_value(*mine, fmt_numbers), format_value(step.value, fmt_numbers)));
      }
    }
    if (!carried) {
      explain_wrong_step(mistaken, best->method, step, s, *mine, tol, fmt_numbers, out, feedback);
    }
    out.wrong.push_back(step.name);
    if (std::optional<std::string> trivial = trivial_value(*mine)) {
      // Nothing is carried forward from a trivial value: later steps would follow from it
      // for free (f = 0 makes b = 0 "right").
      feedback.push_back(fmt::format("{} = {} is {}: nothing later is carried forward from it.",
                                     step.name, format_value(*mine, fmt_numbers), *trivial));
      continue;
    }
    own.values[step.name] = *mine;
  }
  if (!out.wrong.empty()) {
    auto parts = derive_or_nothing(task, best->method, own);
    if (!parts.empty()) out.carried = std::move(parts.front().derivation);
  }
  if (graded > 0 && out.wrong.empty() && feedback.empty()) {
    feedback.push_back(fmt::format("All {} steps are right.", graded));
  }
  out.part =
      make_part(c, part_names::kSteps, graded > 0 ? credit / graded : 0, std::move(feedback));
  return out;
}

}  // namespace raygrade
