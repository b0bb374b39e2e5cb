// The operators of the mistake search, applied to every node of a step's formula.
#include "grading/change_operators.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace raygrade {

const std::vector<std::string_view>& change_kinds() {
  // The changes an earlier search made (and its tests name) first, in its order; then the
  // insertions, the replacements of a quantity, and the exchanges.
  static const std::vector<std::string_view> k = {
      "sign",      "drop-term",  "swap",        "square",   "sqrt",     "abs",
      "normalise", "other-root", "degrees",     "function", "clamp",    "operator",
      "constant",  "factor",     "vector-swap", "operand",  "exchange", "component"};
  return k;
}

std::size_t change_rank(std::string_view kind) {
  const auto& k = change_kinds();
  return static_cast<std::size_t>(std::find(k.begin(), k.end(), kind) - k.begin());
}

// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace change_operators_internal {

using Kind = Value::Kind;

// The type of a formula's value, from its operators and its symbols' values (kNone: unknown).
Kind type_of(const E& e, const Env& env) {
  const ExprNode& n = e.node();
  switch (n.op) {
    case Op::kVector:
    case Op::kCross:
    case Op::kTuple: return Kind::kVector;
    case Op::kSymbol: {
      auto it = env.find(n.name);
      return it == env.end() ? Kind::kNone : it->second.kind;
    }
    case Op::kAdd:
    case Op::kSub:
    case Op::kNeg:
    case Op::kDiv: return type_of(n.args[0], env);
    case Op::kMul: {
      Kind a = type_of(n.args[0], env), b = type_of(n.args[1], env);
      if (a == Kind::kVector || b == Kind::kVector) return Kind::kVector;
      return a == Kind::kNone || b == Kind::kNone ? Kind::kNone : Kind::kScalar;
    }
    case Op::kCompare: return Kind::kBool;
    default: return Kind::kScalar;
  }
}

bool is(const E& e, Op op) { return e.node().op == op; }

E with_op(const E& e, Op op) {
  auto n = std::make_shared<ExprNode>(e.node());
  n->op = op;
  return E(std::shared_ptr<const ExprNode>(std::move(n)));
}

E with_arg(const E& e, std::size_t i, const E& a) {
  auto n = std::make_shared<ExprNode>(e.node());
  n->args[i] = a;
  return E(std::shared_ptr<const ExprNode>(std::move(n)));
}

E without_arg(const E& e, std::size_t i) {
  auto n = std::make_shared<ExprNode>(e.node());
  n->args.erase(n->args.begin() + static_cast<std::ptrdiff_t>(i));
  return E(std::shared_ptr<const ExprNode>(std::move(n)));
}

using Out = std::vector<FormulaChange>;

void add(Out& out, const E& e, std::string_view kind) { out.push_back({e, e, kind}); }

// An arithmetic operator replaced by another, a factor or a term deleted, operands swapped, a
// function for its sibling, a clamp removed.
void operator_changes(const E& e, Out& out) {
  const ExprNode& n = e.node();
  const auto& a = n.args;
  switch (n.op) {
    case Op::kAdd:
      add(out, a[0] - a[1], "sign");
      add(out, a[0], "drop-term");
      add(out, a[1], "drop-term");
      add(out, a[0] * a[1], "operator");
      add(out, a[0] / a[1], "operator");
      break;
    case Op::kSub:
      add(out, a[0] + a[1], "sign");
      add(out, a[1] - a[0], "swap");
      add(out, a[0], "drop-term");
      add(out, -a[1], "drop-term");
      add(out, a[0] * a[1], "operator");
      add(out, a[0] / a[1], "operator");
      break;
    case Op::kNeg: add(out, a[0], "sign"); break;
    case Op::kMul:
      add(out, a[1], "drop-term");
      add(out, a[0], "drop-term");
      add(out, a[0] / a[1], "operator");
      add(out, a[0] + a[1], "operator");
      add(out, a[0] - a[1], "operator");
      break;
    case Op::kDiv:
      add(out, a[1] / a[0], "swap");
      add(out, a[0], is(a[1], Op::kNorm) ? "normalise" : "drop-term");
      add(out, E(1) / a[1], "drop-term");
      add(out, a[0] * a[1], "operator");
      add(out, a[0] + a[1], "operator");
      add(out, a[0] - a[1], "operator");
      break;
    case Op::kCross: add(out, cross(a[1], a[0]), "swap"); break;
    case Op::kSquare: add(out, a[0], "square"); break;
    case Op::kSqrt: add(out, a[0], "sqrt"); break;
    case Op::kAbs: add(out, a[0], "abs"); break;
    case Op::kMin:
    case Op::kMax:
      add(out, with_op(e, n.op == Op::kMin ? Op::kMax : Op::kMin), "other-root");
      // max(0, x) → x: a clamp to a constant left out.
      for (std::size_t i = 0; i < a.size() && a.size() > 1; ++i) {
        if (!is(a[i], Op::kNumber)) continue;
        add(out, a.size() == 2 ? a[1 - i] : without_arg(e, i), "clamp");
      }
      break;
    case Op::kArccosDegrees:
      add(out, e * (std::numbers::pi / 180), "degrees");
      // arcsin(x) = 90° − arccos(x): the angle from the surface instead of from the normal.
      add(out, E(90) - e, "function");
      break;
    default: break;
  }
}

