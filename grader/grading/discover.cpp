// Single changes to a variant's derivation, matched against wrong answers.
#include "grading/discover.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <tuple>

#include "core/error.h"
#include "derivation/formula.h"
#include "kinds/derive.h"

namespace raygrade {

std::string StepChange::text() const {
  return fmt::format("{} = {} → {} = {}", step, before, step, after);
}

const char* to_string(Discovery::Verdict v) {
  switch (v) {
    case Discovery::Verdict::kExplained: return "explained";
    case Discovery::Verdict::kAmbiguous: return "ambiguous";
    case Discovery::Verdict::kNoisy: return "noisy";
    case Discovery::Verdict::kNone: return "none";
  }
  return "none";
}

// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace discover_internal {

// Two numbers of two derivations are the same number: far below any tolerance, above rounding.
constexpr double kSameNumber = 1e-9;

bool same_number(double a, double b) {
  return std::abs(a - b) <= kSameNumber * (1 + std::abs(a) + std::abs(b));
}

// One number of an answer: where it is, and what a derivation step gives it.
struct Leaf {
  nlohmann::json::json_pointer path;
  std::string field;     // the nearest object key above it ("t", "point")
  int component = -1;    // 0..2 when it is a component of a vector [x, y, z]
  nlohmann::json value;  // the reference's (a number, string or boolean)
  double number = NAN;   // the reference's number, when it is one
  std::string step;      // the step that computes it ("" when none does)
  std::size_t part = 0;  // the part of the derivation the step is in
  int occurrence = 0;    // which of the part's steps of that name
};

bool is_vector3(const nlohmann::json& j) {
  return j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number();
}

void flatten(const nlohmann::json& j, const nlohmann::json::json_pointer& at,
             const std::string& field, std::vector<Leaf>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, at / k, k, out);
  } else if (j.is_array()) {
    bool vector = is_vector3(j);
    for (std::size_t i = 0; i < j.size(); ++i) {
      std::size_t before = out.size();
      flatten(j[i], at / i, field, out);
      if (vector && out.size() == before + 1) out.back().component = static_cast<int>(i);
    }
  } else if (!j.is_null()) {
    Leaf l;
    l.path = at;
    l.field = field;
    l.value = j;
    if (j.is_number()) l.number = j.get<double>();
    out.push_back(std::move(l));
  }
}

// A student's number as typed: a JSON number, or a formula of numbers ("9 - sqrt(3)"); with
// `symbols`, a formula in them too ("px^2 + py^2 - r^2"), at `values`.
std::optional<double> student_number(const nlohmann::json& j, const SymbolTable* symbols,
                                     const std::vector<double>& values) {
  if (j.is_number()) return j.get<double>();
  if (!j.is_string()) return std::nullopt;
  FormulaParse p = parse_formula(j.get<std::string>(), symbols);
  if (!p.ok || (p.formula.uses_symbols && !symbols)) return std::nullopt;
  double v = p.formula.evaluate(values);
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// A derivation's step values by (part, name, occurrence).
using StepValues = std::map<std::tuple<std::size_t, std::string, int>, Value>;

StepValues step_values(const std::vector<SolutionPart>& parts) {
  StepValues out;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    std::map<std::string, int> seen;
    for (const auto& s : parts[p].derivation.steps) out[{p, s.name, seen[s.name]++}] = s.value;
  }
  return out;
}

// The number a derivation gives a leaf: NaN when the step is missing or of another type.
double leaf_value(const StepValues& values, const Leaf& l) {
  auto it = values.find({l.part, l.step, l.occurrence});
  if (it == values.end()) return NAN;
  const Value& v = it->second;
  if (l.component >= 0) return v.is_vector() ? v.vector[l.component] : NAN;
  return v.is_scalar() ? v.scalar : NAN;
}

