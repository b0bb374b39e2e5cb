// Grading the kinds of the fields grader (GraderFamily::kFields) by their declared parts:
// each part the student gives is compared by its own rule (a direction as any positive
// multiple, a number by the tolerance, a flag, a set of names), parts that carry no points
// are not required, and every part below full credit says why.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "core/error.h"
#include "derivation/number_format.h"
#include "grading/grade_colour.h"
#include "grading/kind_grader.h"
#include "grading/mistakes.h"
#include "grading/parts.h"
#include "json/cursor.h"
#include "kinds/normal_at.h"
#include "kinds/part_names.h"

namespace raygrade {
namespace {

// A part's verdict: its credit and the sentences that explain it, made together.
struct Verdict {
  Verdict(double c = 0, std::vector<std::string> f = {}, std::vector<FoundMistake> m = {})
      : credit(c), feedback(std::move(f)), mistakes(std::move(m)) {}
  double credit;
  std::vector<std::string> feedback;
  std::vector<FoundMistake> mistakes;  // the named mistakes the part's answer shows
};

Vec3d vec_of(const nlohmann::json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

// Relative difference of two lengths above which a right direction's length is remarked on.
constexpr double kLengthNoteTolerance = kUnitAnswerLength;

class FieldsGrader final : public KindGrader {
 public:
  explicit FieldsGrader(const Problem& p)
      : kind_(p.kind),
        reference_(p.task->answer()),
        normal_task_(dynamic_cast<const NormalTask*>(p.task.get())) {
    context_.problem = &p;
    prepare_step_mistakes(*p.task);
    context_.tolerance = read_tolerance_policy(p);
    if (p.precision >= 0) numbers_.decimals = p.precision;
    std::vector<std::string> names;
    for (const auto& spec : kind_parts(kind_)) names.push_back(spec.name);
    context_.points = read_points_policy(p, default_points(kind_, names));
  }

  void grade(const AnswerReader& a, GradeResult& out) const override {
    std::vector<std::string> names;
    for (const auto& spec : kind_parts(kind_)) names.push_back(spec.name);
    a.allow_only(names);
    for (const auto& spec : kind_parts(kind_)) {
      std::optional<AnswerReader> given = answer_for(a, spec);
      // A part the reference has no value for may be one the answer need not give.
      if (!given && spec.optional_when_absent && !reference_.contains(spec.name)) continue;
      if (!given) {
        out.parts.push_back(missing_part(context_, spec.name,
                                         fmt::format("No {} given ({}).", spec.name, spec.asks)));
        continue;
      }
      Verdict v = grade_part(spec, *given);
      step_mistake(spec, *given, v);
      for (auto& m : v.mistakes) out.mistakes.push_back(std::move(m));
      if (v.credit >= 1 && v.feedback.empty()) v.feedback.emplace_back("Right.");
      out.parts.push_back(make_part(context_, spec.name, v.credit, std::move(v.feedback)));
    }
  }

 private:
  // The student's value for a part: the key itself, or what stands for it (a unit direction
  // is a direction; "total_internal_reflection": true says there is no refracted ray).
  std::optional<AnswerReader> answer_for(const AnswerReader& a, const PartSpec& spec) const {
    if (a.has(spec.name)) return a.at(spec.name);
    for (const auto& alias : spec.aliases) {
      if (a.has(alias)) return a.at(alias);
    }
    const std::string& flag = spec.absent_by_flag;
    if (!flag.empty() && a.has(flag) && a.at(flag).json() == true) {
      return AnswerReader(kNull, nullptr, a.path() + "/" + pointer_token(spec.name));
    }
    return std::nullopt;
  }

  Verdict grade_part(const PartSpec& spec, const AnswerReader& s) const {
    const nlohmann::json* ref =
        reference_.contains(spec.name) ? &reference_.at(spec.name) : nullptr;
    if (spec.compare == Comparison::kRows) return grade_rows(spec, s);
    if (!ref || ref->is_null()) {
      if (s.json().is_null() || s.json() == false) return {1, {}};
      if (spec.zero_when_absent && is_zero(s.json())) return {1, {}};
      return {0, {absent_reason(spec)}};
    }
    if (spec.compare == Comparison::kScalar && ref->is_array()) {
      return grade_colour(spec.name, s, *ref);
    }
    switch (spec.compare) {
      case Comparison::kDirection:
      case Comparison::kUnitDirection: return grade_direction(spec, s, vec_of(*ref));
      case Comparison::kFlag: return grade_flag(spec, s, ref->get<bool>());
      case Comparison::kPoint: return grade_point(spec.name, s, vec_of(*ref));
      case Comparison::kNames: return grade_names(spec.name, s, *ref);
      default: return grade_scalar(spec.name, s, ref->get<double>());
    }
  }

  // The worked solution, and the solutions a catalogued mistake of one of its steps gives
  // (grading/mistakes.h): a part's wrong value is matched against the same step of each.
  void prepare_step_mistakes(const Task& task) {
    std::vector<std::string> methods = task.methods();
    if (methods.empty()) return;
    try {
      right_ = task.derive(methods.front(), nullptr);
    } catch (const Error&) {
      return;
    }
    for (auto& m : mistaken_solutions(task)) {
      if (m.method == methods.front()) mistaken_.push_back(std::move(m));
    }
  }

  // A wrong part whose value is what a mistaken step gives names the mistake, and earns the
  // mistake's credit when that is more than the part had.
  void step_mistake(const PartSpec& spec, const AnswerReader& s, Verdict& v) const {
    if (v.credit >= 1 || !v.mistakes.empty() || mistaken_.empty()) return;
    if (!reference_.contains(spec.name) || s.json().is_null()) return;
    const Step* step = find_answer_step(right_, reference_.at(spec.name));
    if (!step) return;
    const Tolerance& tol = context_.tolerance.for_field(spec.name);
    for (const auto& m : mistaken_) {
      const Step* changed = find_step(m.parts, step->name);
      if (!changed || changed->value.kind != step->value.kind ||
          same_step_value(changed->value, step->value)) {
        continue;
      }
      std::string yours;
      if (changed->value.is_scalar() && s.json().is_number()) {
        auto n = s.number();
        if (!n.value ||
            compare_number(*n.value, changed->value.scalar, changed->value.scalar, tol).match !=
                Match::kRight) {
          continue;
        }
        yours = n.value->text;
      } else if (changed->value.is_vector() && s.json().is_array()) {
        AnswerReader::Vector x = s.vector();
        if (!x.ok) continue;
        bool direction =
            spec.compare == Comparison::kDirection || spec.compare == Comparison::kUnitDirection;
        Match match = direction ? compare_direction(x.c, changed->value.vector, tol).verdict.match
                                : compare_vector(x.c, changed->value.vector, tol).match;
        if (match != Match::kRight) continue;
        yours = format_vector(x.value(), numbers_);
      } else {
        continue;
      }
      std::string msg =
          fmt::format("your {} {} is what the derivation gives with this slip.", spec.name, yours);
      v.mistakes.push_back(make_mistake(m.id, spec.name, msg));
      v.credit = std::max(v.credit, mistake_info(m.id).credit);
      return;
    }
  }

  // Why a part has no value in this problem.
  std::string absent_reason(const PartSpec& spec) const {
    if (spec.why_absent) return spec.why_absent(reference_, [this](double v) { return number(v); });
    return fmt::format("This problem has no {}.", spec.name);
  }

  std::string number(double v) const { return format_number(v, numbers_); }

  Verdict grade_scalar(const std::string& name, const AnswerReader& s, double ref) const {
    const Tolerance& tol = context_.tolerance.for_field(name);
    // The reference at the precision it is graded to.
    auto shown = [&](double v) { return format_number(v, shown_at(tol, ref, numbers_)); };
    if (s.json().is_null()) return {0, {fmt::format("{} is {}, not none.", name, shown(ref))}};
    auto n = s.number();
    if (!n.value) return {0, {fmt::format("{}: {}", name, n.fault)}};
    NumberVerdict v = compare_part(Comparison::kScalar, *n.value, ref, tol).verdict;
    if (v.match == Match::kRight) return {1, {}};
    if (v.match == Match::kInsufficientPrecision) {
      return {tol.precision_credit, {fmt::format("{}: {}", name, v.message)}};
    }
    bool angle = name.find("angle") != std::string::npos;
    double radians = ref * std::numbers::pi / 180;
    if (angle && compare_number(*n.value, radians, radians, tol).match == Match::kRight) {
      return {0,
              {fmt::format("{} = {} is the angle in radians; the answer is in degrees: {}°.", name,
                           n.value->text, shown(ref))}};
    }
    return {
        0, {fmt::format("{} is {}{}, not {}.", name, shown(ref), angle ? "°" : "", n.value->text)}};
  }

  // A light's term the reference has not (no specular term when k_s = 0): zero answers it.
  Verdict grade_no_term(std::string_view key, const AnswerReader& s) const {
    if (is_zero(s.json())) return {1, {}};
    const PartSpec* part = find_part(kind_, key);
    return {0, {part ? absent_reason(*part) : fmt::format("This problem has no {}.", key)}};
  }

  // 0 or [0, 0, 0]: what answers a term that is not there.
  static bool is_zero(const nlohmann::json& j) {
    if (j.is_number()) return j.get<double>() == 0;
    if (!j.is_array()) return false;
    return std::all_of(j.begin(), j.end(), [](const auto& x) {
      return x.is_number() && x.template get<double>() == 0;
    });
  }

  Verdict grade_colour(const std::string& name, const AnswerReader& s,
                       const nlohmann::json& ref) const {
    Vec3d want{ref[0].get<double>(), ref[1].get<double>(), ref[2].get<double>()};
    ColourVerdict v =
        raygrade::grade_colour(name, s, want, context_.tolerance.for_field(name), numbers_);
    return {v.credit, std::move(v.feedback), std::move(v.mistakes)};
  }

  // The named mistakes of a normal problem's normal: the inward normal of a closed object, and a
  // transformed object's normal taken back by A instead of (A⁻¹)ᵀ.
  std::optional<Verdict> normal_mistake(const std::string& name, const AnswerReader::Vector& v,
                                        const Vec3d& ref, bool opposite) const {
    if (!normal_task_ || name != part_names::kNormal) return std::nullopt;
    std::string mine = format_vector(v.value(), numbers_);
    std::string right = format_vector(ref, numbers_);
    if (opposite && normal_task_->solid()) {
      const char* id = "inward-normal";
      std::string msg =
          fmt::format("your normal {} points into the object; outward it is {}.", mine, right);
      return Verdict{mistake_info(id).credit, {msg}, {make_mistake(id, name, msg)}};
    }
    auto by_matrix = normal_task_->normal_by_matrix();
    if (by_matrix &&
        compare_direction(v.c, *by_matrix, context_.tolerance.for_field(name)).verdict.match ==
            Match::kRight) {
      const char* id = "normal-not-inverse-transpose";
      std::string msg = fmt::format(
          "your normal {} is the object's normal taken to the world by the matrix A; by the "
          "inverse transpose (A⁻¹)ᵀ it is {}.",
          mine, right);
      return Verdict{mistake_info(id).credit, {msg}, {make_mistake(id, name, msg)}};
    }
    return std::nullopt;
  }

  Verdict grade_point(const std::string& name, const AnswerReader& s, const Vec3d& ref) const {
    AnswerReader::Vector v = s.vector();
    if (!v.ok) return {0, {fmt::format("{}: {}", name, v.fault)}};
    const Tolerance& tol = context_.tolerance.for_field(name);
    NumberVerdict verdict = compare_part(Comparison::kPoint, v.c, ref, tol).verdict;
    if (verdict.match == Match::kRight) return {1, {}};
    if (verdict.match == Match::kInsufficientPrecision) {
      return {tol.precision_credit, {fmt::format("{}: {}", name, verdict.message)}};
    }
    return {0,
            {fmt::format("The {} is {}, not {}.", name, format_vector(ref, numbers_),
                         format_vector(v.value(), numbers_))}};
  }

  Verdict grade_direction(const PartSpec& spec, const AnswerReader& s, const Vec3d& ref) const {
    const std::string& name = spec.name;
    if (s.json().is_null()) {
      return {0,
              {fmt::format("The ray is refracted (cos²θt = k > 0): its direction is {}.",
                           format_vector(ref, numbers_))}};
    }
    AnswerReader::Vector v = s.vector();
    if (!v.ok) return {0, {fmt::format("{}: {}", name, v.fault)}};
    PartVerdict d = compare_part(spec.compare, v.c, ref, context_.tolerance.for_field(name));
    if (d.length == 0)
      return {0, {fmt::format("{}: a direction cannot be the zero vector.", name)}};
    Vec3d unit = normalized(ref);
    if (d.not_unit) {
      return {0,
              {fmt::format("Your {} points the right way but has length {}; a unit vector "
                           "has length 1: {}.",
                           name, number(d.length), format_vector(unit, numbers_))}};
    }
    if (d.verdict.match == Match::kWrong) {
      if (std::optional<Verdict> m = normal_mistake(name, v, ref, d.opposite)) return *m;
      if (d.opposite) {
        return {
            0,
            {fmt::format("Your {} {} points the opposite way: the answer is {} (or any "
                         "positive multiple).",
                         name, format_vector(v.value(), numbers_), format_vector(ref, numbers_))}};
      }
      return {0,
              {fmt::format("The {} is {} (or any positive multiple), not {}.", name,
                           format_vector(ref, numbers_), format_vector(v.value(), numbers_))}};
    }
    Verdict out{1, {}};
    if (d.verdict.match == Match::kInsufficientPrecision) {
      out.credit = context_.tolerance.for_field(name).precision_credit;
      out.feedback.push_back(fmt::format("{}: {}", name, d.verdict.message));
    }
    if (spec.compare == Comparison::kUnitDirection) return out;
    double ref_length = length(ref);
    bool usual = std::abs(d.length - 1) <= kLengthNoteTolerance ||
                 std::abs(d.length - ref_length) <= kLengthNoteTolerance * ref_length;
    if (!usual) {
      std::string keeps = spec.length_note.empty()
                              ? ""
                              : fmt::format(" ({}, {})", spec.length_note, number(ref_length));
      out.feedback.push_back(fmt::format("Your {} has length {}{}; as a direction it is right.",
                                         name, number(d.length), keeps));
    }
    return out;
  }

  Verdict grade_flag(const PartSpec& spec, const AnswerReader& s, bool ref) const {
    if (!s.json().is_boolean()) s.fail("expected true or false", "type");
    if (s.json().get<bool>() == ref) return {1, {}};
    if (spec.why_flag) {
      return {0, {spec.why_flag(reference_, ref, [this](double v) { return number(v); })}};
    }
    return {0, {fmt::format("{} is {}.", spec.name, ref ? "true" : "false")}};
  }

  Verdict grade_names(const std::string& name, const AnswerReader& s,
                      const nlohmann::json& ref) const {
    std::set<std::string> want, got;
    for (const auto& x : ref) want.insert(x.get<std::string>());
    for (const auto& x : s.items()) got.insert(x.string());
    if (want == got) return {1, {}};
    return {0,
            {fmt::format("The {} that apply are {}, not {}.", name, fmt::join(want, ", "),
                         got.empty() ? "none" : fmt::format("{}", fmt::join(got, ", ")))}};
  }

  // Each light of the answer, by name or in order: every field given must be right.
  Verdict grade_rows(const PartSpec& spec, const AnswerReader& s) const {
    const nlohmann::json& ref = reference_.at(spec.name);
    std::vector<AnswerReader> given = s.items();
    Verdict out;
    double right = 0;
    for (std::size_t i = 0; i < given.size(); ++i) {
      const AnswerReader& g = given[i];
      g.allow_only(
          {"light", "n_dot_l", "r_dot_v", "reaches", part_names::kDiffuse, part_names::kSpecular});
      const nlohmann::json* r = i < ref.size() ? &ref[i] : nullptr;
      if (g.has("light")) {
        r = nullptr;
        for (const auto& x : ref) {
          if (x.at("light") == g.at("light").json()) r = &x;
        }
      }
      if (!r) {
        out.feedback.push_back(fmt::format("{}: the problem has no such light.", g.path()));
        continue;
      }
      std::string light = r->at("light").get<std::string>();
      std::size_t before = out.feedback.size();
      for (const char* key : {"n_dot_l", "r_dot_v", "diffuse", "specular"}) {
        if (!g.has(key)) continue;
        Verdict v = !r->contains(key) ? grade_no_term(key, g.at(key))
                    : r->at(key).is_array()
                        ? grade_colour(key, g.at(key), r->at(key))
                        : grade_scalar(key, g.at(key), r->at(key).get<double>());
        for (auto& m : v.mistakes) out.mistakes.push_back(std::move(m));
        if (v.credit < 1) out.feedback.push_back(fmt::format("Light {}: {}", light, v.feedback[0]));
      }
      if (g.has("reaches")) {
        bool want = r->at("reaches").get<bool>();
        if (!g.at("reaches").json().is_boolean())
          g.at("reaches").fail("expected true or false", "type");
        if (g.at("reaches").json().get<bool>() != want) {
          out.feedback.push_back(
              want ? fmt::format("Light {} reaches the point.", light)
              : r->at("n_dot_l").get<double>() <= 0
                  ? fmt::format("Light {} does not reach the point: the surface faces away from "
                                "it (N·L ≤ 0).",
                                light)
                  : fmt::format("Light {} does not reach the point: its shadow ray is blocked.",
                                light));
        }
      }
      if (out.feedback.size() == before) right += 1;
    }
    std::size_t d = std::max(ref.size(), given.size());
    for (std::size_t i = given.size(); i < ref.size(); ++i) {
      out.feedback.push_back(
          fmt::format("Light {} is not given.", ref[i].at("light").get<std::string>()));
    }
    out.credit = d ? right / static_cast<double>(d) : 1;
    return out;
  }

  static inline const nlohmann::json kNull = nullptr;
  std::string kind_;
  nlohmann::json reference_;
  const NormalTask* normal_task_;           // for a normal problem's named mistakes
  std::vector<SolutionPart> right_;         // the worked solution, by the first method
  std::vector<MistakenSolution> mistaken_;  // it with each catalogued mistake of a step
  NumberFormat numbers_;
};

}  // namespace

std::shared_ptr<const KindGrader> make_fields_grader(const Problem& p) {
  return std::make_shared<FieldsGrader>(p);
}

}  // namespace raygrade