// A constant c replaced by 0, 1, −c, 2c or c/2.
void constant_changes(double c, Out& out) {
  std::vector<double> seen{c};
  for (double x : {0.0, 1.0, -c, 2 * c, c / 2}) {
    if (std::find(seen.begin(), seen.end(), x) != seen.end()) continue;
    seen.push_back(x);
    add(out, E(x), "constant");
  }
}

// A negation, a factor 2 or ½, a square, a square root, an absolute value or a normalisation
// put in at the node. None where it gives the node's own value or another operator's change
// (−(−x), |√x|, √(x²)); none on a constant (its own changes hold them) nor at the root for
// the negation (the whole step negated is a change of the step).
void insertions(const E& e, Kind type, bool root, Out& out) {
  Op op = e.node().op;
  if (op == Op::kNumber || op == Op::kCompare) return;
  if (!root && op != Op::kNeg) add(out, -e, "sign");
  add(out, E(2) * e, "factor");
  add(out, e / E(2), "factor");
  if (type == Kind::kScalar) {
    if (op != Op::kSqrt) add(out, square(e), "square");
    if (op != Op::kSquare && op != Op::kSqrt) add(out, sqrt(e), "sqrt");
    if (op != Op::kAbs && op != Op::kNorm && op != Op::kSqrt && op != Op::kSquare)
      add(out, abs(e), "abs");
  }
  bool normalised = op == Op::kDiv && is(e.node().args[1], Op::kNorm);
  if (type == Kind::kVector && op != Op::kSymbol && !normalised) add(out, e / norm(e), "normalise");
}