// Ties each numeric leaf to the last step whose value is that number (a component: whose
// vector is the leaf's whole vector).
// With `by_name`, each leaf is tied to the last step named as its field instead (a formula's
// value may be another step's too).
void map_leaves(std::vector<Leaf>& leaves, const nlohmann::json& answer,
                const std::vector<SolutionPart>& parts, bool by_name) {
  for (auto& l : leaves) {
    if (!l.value.is_number()) continue;
    if (by_name) {
      for (std::size_t p = 0; p < parts.size(); ++p) {
        std::map<std::string, int> seen;
        for (const auto& s : parts[p].derivation.steps) {
          int occ = seen[s.name]++;
          if (s.name == l.field && !s.given && s.value.is_scalar()) {
            l.step = s.name;
            l.part = p;
            l.occurrence = occ;
          }
        }
      }
      continue;
    }
    std::optional<Vec3d> whole;
    if (l.component >= 0) {
      const auto& arr = answer.at(l.path.parent_pointer());
      whole = Vec3d{arr[0].get<double>(), arr[1].get<double>(), arr[2].get<double>()};
    }
    for (std::size_t p = 0; p < parts.size(); ++p) {
      std::map<std::string, int> seen;
      for (const auto& s : parts[p].derivation.steps) {
        int occ = seen[s.name]++;
        bool fits = whole ? s.value.is_vector() && same_number(s.value.vector.x, whole->x) &&
                                same_number(s.value.vector.y, whole->y) &&
                                same_number(s.value.vector.z, whole->z)
                          : s.value.is_scalar() && same_number(s.value.scalar, l.number);
        if (fits && !s.given) {
          l.step = s.name;
          l.part = p;
          l.occurrence = occ;
        }
      }
    }
  }
}

// An alternative formula: what is evaluated, and how it is shown.
struct Alt {
  E eval;
  E shown;
  std::string kind;
};

E with_arg(const E& e, std::size_t i, const E& a) {
  auto n = std::make_shared<ExprNode>(e.node());
  n->args[i] = a;
  return E(std::shared_ptr<const ExprNode>(std::move(n)));
}

E with_op(const E& e, Op op) {
  auto n = std::make_shared<ExprNode>(e.node());
  n->op = op;
  return E(std::shared_ptr<const ExprNode>(std::move(n)));
}

// What the changes of a formula may use: every step's value, and the given vectors.
struct Context {
  Env values;
  std::vector<std::pair<std::string, E>> given_vectors;  // name, symbol
};

// Which changes: the changes of an operator, a constant or a step's sign (tier 0), the changes
// that put another quantity for a vector (tier 1: one per given vector, so as many as the
// problem has vertices), or both, in the order of the formula.
enum class Tier { kOperators, kOperands, kAll };

bool in_tier(Tier want, Tier t) { return want == Tier::kAll || want == t; }

