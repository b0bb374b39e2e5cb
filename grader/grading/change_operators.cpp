// The operators of the mistake search, applied to every node of a step's formula.
#include "grading/change_operators.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace raygrade {

const std::vector<std::string_view>& change_kinds() {
  // The changes an earlier search made (and its tests name) first, in its order; then the
  // insertions (a step's complement 1 − x among them), the replacements of a quantity, and the
  // exchanges (of two quantities, then of whole families).
  static const std::vector<std::string_view> k = {
      "sign",      "drop-term",  "swap",    "square",         "sqrt",        "abs",
      "normalise", "other-root", "degrees", "function",       "linear",      "clamp",
      "operator",  "constant",   "factor",  "complement",     "vector-swap", "operand",
      "exchange",  "component",  "rotate",  "family-exchange"};
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

void add(Out& out, const E& e, std::string_view kind) { out.push_back({e, e, kind, {}, {}}); }

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
      // min(a, b, …) → a: the comparison left out, the first kept (the first object listed
      // for the nearest).
      if (a.size() > 1 &&
          std::none_of(a.begin(), a.end(), [](const E& x) { return is(x, Op::kNumber); }))
        add(out, a[0], "clamp");
      break;
    case Op::kArccosDegrees:
      add(out, e * (std::numbers::pi / 180), "degrees");
      // arcsin(x) = 90° − arccos(x): the angle from the surface instead of from the normal.
      add(out, E(90) - e, "function");
      break;
    case Op::kArcsinDegrees:
      add(out, e * (std::numbers::pi / 180), "degrees");
      add(out, with_op(e, Op::kArccosDegrees), "function");
      break;
    case Op::kCos: add(out, with_op(e, Op::kSin), "function"); break;
    case Op::kSin: add(out, with_op(e, Op::kCos), "function"); break;
    case Op::kRadians: add(out, a[0], "degrees"); break;
    default: break;
  }
  // An angle in degrees taken to radians, x·π/180: the conversion left out (degrees read as
  // radians).
  if (n.op == Op::kDiv && is(a[1], Op::kNumber) && a[1].node().number == 180 &&
      is(a[0], Op::kMul)) {
    const auto& m = a[0].node().args;
    for (std::size_t i = 0; i < 2; ++i)
      if (is(m[i], Op::kNumber) && m[i].node().base == "pi") add(out, m[1 - i], "degrees");
  }
  // A function taken as linear: f(a·b) → a·f(b) (θt = η·θi for arcsin(η·sin θi), √(ab) as a√b).
  bool function = n.op == Op::kSin || n.op == Op::kCos || n.op == Op::kTan ||
                  n.op == Op::kArcsinDegrees || n.op == Op::kArccosDegrees || n.op == Op::kSqrt;
  if (function && is(a[0], Op::kMul)) {
    const auto& m = a[0].node().args;
    add(out, m[0] * with_arg(e, 0, m[1]), "linear");
    add(out, with_arg(e, 0, m[0]) * m[1], "linear");
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
    out.push_back({tuple(parts[0], parts[1], parts[2]),
                   tuple(names[0], names[1], names[2]),
                   "component",
                   {},
                   {}});
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
    c.from = e;
    c.to = c.eval;
    sink(std::move(c));
  }
  if (is(e, Op::kSymbol)) return true;  // its args are how it is shown
  for (std::size_t i = 0; i < e.node().args.size(); ++i) {
    bool more = each(e.node().args[i], s, tier, false, left, [&](FormulaChange&& x) {
      sink({with_arg(e, i, x.eval), with_arg(e, i, x.shown), x.kind, x.from, x.to});
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

// Where a quantity's index begins: at its trailing digits (S_1, v12), or at a triangle's vertex
// letter a, b or c after "_" (w_a, N_b) when `letters`; at the name's end when it has none.
std::size_t index_at(std::string_view name, bool letters = true) {
  std::size_t end = name.size();
  while (end > 0 && name[end - 1] >= '0' && name[end - 1] <= '9') --end;
  bool letter = end == name.size() && end >= 3 && name[end - 2] == '_' && name[end - 1] >= 'a' &&
                name[end - 1] <= 'c';
  return letters && letter ? end - 1 : end;
}

// The family of a quantity: its name with a trailing index made alike (S_1, S_2 → S_#; w_a,
// w_b → w_@ with `letters`); the two polarizations' amplitudes and reflectances are indexed by
// s and p (r_s, r_p → r_#).
std::string family(std::string_view name, bool letters = true) {
  // not a part: the derivation's quantities, whatever the parts are
  if (name == "r_s" || name == "r_p" || name == "R_s" || name == "R_p")
    return std::string(name.substr(0, 2)) + "#";
  std::size_t at = index_at(name, letters);
  if (at == name.size()) return std::string(name);
  bool digits = name[at] >= '0' && name[at] <= '9';
  return std::string(name.substr(0, at)) + (digits ? "#" : "@");
}

std::size_t mix(std::size_t h, std::size_t v) {
  return h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
}

// A node's own part of its form: its operator, number, relation, or its quantity's family.
std::size_t node_hash(const ExprNode& n) {
  std::size_t h = mix(0, static_cast<std::size_t>(n.op));
  if (n.op == Op::kSymbol) return mix(h, std::hash<std::string>{}(family(n.name)));
  h = mix(h, std::hash<double>{}(n.number));
  for (int k = 0; k < 3; ++k) h = mix(h, std::hash<double>{}(n.vector[k]));
  return mix(h, std::hash<std::string>{}(n.relation));
}

// Whether `y` has the form of `x`; `names` maps each quantity of `x` to the one of `y` in its
// place (one for each).
bool same_form(const E& x, const E& y, std::map<std::string, E, std::less<>>& names) {
  const ExprNode &a = x.node(), &b = y.node();
  if (a.op != b.op) return false;
  if (a.op == Op::kSymbol) {
    if (family(a.name) != family(b.name)) return false;
    auto [it, fresh] = names.emplace(a.name, y);
    return fresh || it->second.node().name == b.name;
  }
  if (a.number != b.number || a.relation != b.relation || a.args.size() != b.args.size())
    return false;
  for (int k = 0; k < 3; ++k)
    if (a.vector[k] != b.vector[k]) return false;
  for (std::size_t i = 0; i < a.args.size(); ++i)
    if (!same_form(a.args[i], b.args[i], names)) return false;
  return true;
}

// The index a quantity's name ends in ("1" of S_1, "a" of w_a; "" for none).
std::string_view index_of(std::string_view name) { return name.substr(index_at(name)); }

// `to` with the quantities named in `names` replaced, and every other quantity whose index one
// of them had re-indexed as it was (c_1 → r_1 made for c_2 is r_2).
E reindexed(const E& to, const std::map<std::string, E, std::less<>>& names) {
  std::map<std::string, std::string, std::less<>> indices;
  for (const auto& [x, y] : names) {
    std::string_view a = index_of(x), b = index_of(y.node().name);
    if (!a.empty() && !b.empty() && a != b) indices.emplace(std::string(a), std::string(b));
  }
  std::function<E(const E&)> walk = [&](const E& e) -> E {
    if (e.empty()) return e;
    if (is(e, Op::kSymbol)) {
      const std::string& name = e.node().name;
      if (auto it = names.find(name); it != names.end()) return it->second;
      std::string_view index = index_of(name);
      auto re = indices.find(index);
      if (index.empty() || re == indices.end()) return e;
      return sym(name.substr(0, name.size() - index.size()) + re->second);
    }
    E out = e;
    for (std::size_t i = 0; i < e.node().args.size(); ++i) {
      E a = walk(e.node().args[i]);
      if (&a.node() != &e.node().args[i].node()) out = with_arg(out, i, a);
    }
    return out;
  };
  return walk(to);
}

// The form hash of `e`, each node's pushed to `all` when given; with `from`, the nodes of its
// form replaced in `out` (`changed` set).
std::size_t walk_forms(const E& e, std::vector<std::size_t>* all, const E* from, const E* to,
                       std::size_t target, E& out, bool& changed) {
  const ExprNode& n = e.node();
  std::size_t h = node_hash(n);
  out = e;
  if (n.op != Op::kSymbol) {
    for (std::size_t i = 0; i < n.args.size(); ++i) {
      E a;
      bool c = false;
      h = mix(h, walk_forms(n.args[i], all, from, to, target, a, c));
      if (c) {
        out = with_arg(out, i, a);
        changed = true;
      }
    }
  }
  if (all) all->push_back(h);
  if (from && h == target) {
    std::map<std::string, E, std::less<>> names;
    if (same_form(*from, e, names)) {
      out = reindexed(*to, names);
      changed = true;
    }
  }
  return h;
}

// A list of quantities, one for each of another list (what a renaming renames, and into what):
// shown as a tuple, never evaluated.
E quantity_list(const std::vector<std::string>& names, const ChangeScope& s) {
  auto n = std::make_shared<ExprNode>();
  n->op = Op::kTuple;
  for (const auto& name : names) n->args.push_back(s.symbols->at(name));
  return E(std::shared_ptr<const ExprNode>(std::move(n)));
}

// The families in scope of three quantities or more of one type (S_1, S_2, S_3; w_a, w_b, w_c),
// each as its members' names in the order of their indices.
std::vector<std::vector<std::string>> families(const ChangeScope& s) {
  std::map<std::pair<std::string, Kind>, std::vector<std::string>> by;
  for (const auto& [name, v] : *s.values)
    if (family(name) != name && !v.is_bool()) by[{family(name), v.kind}].push_back(name);
  std::vector<std::vector<std::string>> out;
  for (auto& [f, names] : by) {
    if (names.size() < 3) continue;
    std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
      std::string_view x = index_of(a), y = index_of(b);
      return x.size() != y.size() ? x.size() < y.size() : x < y;
    });
    out.push_back(std::move(names));
  }
  return out;
}

// A step's renamings, made throughout it: each family it names whole rotated by one either way
// (the weights of a, b, c given to b, c, a), and exchanged member by member with another family
// in scope of the same indices and type (u_a, u_b, u_c for v_a, v_b, v_c). `sink(kind, from, to)`.
template <typename Sink>
void renamings(const E& e, const ChangeScope& s, Sink sink) {
  std::map<std::string, int, std::less<>> uses;
  symbol_uses(e, uses);
  auto fams = families(s);
  auto named = [&](const std::vector<std::string>& m) {
    return std::all_of(m.begin(), m.end(), [&](const std::string& x) { return uses.count(x); });
  };
  auto indices = [](const std::vector<std::string>& m) {
    std::vector<std::string_view> out;
    out.reserve(m.size());
    for (const auto& x : m) out.push_back(index_of(x));
    return out;
  };
  auto kind = [&](const std::vector<std::string>& m) { return s.values->at(m[0]).kind; };
  for (std::size_t f = 0; f < fams.size(); ++f) {
    const auto& m = fams[f];
    if (!named(m)) continue;
    for (std::size_t shift : {std::size_t{1}, m.size() - 1}) {
      std::vector<std::string> to;
      for (std::size_t i = 0; i < m.size(); ++i) to.push_back(m[(i + shift) % m.size()]);
      sink("rotate", m, to);
    }
    for (std::size_t g = 0; g < fams.size(); ++g) {
      const auto& o = fams[g];
      if (g == f || kind(o) != kind(m) || indices(o) != indices(m) || (g < f && named(o))) continue;
      std::vector<std::string> from = m, to = o;
      from.insert(from.end(), o.begin(), o.end());
      to.insert(to.end(), m.begin(), m.end());
      sink("family-exchange", from, to);
    }
  }
}

// Whether a step's value is a number strictly between 0 and 1 (a texture coordinate, a weight, a
// reflectance, a cosine), whose complement 1 − x a student may take for it.
bool complementable(const E& e, const ChangeScope& s) {
  try {
    Value v = evaluate(e, *s.values);
    return v.is_scalar() && v.scalar > 0 && v.scalar < 1;
  } catch (const EvaluationFault&) {
    return false;
  }
}

}  // namespace change_operators_internal