// Another quantity of the same type for the symbol `e`, and a vector with one component
// dropped.
void operand_changes(const E& e, const ChangeScope& s, Out& out) {
  const ExprNode& n = e.node();
  auto it = s.values->find(n.name);
  if (it == s.values->end()) return;
  const Value& v = it->second;
  for (const auto& [name, value] : *s.values) {
    if (name == n.name || value.kind != v.kind || v.is_bool()) continue;
    add(out, s.symbols->at(name), v.is_vector() ? "vector-swap" : "operand");
  }
  if (!v.is_vector()) return;
  static const char* const kAxes[] = {"x", "y", "z"};
  std::string shown = to_text(e);
  for (int k = 0; k < 3; ++k) {
    if (v.vector[k] == 0) continue;
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

std::size_t count_operands(const E& e, const ChangeScope& s) {
  auto it = s.values->find(e.node().name);
  if (it == s.values->end() || it->second.is_bool()) return 0;
  std::size_t k = 0;
  for (const auto& [name, value] : *s.values)
    k += name != it->first && value.kind == it->second.kind;
  if (it->second.is_vector())
    for (int i = 0; i < 3; ++i) k += it->second.vector[i] != 0;
  return k;
}

// The changes at the node `e` itself.
void local_changes(const E& e, const ChangeScope& s, ChangeTier tier, bool root, Out& out) {
  const ExprNode& n = e.node();
  bool ops = tier != ChangeTier::kOperands, operands = tier != ChangeTier::kOperators;
  if (ops) {
    Kind type = type_of(e, *s.values);
    if (n.op == Op::kSymbol && type == Kind::kVector) {
      constexpr double kUnit = 1e-9;  // a vector of length 1 needs no normalising
      if (std::abs(length(s.values->at(n.name).vector) - 1) > kUnit)
        add(out, e / norm(e), "normalise");
    }
    if (n.op == Op::kNumber) constant_changes(n.number, out);
    operator_changes(e, out);
    insertions(e, type, root, out);
  }
  if (operands && n.op == Op::kSymbol) operand_changes(e, s, out);
}

bool each(const E& e, const ChangeScope& s, ChangeTier tier, bool root, std::size_t& left,
          const std::function<void(FormulaChange&&)>& sink) {
  if (e.empty()) return true;
  Out local;
  local_changes(e, s, tier, root, local);
  for (auto& c : local) {
    if (left == 0) return false;
    --left;
    sink(std::move(c));
  }
  if (is(e, Op::kSymbol)) return true;  // its args are how it is shown
  for (std::size_t i = 0; i < e.node().args.size(); ++i) {
    bool more = each(e.node().args[i], s, tier, false, left, [&](FormulaChange&& x) {
      sink({with_arg(e, i, x.eval), with_arg(e, i, x.shown), x.kind});
    });
    if (!more) return false;
  }
  return true;
}

std::size_t count(const E& e, const ChangeScope& s, ChangeTier tier, bool root) {
  if (e.empty()) return 0;
  std::size_t k = 0;
  if (tier != ChangeTier::kOperators && is(e, Op::kSymbol)) k += count_operands(e, s);
  if (tier != ChangeTier::kOperands) {
    Out local;
    local_changes(e, s, ChangeTier::kOperators, root, local);
    k += local.size();
  }
  if (is(e, Op::kSymbol)) return k;
  for (const E& a : e.node().args) k += count(a, s, tier, false);
  return k;
}

// How often each quantity is named in the formula (not in how a symbol is shown).
void symbol_uses(const E& e, std::map<std::string, int, std::less<>>& uses) {
  if (e.empty()) return;
  if (is(e, Op::kSymbol)) {
    ++uses[e.node().name];
    return;
  }
  for (const E& a : e.node().args) symbol_uses(a, uses);
}

// The formula with the quantities named as keys of `to` replaced by their values.
E substitute(const E& e, const std::map<std::string, E, std::less<>>& to) {
  if (e.empty()) return e;
  if (is(e, Op::kSymbol)) {
    auto it = to.find(e.node().name);
    return it == to.end() ? e : it->second;
  }
  E out = e;
  for (std::size_t i = 0; i < e.node().args.size(); ++i) {
    E a = substitute(e.node().args[i], to);
    if (&a.node() != &e.node().args[i].node()) out = with_arg(out, i, a);
  }
  return out;
}

// The pairs (a, b) a step's exchanges use: both named in the formula, or a named twice or more
// and b any other quantity of its type in scope. `sink` is called with each.
template <typename Sink>
void exchange_pairs(const E& e, const ChangeScope& s, Sink sink) {
  std::map<std::string, int, std::less<>> uses;
  symbol_uses(e, uses);
  for (const auto& [a, count] : uses) {
    auto va = s.values->find(a);
    if (va == s.values->end() || va->second.is_bool()) continue;
    for (const auto& [b, vb] : *s.values) {
      if (b == a || vb.kind != va->second.kind) continue;
      bool both = uses.count(b) > 0;
      if ((both && a < b) || (!both && count >= 2)) sink(a, b);
    }
  }
}

}  // namespace change_operators_internal

bool each_change(const E& e, const ChangeScope& scope, ChangeTier tier, std::size_t& left,
                 const std::function<void(FormulaChange&&)>& sink) {
  return change_operators_internal::each(e, scope, tier, true, left, sink);
}

std::size_t count_changes(const E& e, const ChangeScope& scope, ChangeTier tier) {
  return change_operators_internal::count(e, scope, tier, true);
}

bool each_step_change(const E& e, const ChangeScope& scope, ChangeTier tier, std::size_t& left,
                      const std::function<void(FormulaChange&&)>& sink) {
  using namespace change_operators_internal;  // NOLINT: this file's own functions
  if (tier != ChangeTier::kOperands) {
    if (left == 0) return false;
    --left;
    sink({-e, -e, "sign"});
  }
  if (tier == ChangeTier::kOperators) return true;
  bool more = true;
  exchange_pairs(e, scope, [&](const std::string& a, const std::string& b) {
    if (left == 0) {
      more = false;
      return;
    }
    --left;
    std::map<std::string, E, std::less<>> to{{a, scope.symbols->at(b)}, {b, scope.symbols->at(a)}};
    E changed = substitute(e, to);
    sink({changed, changed, "exchange"});
  });
  return more;
}

std::size_t count_step_changes(const E& e, const ChangeScope& scope, ChangeTier tier) {
  std::size_t k = tier != ChangeTier::kOperands ? 1 : 0;
  if (tier == ChangeTier::kOperators) return k;
  change_operators_internal::exchange_pairs(e, scope,
                                            [&](const std::string&, const std::string&) { ++k; });
  return k;
}

}  // namespace raygrade