void symbol_alternatives(const E& e, const Context& c, Tier tier, std::vector<Alt>& out) {
  const ExprNode& n = e.node();
  auto it = c.values.find(n.name);
  if (it == c.values.end() || !it->second.is_vector()) return;
  Vec3d v = it->second.vector;
  constexpr double kUnit = 1e-9;  // a vector of length 1 needs no normalising
  if (std::abs(length(v) - 1) > kUnit && in_tier(tier, Tier::kOperators)) {
    E unit = e / norm(e);
    out.push_back({unit, unit, "normalise"});
  }
  if (!in_tier(tier, Tier::kOperands)) return;
  for (const auto& [name, symbol] : c.given_vectors) {
    if (name != n.name) out.push_back({symbol, symbol, "vector-swap"});
  }
  static const char* const kAxes[] = {"x", "y", "z"};
  std::string shown = to_text(e);
  for (int k = 0; k < 3; ++k) {
    if (v[k] == 0) continue;
    E parts[3], names[3];
    for (int i = 0; i < 3; ++i) {
      Vec3d axis{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
      parts[i] = i == k ? E(0) : dot(e, vec(axis));
      names[i] = i == k ? E(0) : sym("", shown + "_" + kAxes[i]);
    }
    out.push_back(
        {tuple(parts[0], parts[1], parts[2]), tuple(names[0], names[1], names[2]), "component"});
  }
}

// The changes at the node `e` itself.
void local_alternatives(const E& e, const Context& c, Tier tier, std::vector<Alt>& out) {
  const ExprNode& n = e.node();
  if (n.op == Op::kSymbol) return symbol_alternatives(e, c, tier, out);
  if (!in_tier(tier, Tier::kOperators)) return;
  auto both = [&](const E& x, const char* kind) { out.push_back({x, x, kind}); };
  const auto& a = n.args;
  switch (n.op) {
    case Op::kAdd:
      both(a[0] - a[1], "sign");
      both(a[0], "drop-term");
      both(a[1], "drop-term");
      break;
    case Op::kSub:
      both(a[0] + a[1], "sign");
      both(a[1] - a[0], "swap");
      both(a[0], "drop-term");
      both(-a[1], "drop-term");
      break;
    case Op::kNeg: both(a[0], "sign"); break;
    case Op::kMul:
      if (a[0].node().op == Op::kNumber) both(a[1], "drop-term");
      if (a[1].node().op == Op::kNumber) both(a[0], "drop-term");
      break;
    case Op::kDiv:
      both(a[1] / a[0], "swap");
      both(a[0], a[1].node().op == Op::kNorm ? "normalise" : "drop-term");
      break;
    case Op::kCross: both(cross(a[1], a[0]), "swap"); break;
    case Op::kSquare: both(a[0], "square"); break;
    case Op::kSqrt: both(a[0], "sqrt"); break;
    case Op::kMin: both(with_op(e, Op::kMax), "other-root"); break;
    case Op::kMax: both(with_op(e, Op::kMin), "other-root"); break;
    case Op::kArccosDegrees: both(e * (std::numbers::pi / 180), "degrees"); break;
    default: break;
  }
}

// How many changes of `tier` the formula `e` has, anywhere in its tree, without making them:
// a formula of a thousand terms has that many, and each change made copies its path.
std::size_t count_alternatives(const E& e, const Context& c, Tier tier) {
  if (e.empty()) return 0;
  const ExprNode& n = e.node();
  if (n.op == Op::kSymbol) {
    auto it = c.values.find(n.name);
    if (it == c.values.end() || !it->second.is_vector()) return 0;
    Vec3d v = it->second.vector;
    std::size_t k = 0;
    if (std::abs(length(v) - 1) > 1e-9 && in_tier(tier, Tier::kOperators)) ++k;
    if (in_tier(tier, Tier::kOperands)) {
      for (const auto& g : c.given_vectors) k += g.first != n.name;
      for (int i = 0; i < 3; ++i) k += v[i] != 0;
    }
    return k;
  }
  std::vector<Alt> local;
  if (in_tier(tier, Tier::kOperators)) local_alternatives(e, c, Tier::kOperators, local);
  std::size_t k = local.size();
  for (const E& a : n.args) k += count_alternatives(a, c, tier);
  return k;
}

// Calls `sink` with each single change of `tier` of the formula `e`, anywhere in its tree (the
// node's own first, then each operand's), until `left` of them have been made. Returns false
// when it stopped for `left`.
bool each_alternative(const E& e, const Context& c, Tier tier, std::size_t& left,
                      const std::function<void(Alt&&)>& sink) {
  if (e.empty()) return true;
  std::vector<Alt> local;
  local_alternatives(e, c, tier, local);
  for (auto& a : local) {
    if (left == 0) return false;
    --left;
    sink(std::move(a));
  }
  if (e.node().op == Op::kSymbol) return true;  // its args are how it is shown
  for (std::size_t i = 0; i < e.node().args.size(); ++i) {
    bool more = each_alternative(e.node().args[i], c, tier, left, [&](Alt&& x) {
      sink({with_arg(e, i, x.eval), with_arg(e, i, x.shown), std::move(x.kind)});
    });
    if (!more) return false;
  }
  return true;
}

// The nodes of a formula: what evaluating it costs.
std::size_t formula_size(const E& e) {
  if (e.empty()) return 0;
  std::size_t k = 1;
  if (e.node().op != Op::kSymbol)
    for (const E& a : e.node().args) k += formula_size(a);
  return k;
}

// The largest level L such that the counts, each cut to L, sum to at most `budget` (every
// count's when they fit).
std::size_t water_level(const std::vector<std::size_t>& counts, std::size_t budget) {
  std::size_t hi = 0;
  for (std::size_t n : counts) hi = std::max(hi, n);
  auto total = [&](std::size_t level) {
    std::size_t t = 0;
    for (std::size_t n : counts) t += std::min(n, level);
    return t;
  };
  std::size_t lo = 0;
  while (lo < hi) {
    std::size_t mid = lo + (hi - lo + 1) / 2;
    if (total(mid) <= budget)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

// Numbers that fit one answer: the changes giving them, and their chance to fit at random.
struct Prediction {
  std::vector<double> numbers;  // per leaf (NaN for a leaf with no step)
  std::vector<StepChange> changes;
};

// How many of each step's changes the budget pays for: all of them when they fit; else each
// step an equal share of its operators' changes (the whole step negated among them) first, then
// what is left in equal shares of its operands'.
struct Shares {
  std::vector<std::size_t> ops, operands, take_ops, take_operands;
  bool truncated = false;
};
Shares shares(const std::vector<const Step*>& steps, const Context& c, std::size_t budget) {
  Shares r;
  r.ops.resize(steps.size());
  r.operands.resize(steps.size());
  std::size_t total = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    r.ops[i] = 1 + count_alternatives(steps[i]->formula, c, Tier::kOperators);  // 1: negated
    r.operands[i] = count_alternatives(steps[i]->formula, c, Tier::kOperands);
    total += r.ops[i] + r.operands[i];
  }
  r.take_ops = r.ops;
  r.take_operands = r.operands;
  if (total <= budget) return r;
  r.truncated = true;
  std::size_t level = water_level(r.ops, budget), used = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) used += r.take_ops[i] = std::min(r.ops[i], level);
  bool all_ops = used == std::accumulate(r.ops.begin(), r.ops.end(), std::size_t{0});
  std::size_t level1 = all_ops ? water_level(r.operands, budget - used) : 0;
  for (std::size_t i = 0; i < steps.size(); ++i)
    r.take_operands[i] = std::min(r.operands[i], level1);
  return r;
}

}  // namespace discover_internal