bool renaming_kind(std::string_view kind) { return kind == "rotate" || kind == "family-exchange"; }
bool renames(const FormulaChange& c) { return renaming_kind(c.kind); }

std::optional<E> rename_everywhere(const E& formula, const E& from, const E& to) {
  using namespace change_operators_internal;  // NOLINT: this file's own functions
  if (formula.empty()) return std::nullopt;
  std::map<std::string, int, std::less<>> uses;
  symbol_uses(formula, uses);
  std::map<std::string, E, std::less<>> names;
  bool any = false;
  for (std::size_t i = 0; i < from.node().args.size(); ++i) {
    const std::string& name = from.node().args[i].node().name;
    names.emplace(name, to.node().args[i]);
    any = any || uses.count(name) > 0;
  }
  if (!any) return std::nullopt;
  return substitute(formula, names);
}

bool made_everywhere(const FormulaChange& c) {
  using namespace change_operators_internal;  // NOLINT: this file's own functions
  if (renames(c)) return false;               // made by rename_everywhere
  if (c.from.empty() || c.to.empty() || is(c.from, Op::kNumber)) return false;
  if (!is(c.from, Op::kSymbol)) return true;
  // A quantity of an indexed family (S_1, c_1), for its like in every step: not for another of
  // its own family (that is one quantity for another, not a slip made each time).
  // (A vertex-lettered quantity, w_a, is made everywhere only as part of a node's form.)
  const std::string& name = c.from.node().name;
  if (family(name, false) == name) return false;
  return !is(c.to, Op::kSymbol) || family(c.to.node().name, false) != family(name, false);
}

