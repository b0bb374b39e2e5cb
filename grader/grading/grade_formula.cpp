// Grading the kind `derive`: a student's formula is checked by evaluating it against the
// reference formula at random points, as WeBWorK and STACK do, and against the formulas the
// catalogued mistakes give.
#include <fmt/format.h>

#include <cmath>
#include <random>

#include "grading/kind_grader.h"
#include "grading/mistakes.h"
#include "kinds/derive.h"

namespace raygrade {
namespace {

// Points at which formulas are compared. Two different polynomials of low degree agree at
// twelve random points with probability zero; twelve keeps a class of answers fast.
constexpr int kFormulaPoints = 12;
// The seed of the points (mixed with the problem's id): the same points on every run, so a
// grade never changes between runs.
constexpr std::uint64_t kFormulaSeed = 0x5eed000c711de7ULL;
// Agreement at a point: relative to the values' size, far above the rounding of a few dozen
// operations (about 1e-15) and far below any real difference.
constexpr double kFormulaRelative = 1e-9;
// Symbols are drawn from [-kSymbolRange, kSymbolRange]; a radius r from [kRadiusLow, kSymbolRange].
constexpr double kSymbolRange = 3;
constexpr double kRadiusLow = 0.5;

std::uint64_t fnv1a(std::string_view s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (char c : s) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

struct Quantity {
  std::string name;
  std::vector<double> reference;  // at each point
  std::vector<std::pair<std::string, std::vector<double>>> mistakes;
};

class FormulaGrader final : public KindGrader {
 public:
  explicit FormulaGrader(const Problem& p) : task_(dynamic_cast<const DeriveTask&>(*p.task)) {
    context_.problem = &p;
    context_.tolerance = read_tolerance_policy(p);
    std::vector<std::pair<std::string, double>> parts;
    for (const auto& q : task_.quantities()) parts.emplace_back(q.name, 1);
    context_.points = read_points_policy(p, parts);
    for (const auto& s : task_.symbols()) {
      std::vector<std::string> aliases;
      if (s.display != s.name) aliases.push_back(s.display);
      symbols_.add(s.name, aliases);
    }
    std::mt19937_64 rng(kFormulaSeed ^ fnv1a(p.id));
    auto uniform = [&](double lo, double hi) {
      return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    };
    std::vector<Env> envs;
    for (int k = 0; k < kFormulaPoints; ++k) {
      std::vector<double> values;
      Env env;
      for (const auto& s : task_.symbols()) {
        // not a part: the formula's symbol r, a radius
        double v = s.name == "r" ? uniform(kRadiusLow, kSymbolRange)
                                 : uniform(-kSymbolRange, kSymbolRange);
        values.push_back(v);
        env[s.name] = v;
      }
      points_.push_back(std::move(values));
      envs.push_back(std::move(env));
    }
    for (const auto& q : task_.quantities()) {
      Quantity out{q.name, {}, {}};
      for (const auto& env : envs) out.reference.push_back(evaluate(q.formula, env).scalar);
      for (const auto& fm : formula_mistakes()) {
        auto wrong = fm.rewrite(q.name, q.formula);
        if (!wrong) continue;
        std::vector<double> values;
        try {
          for (const auto& env : envs) values.push_back(evaluate(*wrong, env).scalar);
        } catch (const EvaluationFault&) {  // the mistake does not apply to this formula
          continue;
        }
        if (!agree(values, out.reference)) out.mistakes.emplace_back(fm.id, std::move(values));
      }
      quantities_.push_back(std::move(out));
    }
  }

  void grade(const AnswerReader& a, GradeResult& out) const override {
    std::vector<std::string> names;
    for (const auto& q : quantities_) names.push_back(q.name);
    a.allow_only(names);
    for (std::size_t i = 0; i < quantities_.size(); ++i) {
      const Quantity& q = quantities_[i];
      if (!a.has(q.name)) {
        out.parts.push_back(missing_part(context_, q.name));
        continue;
      }
      AnswerReader s = a.at(q.name);
      std::string text = s.json().is_number() ? s.json().dump() : s.string();
      FormulaParse parsed = parse_formula(text, &symbols_);
      if (!parsed.ok) {
        out.parts.push_back(
            make_part(context_, q.name, 0,
                      {fmt::format("Could not read {} = {}: {}.", q.name, text, parsed.message)}));
        continue;
      }
      std::vector<double> mine;
      for (const auto& p : points_) mine.push_back(parsed.formula.evaluate(p));
      if (agree(mine, q.reference)) {
        out.parts.push_back(make_part(context_, q.name, 1, {"Right."}));
        continue;
      }
      bool named = false;
      for (const auto& [id, values] : q.mistakes) {
        if (!agree(mine, values)) continue;
        out.mistakes.push_back(
            make_mistake(id, q.name, fmt::format("{} = {} is what it gives.", q.name, text)));
        out.parts.push_back(
            make_part(context_, q.name, mistake_info(id).credit,
                      {fmt::format("{} = {}.", q.name, task_.quantities()[i].display)}));
        named = true;
        break;
      }
      if (!named) {
        out.parts.push_back(
            make_part(context_, q.name, 0,
                      {fmt::format("{} = {} is not equivalent to the right formula, {} = {}.",
                                   q.name, text, q.name, task_.quantities()[i].display)}));
      }
    }
  }

 private:
  // Two formulas agree when they agree at every point where the reference is defined (at
  // least half of them).
  static bool agree(const std::vector<double>& mine, const std::vector<double>& ref) {
    int defined = 0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
      if (!std::isfinite(ref[k])) continue;
      ++defined;
      if (!std::isfinite(mine[k])) return false;
      double scale = std::max({1.0, std::abs(ref[k]), std::abs(mine[k])});
      if (std::abs(mine[k] - ref[k]) > kFormulaRelative * scale) return false;
    }
    return 2 * defined >= static_cast<int>(ref.size());
  }

  const DeriveTask& task_;
  SymbolTable symbols_;
  std::vector<std::vector<double>> points_;
  std::vector<Quantity> quantities_;
};

}  // namespace

std::shared_ptr<const KindGrader> make_formula_grader(const Problem& p) {
  return std::make_shared<FormulaGrader>(p);
}

}  // namespace raygrade