struct ChangeSearch::Impl {
  std::vector<discover_internal::Leaf> leaves;
  std::vector<double> reference;      // per leaf
  std::vector<bool> computed;         // per leaf: some method's step computes it
  SymbolTable symbols;                // a derive problem's symbols ("px", also "p_x")
  std::vector<double> symbol_values;  // their values in the problem's own numbers
  TolerancePolicy tolerance;
  std::vector<discover_internal::Prediction> predictions;
  std::size_t changes = 0;
  std::size_t derivations = 0;  // changed derivations worked
  std::size_t work = 0;         // their cost: steps and formula nodes
  bool truncated = false;       // some changes were left out for the budget

  double allowed_at(std::size_t i, const std::vector<double>& numbers) const {
    const discover_internal::Leaf& l = leaves[i];
    const Tolerance& t = tolerance.for_field(l.field);
    double scale = std::abs(numbers[i]);
    if (l.component >= 0) {
      double s2 = 0;
      for (std::size_t k = 0; k < leaves.size(); ++k) {
        if (leaves[k].component >= 0 && leaves[k].path.parent_pointer() == l.path.parent_pointer())
          s2 += numbers[k] * numbers[k];
      }
      scale = std::sqrt(s2);
    }
    return allowed_error(numbers[i], scale, t);
  }

  // `mapped`: the leaves as the change's method computes them.
  void add(const StepChange& change, const std::vector<discover_internal::Leaf>& mapped,
           std::vector<double> numbers) {
    using discover_internal::same_number;
    bool moved = false;
    for (std::size_t i = 0; i < numbers.size(); ++i) {
      if (!mapped[i].step.empty() && !std::isfinite(numbers[i])) return;
      if (std::isfinite(numbers[i]) && !same_number(numbers[i], reference[i])) moved = true;
    }
    if (!moved) return;
    ++changes;
    for (std::size_t i = 0; i < numbers.size(); ++i)
      if (std::isnan(numbers[i])) numbers[i] = reference[i];
    for (auto& p : predictions) {
      bool same = true;
      for (std::size_t i = 0; i < numbers.size() && same; ++i)
        same = (std::isnan(numbers[i]) && std::isnan(p.numbers[i])) ||
               same_number(numbers[i], p.numbers[i]);
      if (same) {
        p.changes.push_back(change);
        return;
      }
    }
    predictions.push_back(discover_internal::Prediction{std::move(numbers), {change}});
  }
};

ChangeSearch::~ChangeSearch() = default;
std::size_t ChangeSearch::changes() const { return impl_->changes; }
std::size_t ChangeSearch::derivations() const { return impl_->derivations; }
std::size_t ChangeSearch::work() const { return impl_->work; }
bool ChangeSearch::truncated() const { return impl_->truncated; }