std::size_t form_hash(const E& e) {
  E out;
  bool changed = false;
  return change_operators_internal::walk_forms(e, nullptr, nullptr, nullptr, 0, out, changed);
}

void form_hashes(const E& e, std::vector<std::size_t>& out) {
  if (e.empty()) return;
  E ignored;
  bool changed = false;
  change_operators_internal::walk_forms(e, &out, nullptr, nullptr, 0, ignored, changed);
}

std::optional<E> change_everywhere(const E& formula, const E& from, const E& to, std::size_t hash) {
  if (formula.empty()) return std::nullopt;
  E out;
  bool changed = false;
  change_operators_internal::walk_forms(formula, nullptr, &from, &to, hash, out, changed);
  if (!changed) return std::nullopt;
  return out;
}

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
    sink({-e, -e, "sign", {}, {}});
    if (complementable(e, scope)) {
      if (left == 0) return false;
      --left;
      sink({1 - e, 1 - e, "complement", {}, {}});
    }
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
    sink({changed, changed, "exchange", {}, {}});
  });
  renamings(e, scope, [&](std::string_view kind, const auto& from, const auto& to) {
    if (!more || left == 0) {
      more = false;
      return;
    }
    --left;
    E f = quantity_list(from, scope), t = quantity_list(to, scope);
    E changed = *rename_everywhere(e, f, t);
    sink({changed, changed, kind, f, t});
  });
  return more;
}

std::size_t count_step_changes(const E& e, const ChangeScope& scope, ChangeTier tier) {
  using namespace change_operators_internal;  // NOLINT: this file's own functions
  std::size_t k = tier != ChangeTier::kOperands ? (complementable(e, scope) ? 2 : 1) : 0;
  if (tier == ChangeTier::kOperators) return k;
  exchange_pairs(e, scope, [&](const std::string&, const std::string&) { ++k; });
  renamings(e, scope, [&](std::string_view, const auto&, const auto&) { ++k; });
  return k;
}

}  // namespace raygrade