ChangeSearch::ChangeSearch(const Problem& problem) : impl_(std::make_unique<Impl>()) {
  using namespace discover_internal;  // NOLINT: this file's own functions
  Impl& m = *impl_;
  try {
    m.tolerance = read_tolerance_policy(problem);
  } catch (const Error&) {
    // The grader reports a faulty tolerance; the search uses the defaults.
  }
  const Task& task = *problem.task;
  // The problem's method first: its derivation must work (an Error here is the caller's); then
  // the kind's others, each skipped when it cannot be worked for these numbers.
  std::vector<std::string> methods = task.methods();
  std::string first = problem.method.empty() && !methods.empty() ? methods.front() : problem.method;
  std::erase(methods, first);
  methods.insert(methods.begin(), first);
  if (methods.size() > kMaxSearchedMethods) methods.resize(kMaxSearchedMethods);
  nlohmann::json answer = task.answer();
  // A derive problem is answered by formulas in its symbols. A change alters a quantity's
  // formula, so each formula is compared by its value at the problem's own numbers: the value
  // of the quantity's step, and of the student's formula with the symbols at those numbers.
  const auto* derive = dynamic_cast<const DeriveTask*>(&task);
  if (derive) {
    for (const auto& s : derive->symbols()) {
      std::vector<std::string> aliases;
      if (s.display != s.name) aliases.push_back(s.display);
      m.symbols.add(s.name, aliases);
      m.symbol_values.push_back(s.example);
    }
    StepValues values = step_values(task.derive(first));
    for (const auto& q : derive->quantities()) {
      for (const auto& [at, v] : values)
        if (std::get<1>(at) == q.name && v.is_scalar()) answer[q.name] = v.scalar;
    }
  }
  flatten(answer, nlohmann::json::json_pointer(), "", m.leaves);
  for (const auto& l : m.leaves) m.reference.push_back(l.number);
  std::vector<bool> computed(m.leaves.size(), false);
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const std::string& method = methods[k];
    std::vector<SolutionPart> right;
    try {
      right = task.derive(method);
    } catch (const Error&) {
      if (k == 0) throw;
      continue;
    }
    std::vector<Leaf> mapped = m.leaves;
    map_leaves(mapped, answer, right, derive != nullptr);
    for (std::size_t i = 0; i < mapped.size(); ++i)
      computed[i] = computed[i] || !mapped[i].step.empty();
    // The steps and formulas to change, once each.
    Context c;
    std::vector<const Step*> steps;
    std::set<std::pair<std::string, std::string>> seen;
    for (const auto& part : right) {
      for (const auto& s : part.derivation.steps) {
        c.values[s.name] = s.value;
        if (s.given && s.value.is_vector()) c.given_vectors.emplace_back(s.name, s.symbol);
        if (!s.given && !s.formula.empty() && seen.insert({s.name, to_text(s.formula)}).second)
          steps.push_back(&s);
      }
    }
    // What a changed derivation costs (its steps and their formulas' nodes), and how many
    // changes this method's share of the budget pays for. A formula of n terms has n changes of
    // its operators and, for each vector in it, one per given vector: n² for a polygon's
    // Newell sum. Beyond the budget, each step gets an equal share of its operators' changes
    // first (every change of a short step), then of its operands'.
    std::size_t cost = 0;
    for (const auto& part : right) {
      for (const auto& s : part.derivation.steps) cost += 1 + formula_size(s.formula);
    }
    std::size_t budget = std::max(kMinSearchedChanges, kSearchWork / methods.size() / cost);
    const auto& [ops, operands, take_ops, take_operands, cut] = shares(steps, c, budget);
    m.truncated = m.truncated || cut;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const Step* s = steps[i];
      std::string before = to_text(s->formula);
      auto try_change = [&](Alt&& alt) {
        ++m.derivations;
        m.work += cost;
        Overrides o;
        o.formula = [&](std::string_view step, const E& f) -> std::optional<E> {
          if (step != s->name || to_text(f) != before) return std::nullopt;
          return alt.eval;
        };
        std::vector<double> numbers;
        try {
          StepValues values = step_values(task.derive(method, &o));
          for (const auto& l : mapped)
            numbers.push_back(l.step.empty() ? NAN : leaf_value(values, l));
        } catch (const Error&) {
          return;  // the change leaves the method's way (no root where one was)
        } catch (const EvaluationFault&) {
          return;  // the change makes no sense here (a vector where a number was)
        }
        m.add(StepChange{method, s->name, alt.kind, before, to_text(alt.shown)}, mapped,
              std::move(numbers));
      };
      Alt negated{-s->formula, -s->formula, "sign"};
      if (take_ops[i] == ops[i] && take_operands[i] == operands[i]) {
        // Every change of the step, in the formula's order, the whole step negated last.
        std::size_t left = ops[i] + operands[i];
        each_alternative(s->formula, c, Tier::kAll, left, try_change);
        try_change(std::move(negated));
        continue;
      }
      std::size_t left = take_ops[i];
      if (left > 0) {
        --left;
        try_change(std::move(negated));
      }
      each_alternative(s->formula, c, Tier::kOperators, left, try_change);
      left = take_operands[i];
      each_alternative(s->formula, c, Tier::kOperands, left, try_change);
    }
  }
  // A number some method computes can be explained; one that none computes cannot.
  for (std::size_t i = 0; i < m.leaves.size(); ++i) m.computed.push_back(computed[i]);
}

Discovery ChangeSearch::explain(const nlohmann::json& answer) const {
  using namespace discover_internal;  // NOLINT: this file's own functions
  const Impl& m = *impl_;
  Discovery d;
  std::vector<double> given(m.leaves.size(), NAN);
  bool wrong = false, compared = false;
  for (std::size_t i = 0; i < m.leaves.size(); ++i) {
    const Leaf& l = m.leaves[i];
    if (!answer.contains(l.path)) continue;
    const nlohmann::json& s = answer.at(l.path);
    if (!l.value.is_number()) {
      if (s != l.value) return d;  // a word or a verdict no change of a number explains
      continue;
    }
    std::optional<double> x =
        student_number(s, m.symbol_values.empty() ? nullptr : &m.symbols, m.symbol_values);
    if (!x) return d;
    given[i] = *x;
    compared = true;
    if (std::abs(*x - m.reference[i]) > m.allowed_at(i, m.reference)) {
      if (!m.computed[i]) return d;  // a number no step computes
      wrong = true;
    }
  }
  if (!compared || !wrong) return d;
  // The changed answers that fit, told apart by the numbers the student gave alone; and the
  // chance that a random answer of those numbers fits some changed answer.
  std::vector<const Prediction*> fits;
  std::size_t distinct = 0;
  std::vector<std::vector<double>> seen(1);  // the reference's numbers fit no wrong answer
  for (std::size_t i = 0; i < given.size(); ++i)
    if (!std::isnan(given[i])) seen[0].push_back(m.reference[i]);
  for (const auto& p : m.predictions) {
    std::vector<double> on_given;
    double chance = 1;
    bool fit = true;
    for (std::size_t i = 0; i < given.size(); ++i) {
      if (std::isnan(given[i])) continue;
      double allowed = m.allowed_at(i, p.numbers);
      on_given.push_back(p.numbers[i]);
      chance *= std::min(1.0, allowed / std::max(1.0, std::abs(m.reference[i])));
      fit = fit && std::abs(given[i] - p.numbers[i]) <= allowed;
    }
    bool repeated = std::any_of(seen.begin(), seen.end(), [&](const std::vector<double>& q) {
      for (std::size_t k = 0; k < q.size(); ++k)
        if (!same_number(q[k], on_given[k])) return false;
      return true;
    });
    if (repeated) {
      if (fit) fits.push_back(&p);
      continue;
    }
    seen.push_back(on_given);
    d.random_fit += chance;
    if (fit) {
      fits.push_back(&p);
      ++distinct;
    }
  }
  if (fits.empty()) return d;
  d.fitting = distinct;
  if (d.random_fit > kMaxRandomFit) {
    d.verdict = Discovery::Verdict::kNoisy;
  } else if (distinct > 1) {
    d.verdict = Discovery::Verdict::kAmbiguous;
  } else {
    d.verdict = Discovery::Verdict::kExplained;
    for (const Prediction* p : fits)
      d.changes.insert(d.changes.end(), p->changes.begin(), p->changes.end());
  }
  return d;
}

}  // namespace raygrade
