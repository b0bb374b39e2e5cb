// Single changes to a variant's derivation, matched against wrong answers.
#include "grading/discover.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <string_view>
#include <tuple>

#include "core/error.h"
#include "derivation/formula.h"
#include "grading/change_operators.h"
#include "grading/parts.h"
#include "kinds/derive.h"
#include "kinds/part_names.h"

namespace raygrade {

std::string StepChange::text() const {
  std::string_view tail = !everywhere           ? ""
                          : renaming_kind(kind) ? ", and so in every step that uses them"
                                                : ", and alike in every step of that form";
  return fmt::format("{} = {} → {} = {}{}", step, before, step, after, tail);
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
    if (j.is_boolean()) l.number = j.get<bool>() ? 1 : 0;  // a verdict a step may compute
    out.push_back(std::move(l));
  }
}

// A student's number as typed: a JSON number, or a formula of numbers ("9 - sqrt(3)"); with
// `symbols`, a formula in them too ("px^2 + py^2 - r^2"), at `values`.
std::optional<StudentNumber> student_number(const nlohmann::json& j, const SymbolTable* symbols,
                                            const std::vector<double>& values) {
  if (j.is_number()) {
    double v = j.get<double>();
    // The shortest text that reads back as v is what the student typed (as the grader reads it).
    std::string text = j.is_number_float() ? fmt::format("{}", v) : j.dump();
    return StudentNumber{v, typed_digits(text), text};
  }
  if (!j.is_string()) return std::nullopt;
  FormulaParse p = parse_formula(j.get<std::string>(), symbols);
  if (!p.ok || (p.formula.uses_symbols && !symbols)) return std::nullopt;
  double v = p.formula.evaluate(values);
  if (!std::isfinite(v)) return std::nullopt;
  return StudentNumber{v, p.digits, j.get<std::string>()};
}

// One value of an answer: a number, or the three numbers of a vector, compared as the grader
// compares it (grading/parts.h, value_rule).
struct Group {
  std::vector<std::size_t> leaves;  // one, or a vector's three
  ValueRule rule;
  int hit = -1;  // the hit it belongs to, in a set of hits (any order)
};

// The object keys on the way to a value ("hits", "point"): array indices left out.
std::vector<std::string> object_keys(const nlohmann::json::json_pointer& path) {
  std::vector<std::string> keys;
  std::string s = path.to_string();
  std::size_t at = 1;
  while (at <= s.size() && !s.empty()) {
    std::size_t end = s.find('/', at);
    std::string token = s.substr(at, end == std::string::npos ? std::string::npos : end - at);
    bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    if (!index) keys.push_back(token);
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return keys;
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
  if (l.value.is_boolean()) return v.is_bool() ? (v.truth ? 1.0 : 0.0) : NAN;
  return v.is_scalar() ? v.scalar : NAN;
}

// A value of the k-th item of a list (the lights' /lights/2/diffuse) is its item's step
// named for it (diffuse_3), when that step has its value: several items' steps may share a
// value (0 for a light that does not reach P) that only the name tells apart. A verdict
// (/lights/2/reaches) is only ever tied so. Returns whether the leaf was tied.
bool map_to_item_step(Leaf& l, const std::vector<SolutionPart>& parts) {
  if (std::isnan(l.number) || l.component >= 0 || l.path.parent_pointer().empty()) return false;
  std::string item = l.path.parent_pointer().back();
  if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos) return false;
  std::string name = fmt::format("{}_{}", l.field, std::stoul(item) + 1);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    std::map<std::string, int> seen;
    for (const auto& s : parts[p].derivation.steps) {
      int occ = seen[s.name]++;
      if (s.name != name || s.given) continue;
      bool fits = l.value.is_boolean()
                      ? s.value.is_bool() && (s.value.truth ? 1 : 0) == l.number
                      : s.value.is_scalar() && same_number(s.value.scalar, l.number);
      if (!fits) continue;
      l.step = s.name;
      l.part = p;
      l.occurrence = occ;
    }
  }
  return !l.step.empty();
}

// Ties each numeric leaf to the last step whose value is that number (a component: whose
// vector is the leaf's whole vector).
// With `by_name`, each leaf is tied to the last step named as its field instead (a formula's
// value may be another step's too).
void map_leaves(std::vector<Leaf>& leaves, const nlohmann::json& answer,
                const std::vector<SolutionPart>& parts, bool by_name) {
  for (auto& l : leaves) {
    if (map_to_item_step(l, parts)) continue;
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

// The value of an answer at `at`, or null; a unit direction stands for the direction, as the
// grader reads it.
const nlohmann::json* answer_at(const nlohmann::json& answer, nlohmann::json::json_pointer at) {
  if (!answer.contains(at) && object_keys(at).back() == part_names::kDirection) {
    std::string text = at.to_string();
    text.replace(text.rfind(part_names::kDirection),
                 std::string_view(part_names::kDirection).size(), part_names::kUnitDirection);
    at = nlohmann::json::json_pointer(text);
  }
  return answer.contains(at) ? &answer.at(at) : nullptr;
}

// The nodes of a formula: what evaluating it costs.
std::size_t formula_size(const E& e) {
  if (e.empty()) return 0;
  std::size_t k = 1;
  if (e.node().op != Op::kSymbol)
    for (const E& a : e.node().args) k += formula_size(a);
  return k;
}

// The quantities a formula names (not in how a symbol is shown).
void names_in(const E& e, std::set<std::string>& out) {
  if (e.empty()) return;
  if (e.node().op == Op::kSymbol) {
    out.insert(e.node().name);
    return;
  }
  for (const E& a : e.node().args) names_in(a, out);
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

// A step to change, with the scope it is worked in: its changes' counts by tier, and how many of
// each the budget pays for. `once`: the only step of its name and formula in the derivation,
// so its changed value alone decides the changed derivation (changes giving one value are
// worked once).
struct StepPlan {
  const Step* step = nullptr;
  bool once = false;
  std::size_t ops = 0, operands = 0, take_ops = 0, take_operands = 0;
};

// How many of each step's changes the budget pays for: all of them when they fit; else each
// step an equal share of its operators' changes (the whole step negated among them) first, then
// what is left in equal shares of its operands'. Returns whether the budget cut some.
bool share(std::vector<StepPlan>& plans, std::size_t budget) {
  std::size_t total = 0;
  std::vector<std::size_t> ops, operands;
  for (auto& p : plans) {
    p.take_ops = p.ops;
    p.take_operands = p.operands;
    total += p.ops + p.operands;
    ops.push_back(p.ops);
    operands.push_back(p.operands);
  }
  if (total <= budget) return false;
  std::size_t level = water_level(ops, budget), used = 0;
  for (auto& p : plans) used += p.take_ops = std::min(p.ops, level);
  bool all_ops = used == std::accumulate(ops.begin(), ops.end(), std::size_t{0});
  std::size_t level1 = all_ops ? water_level(operands, budget - used) : 0;
  for (auto& p : plans) p.take_operands = std::min(p.operands, level1);
  return true;
}

// A value as a key of the changes already worked: equal values give equal derivations.
std::array<double, 3> value_key(const Value& v) {
  auto canon = [](double x) { return std::isnan(x) ? NAN : x == 0 ? 0.0 : x; };
  if (v.is_vector()) return {canon(v.vector.x), canon(v.vector.y), canon(v.vector.z)};
  return {canon(v.scalar), v.is_bool() ? double(v.truth) : 0.0, v.is_scalar() ? 1.0 : 2.0};
}

bool same_value(const Value& a, const Value& b) {
  return a.kind == b.kind && value_key(a) == value_key(b);
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

  // An answer that names the object hit first (first-hit): its name's leaf, and the objects'
  // names (the headings of the derivation's parts). A change that makes another object's hit
  // the first names that object, and the hit's numbers are that object's (follow_object).
  std::ptrdiff_t name_leaf = -1;
  std::vector<std::string> objects;
  // For the method searched: the reference object's part, the leaf that picks the object (the
  // first hit's t) and the step of each object's part whose value it takes.
  struct Follow {
    bool active = false;
    std::size_t part = 0;
    std::size_t selector = 0;
    std::string step;
    int occurrence = 0;
  } follow;
  // The verdicts the student gave that a step computes (`given` 0 or 1); `wrong` set when one
  // is not the reference's.
  std::vector<std::size_t> verdicts_given(const std::vector<double>& given, bool& wrong) const;
  // Whether the object that `numbers` names is `named` (none named: yes), by the grader's rule.
  bool names_fit(const std::optional<std::string>& named,
                 const std::vector<double>& numbers) const {
    if (!named) return true;
    auto k = static_cast<std::size_t>(numbers[static_cast<std::size_t>(name_leaf)]);
    return k < objects.size() && same_object_name(*named, objects[k]);
  }
  void find_follow(const std::vector<SolutionPart>& right,
                   const std::vector<discover_internal::Leaf>& mapped);
  void follow_object(const discover_internal::StepValues& values,
                     const std::vector<discover_internal::Leaf>& mapped,
                     std::vector<double>& numbers) const;

  std::vector<discover_internal::Group> groups;  // the answer's values
  std::vector<std::vector<std::size_t>> hits;    // per hit of a set of hits: its groups
  std::size_t hit_t = 0;                         // which of a hit's groups is its t

  void make_groups(std::string_view kind);
  // For each group, the group of `numbers` it is compared with: itself, but in a set of hits
  // the hit of the same rank by t (hits are right in any order); `own` gives the order of the
  // hits the group belongs to.
  std::vector<std::size_t> counterparts(const std::vector<double>& own,
                                        const std::vector<double>& numbers) const;
  // The group `g` of the student's values against group `c` of `numbers`, as the grader
  // compares them.
  PartVerdict compare(std::size_t g, const std::vector<StudentNumber>& student, std::size_t c,
                      const std::vector<double>& numbers) const;
  // The chance that random numbers in place of the student's fit group `c` of `numbers`.
  double chance(std::size_t c, const std::vector<double>& numbers) const;

  // `mapped`: the leaves as the change's method computes them. Returns the prediction the
  // change joined, or −1 when it moved no number or left some number undefined.
  std::ptrdiff_t add(const StepChange& change, const std::vector<discover_internal::Leaf>& mapped,
                     std::vector<double> numbers) {
    using discover_internal::same_number;
    bool moved = false;
    for (std::size_t i = 0; i < numbers.size(); ++i) {
      if (!mapped[i].step.empty() && !std::isfinite(numbers[i])) return -1;
      if (std::isfinite(numbers[i]) && !same_number(numbers[i], reference[i])) moved = true;
    }
    if (!moved) return -1;
    ++changes;
    for (std::size_t i = 0; i < numbers.size(); ++i)
      if (std::isnan(numbers[i])) numbers[i] = reference[i];
    for (std::size_t k = 0; k < predictions.size(); ++k) {
      auto& p = predictions[k];
      bool same = true;
      for (std::size_t i = 0; i < numbers.size() && same; ++i)
        same = (std::isnan(numbers[i]) && std::isnan(p.numbers[i])) ||
               same_number(numbers[i], p.numbers[i]);
      if (same) {
        p.changes.push_back(change);
        return static_cast<std::ptrdiff_t>(k);
      }
    }
    predictions.push_back(discover_internal::Prediction{std::move(numbers), {change}});
    return static_cast<std::ptrdiff_t>(predictions.size() - 1);
  }

  void search_method(const Task& task, const std::string& method,
                     const std::vector<SolutionPart>& right,
                     const std::vector<discover_internal::Leaf>& mapped, std::size_t methods);
  void search_step(const Task& task, const std::string& method,
                   const discover_internal::StepPlan& plan, const ChangeScope& scope,
                   const std::vector<discover_internal::Leaf>& mapped, std::size_t cost);
  // Works one changed derivation: `override` gives each step's changed formula. Returns the
  // prediction the change joined (−1: none).
  std::ptrdiff_t work_change(const Task& task, const std::string& method, const StepChange& change,
                             const Overrides& override,
                             const std::vector<discover_internal::Leaf>& mapped, std::size_t cost);

  // The changes whose changed node's form recurs in another step of the derivation, made again
  // in every step of that form once the method's single changes are worked.
  struct Everywhere {
    StepChange change;
    E from, to;
    std::size_t hash = 0;
    bool rename = false;  // quantities renamed in every step naming them (rename_everywhere)
  };
  std::vector<Everywhere> everywhere;
  std::set<std::pair<std::size_t, std::size_t>> everywhere_seen;
  std::set<std::string> renamed_seen;
  // How many of the method's steps name each quantity.
  std::map<std::string, int, std::less<>> naming;
  // The form hashes of the method's steps: the first step (name and formula) with each, and
  // whether the form is met more than once (in that step or another).
  std::map<std::size_t, std::pair<std::string, bool>> forms;
};

// Works the changes of one step that the budget pays for. A change is evaluated in the step's
// scope first: one that leaves the step's value as it was moves nothing, and one that gives a
// value another change gave joins that change's numbers, without working the derivation again.
void ChangeSearch::Impl::search_step(const Task& task, const std::string& method,
                                     const discover_internal::StepPlan& plan,
                                     const ChangeScope& scope,
                                     const std::vector<discover_internal::Leaf>& mapped,
                                     std::size_t cost) {
  using namespace discover_internal;  // NOLINT: this file's own functions
  const Step* s = plan.step;
  std::string before = to_text(s->formula);
  std::map<std::array<double, 3>, std::ptrdiff_t> worked;  // a changed value → its prediction
  // A change of a node whose form is met more than once is made everywhere later.
  auto remember_everywhere = [&](const FormulaChange& alt, const StepChange& change) {
    if (renames(alt)) {
      // Once per renaming, when another step names one of its quantities.
      std::set<std::string> own;
      names_in(s->formula, own);
      std::string key;
      bool elsewhere = false;
      for (const E* list : {&alt.from, &alt.to}) {
        for (const E& q : list->node().args) {
          key += q.node().name + ",";
          auto it = naming.find(q.node().name);
          elsewhere =
              elsewhere || (it != naming.end() && it->second > (own.count(it->first) ? 1 : 0));
        }
      }
      if (!elsewhere || !renamed_seen.insert(key).second) return;
      StepChange c = change;
      c.everywhere = true;
      everywhere.push_back({std::move(c), alt.from, alt.to, 0, true});
      return;
    }
    if (!made_everywhere(alt)) return;
    std::size_t h = form_hash(alt.from);
    auto it = forms.find(h);
    if (it == forms.end() || !it->second.second) return;
    // Once per change of a form: the same change of each light's L is one change everywhere.
    if (!everywhere_seen.insert({h, form_hash(alt.to)}).second) return;
    StepChange c = change;
    c.everywhere = true;
    everywhere.push_back({std::move(c), alt.from, alt.to, h});
  };
  auto try_change = [&](FormulaChange&& alt) {
    auto change = [&] {
      return StepChange{method, s->name, std::string(alt.kind), before, to_text(alt.shown)};
    };
    std::array<double, 3> key{};
    remember_everywhere(alt, change());
    if (plan.once) {
      work += formula_size(alt.eval);
      Value v;
      try {
        v = evaluate(alt.eval, *scope.values);
      } catch (const EvaluationFault&) {
        return;  // the change makes no sense here (a vector where a number was)
      }
      if (same_value(v, s->value)) return;  // no number moves
      if ((v.is_scalar() && !std::isfinite(v.scalar)) ||
          (v.is_vector() && !std::isfinite(length(v.vector))))
        return;  // no number defined
      key = value_key(v);
      if (auto it = worked.find(key); it != worked.end()) {
        if (it->second >= 0) {
          predictions[static_cast<std::size_t>(it->second)].changes.push_back(change());
          ++changes;
        }
        return;
      }
    }
    Overrides o;
    o.formula = [&](std::string_view step, const E& f) -> std::optional<E> {
      if (step != s->name || to_text(f) != before) return std::nullopt;
      return alt.eval;
    };
    std::ptrdiff_t joined = work_change(task, method, change(), o, mapped, cost);
    if (plan.once) worked[key] = joined;
  };
  if (plan.take_ops == plan.ops && plan.take_operands == plan.operands) {
    std::size_t left = plan.ops + plan.operands;
    each_change(s->formula, scope, ChangeTier::kAll, left, try_change);
    each_step_change(s->formula, scope, ChangeTier::kAll, left, try_change);
    return;
  }
  // The whole step negated first.
  std::size_t left = plan.take_ops;
  each_step_change(s->formula, scope, ChangeTier::kOperators, left, try_change);
  each_change(s->formula, scope, ChangeTier::kOperators, left, try_change);
  left = plan.take_operands;
  each_step_change(s->formula, scope, ChangeTier::kOperands, left, try_change);
  each_change(s->formula, scope, ChangeTier::kOperands, left, try_change);
}

std::ptrdiff_t ChangeSearch::Impl::work_change(const Task& task, const std::string& method,
                                               const StepChange& change, const Overrides& override,
                                               const std::vector<discover_internal::Leaf>& mapped,
                                               std::size_t cost) {
  using namespace discover_internal;  // NOLINT: this file's own functions
  ++derivations;
  work += cost;
  try {
    StepValues values = step_values(task.derive(method, &override));
    std::vector<double> numbers;
    numbers.reserve(mapped.size());
    for (const auto& l : mapped) numbers.push_back(l.step.empty() ? NAN : leaf_value(values, l));
    follow_object(values, mapped, numbers);
    return add(change, mapped, std::move(numbers));
  } catch (const Error&) {
    // the change leaves the method's way (no root where one was)
  } catch (const EvaluationFault&) {
    // the change makes no sense here (a vector where a number was)
  }
  return -1;
}

// Every change of every step of one method's derivation that the budget pays for, each step in
// its scope: the givens and steps of its part before it.
void ChangeSearch::Impl::search_method(const Task& task, const std::string& method,
                                       const std::vector<SolutionPart>& right,
                                       const std::vector<discover_internal::Leaf>& mapped,
                                       std::size_t methods) {
  using namespace discover_internal;  // NOLINT: this file's own functions
  // The steps to change, once each; a step of one name and formula met twice is changed
  // everywhere at once, and worked whole for every change.
  std::map<std::pair<std::string, std::string>, int> uses;
  std::size_t cost = 0;     // what a changed derivation costs: its steps and formulas' nodes
  std::size_t largest = 0;  // the largest formula, which each change is evaluated on first
  for (const auto& part : right) {
    for (const auto& s : part.derivation.steps) {
      cost += 1 + formula_size(s.formula);
      largest = std::max(largest, formula_size(s.formula));
      if (!s.given && !s.formula.empty()) ++uses[{s.name, to_text(s.formula)}];
    }
  }
  // Each step's changes counted in its scope, then shared out by the budget.
  std::vector<StepPlan> plans;
  auto walk = [&](const std::function<void(const Step&, const ChangeScope&)>& visit) {
    std::set<std::pair<std::string, std::string>> seen;
    for (const auto& part : right) {
      Env env;
      std::map<std::string, E, std::less<>> shown;
      ChangeScope scope{&env, &shown};
      for (const auto& s : part.derivation.steps) {
        if (!s.given && !s.formula.empty() && seen.insert({s.name, to_text(s.formula)}).second)
          visit(s, scope);
        env[s.name] = s.value;
        shown[s.name] = s.symbol;
      }
    }
  };
  walk([&](const Step& s, const ChangeScope& scope) {
    StepPlan p;
    p.step = &s;
    p.once = uses[{s.name, to_text(s.formula)}] == 1;
    p.ops = count_changes(s.formula, scope, ChangeTier::kOperators) +
            count_step_changes(s.formula, scope, ChangeTier::kOperators);
    p.operands = count_changes(s.formula, scope, ChangeTier::kOperands) +
                 count_step_changes(s.formula, scope, ChangeTier::kOperands);
    plans.push_back(p);
  });
  // A formula of n terms has a few changes per node and, for each quantity in it, one per
  // quantity of its type in scope: n² for a polygon's Newell sum. Beyond the budget, each step
  // gets an equal share of its operators' changes first (every change of a short step), then
  // of its operands'.
  // A change costs its changed formula's evaluation (its nodes and the few it puts in) and,
  // when its value is new, a derivation.
  constexpr std::size_t kInserted = 4;
  std::size_t budget =
      std::max(kMinSearchedChanges, kSearchWork / methods / (cost + largest + kInserted));
  truncated = share(plans, budget) || truncated;
  // The form of every node of every step, for the changes made everywhere.
  forms.clear();
  everywhere.clear();
  everywhere_seen.clear();
  renamed_seen.clear();
  naming.clear();
  walk([&](const Step& s, const ChangeScope&) {
    std::set<std::string> names;
    names_in(s.formula, names);
    for (const auto& n : names) ++naming[n];
    std::vector<std::size_t> hashes;
    form_hashes(s.formula, hashes);
    std::string self = s.name + "\n" + to_text(s.formula);
    for (std::size_t h : hashes) {
      auto [it, fresh] = forms.emplace(h, std::pair{self, false});
      if (!fresh) it->second.second = true;  // met twice, in this step or another
    }
  });
  std::size_t start = work;
  std::size_t i = 0;
  walk([&](const Step&, const ChangeScope& scope) {
    search_step(task, method, plans[i++], scope, mapped, cost);
  });
  // Then each change again in every step of its node's form, while the budget lasts.
  for (const auto& e : everywhere) {
    if (work - start + cost > kSearchWork / methods) break;
    Overrides o;
    o.formula = [&](std::string_view, const E& f) {
      return e.rename ? rename_everywhere(f, e.from, e.to)
                      : change_everywhere(f, e.from, e.to, e.hash);
    };
    work_change(task, method, e.change, o, mapped, cost);
  }
}

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
  m.make_groups(problem.kind);
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
    m.find_follow(right, mapped);
    m.search_method(task, method, right, mapped, methods.size());
  }
  // A number some method computes can be explained; one that none computes cannot.
  for (std::size_t i = 0; i < m.leaves.size(); ++i) m.computed.push_back(computed[i]);
}

void ChangeSearch::Impl::find_follow(const std::vector<SolutionPart>& right,
                                     const std::vector<discover_internal::Leaf>& mapped) {
  using namespace discover_internal;  // NOLINT: this file's own functions
  follow = Follow{};
  if (name_leaf < 0) {
    // The leaf "object" whose value is the heading of a part: the object hit first.
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      if (leaves[i].field != part_names::kObject || !leaves[i].value.is_string()) continue;
      for (std::size_t p = 0; p < right.size(); ++p) {
        if (right[p].heading != leaves[i].value.get<std::string>()) continue;
        name_leaf = static_cast<std::ptrdiff_t>(i);
        reference[i] = static_cast<double>(p);
      }
    }
    if (name_leaf < 0) return;
    for (const auto& part : right) objects.push_back(part.heading);
  }
  if (right.size() != objects.size()) return;
  auto part = static_cast<std::size_t>(reference[static_cast<std::size_t>(name_leaf)]);
  // The selector: a leaf computed outside the object's part whose value a step of that part
  // has (the first hit's t, the object's t0).
  for (std::size_t i = 0; i < mapped.size() && !follow.active; ++i) {
    if (mapped[i].step.empty() || mapped[i].part == part || mapped[i].component >= 0) continue;
    std::map<std::string, int> seen;
    for (const auto& s : right[part].derivation.steps) {
      int occ = seen[s.name]++;
      if (s.given || !s.value.is_scalar() || !same_number(s.value.scalar, reference[i])) continue;
      follow = Follow{true, part, i, s.name, occ};
    }
  }
}

void ChangeSearch::Impl::follow_object(const discover_internal::StepValues& values,
                                       const std::vector<discover_internal::Leaf>& mapped,
                                       std::vector<double>& numbers) const {
  using namespace discover_internal;  // NOLINT: this file's own functions
  if (!follow.active) return;
  double t = numbers[follow.selector];
  auto name = static_cast<std::size_t>(name_leaf);
  numbers[name] = static_cast<double>(follow.part);
  if (same_number(t, reference[follow.selector])) return;
  for (std::size_t p = 0; p < objects.size(); ++p) {
    auto it = values.find({p, follow.step, follow.occurrence});
    if (it == values.end() || !it->second.is_scalar() || !same_number(it->second.scalar, t))
      continue;
    // That object is hit first: the hit's numbers are its own.
    numbers[name] = static_cast<double>(p);
    for (std::size_t i = 0; i < mapped.size(); ++i) {
      if (mapped[i].step.empty() || mapped[i].part != follow.part) continue;
      Leaf l = mapped[i];
      l.part = p;
      numbers[i] = leaf_value(values, l);
    }
    return;
  }
}

void ChangeSearch::Impl::make_groups(std::string_view kind) {
  using discover_internal::Group;
  std::map<int, std::vector<std::size_t>> by_hit;
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    const auto& l = leaves[i];
    if (!l.value.is_number() || l.component > 0) continue;  // a vector's from its first
    Group g;
    g.leaves = {i};
    if (l.component == 0) g.leaves = {i, i + 1, i + 2};
    g.rule = value_rule(kind, discover_internal::object_keys(l.path), l.component == 0);
    std::string at = l.path.to_string();
    if (at.rfind("/hits/", 0) == 0) g.hit = std::atoi(at.c_str() + 6);
    if (g.hit >= 0) by_hit[g.hit].push_back(groups.size());
    groups.push_back(std::move(g));
  }
  // A set of hits is put in order by t: every hit the same values, one of them its t.
  for (const auto& [h, gs] : by_hit) hits.push_back(gs);
  auto t_at = [&](const std::vector<std::size_t>& gs) {
    for (std::size_t q = 0; q < gs.size(); ++q)
      if (leaves[groups[gs[q]].leaves.front()].field == part_names::kT) return q;
    return gs.size();
  };
  if (!hits.empty()) hit_t = t_at(hits.front());
  for (const auto& gs : hits) {
    if (gs.size() != hits.front().size() || t_at(gs) != hit_t || hit_t == gs.size()) {
      hits.clear();
      break;
    }
  }
}

std::vector<std::size_t> ChangeSearch::Impl::counterparts(
    const std::vector<double>& own, const std::vector<double>& numbers) const {
  std::vector<std::size_t> out(groups.size());
  std::iota(out.begin(), out.end(), std::size_t{0});
  if (hits.size() < 2) return out;
  auto t_of = [&](const std::vector<double>& v, std::size_t h) {
    return v[groups[hits[h][hit_t]].leaves.front()];
  };
  for (std::size_t h = 0; h < hits.size(); ++h) {
    if (std::isnan(t_of(own, h)) || std::isnan(t_of(numbers, h))) return out;
  }
  auto order = [&](const std::vector<double>& v) {
    std::vector<std::size_t> o(hits.size());
    std::iota(o.begin(), o.end(), std::size_t{0});
    std::stable_sort(o.begin(), o.end(),
                     [&](std::size_t a, std::size_t b) { return t_of(v, a) < t_of(v, b); });
    return o;
  };
  std::vector<std::size_t> mine = order(own), theirs = order(numbers);
  for (std::size_t k = 0; k < hits.size(); ++k) {
    for (std::size_t q = 0; q < hits[mine[k]].size(); ++q)
      out[hits[mine[k]][q]] = hits[theirs[k]][q];
  }
  return out;
}

PartVerdict ChangeSearch::Impl::compare(std::size_t g, const std::vector<StudentNumber>& student,
                                        std::size_t c, const std::vector<double>& numbers) const {
  const auto& mine = groups[g].leaves;
  const auto& theirs = groups[c].leaves;
  const Tolerance& t = tolerance.for_field(groups[g].rule.tolerance_field);
  if (mine.size() == 1)
    return compare_part(groups[g].rule.compare, student[mine[0]], numbers[theirs[0]], t);
  StudentNumber s[3] = {student[mine[0]], student[mine[1]], student[mine[2]]};
  Vec3d r{numbers[theirs[0]], numbers[theirs[1]], numbers[theirs[2]]};
  return compare_part(groups[g].rule.compare, s, r, t);
}

double ChangeSearch::Impl::chance(std::size_t c, const std::vector<double>& numbers) const {
  const auto& g = groups[c];
  const Tolerance& t = tolerance.for_field(g.rule.tolerance_field);
  // Random numbers are drawn uniformly within max(1, |reference|) of each reference number: the
  // chance to fall in a window is the share of that range the window covers.
  auto share = [&](std::size_t k, double centre, double half) {
    double r = reference[g.leaves[k]], range = std::max(1.0, std::abs(r));
    double covered = std::min(centre + half, r + range) - std::max(centre - half, r - range);
    return std::clamp(covered / (2 * range), 0.0, 1.0);
  };
  if (g.leaves.size() == 1) {
    double x = numbers[g.leaves[0]];
    return share(0, x, allowed_error(x, x, t));
  }
  Vec3d v{numbers[g.leaves[0]], numbers[g.leaves[1]], numbers[g.leaves[2]]};
  Vec3d ref{reference[g.leaves[0]], reference[g.leaves[1]], reference[g.leaves[2]]};
  double scale = length(v);
  bool any = g.rule.compare == Comparison::kDirection;
  bool unit = any || g.rule.compare == Comparison::kUnitDirection;
  std::array<double, 3> shares{};
  for (int k = 0; k < 3; ++k) {
    auto i = static_cast<std::size_t>(k);
    if (!unit) {
      shares[i] = share(i, v[k], allowed_error(v[k], scale, t));
      continue;
    }
    // A direction is compared as a unit vector: in the student's numbers its window is the
    // unit window at the length a random answer has (the reference's; 1 for a unit vector).
    double at = any ? length(ref) : 1;
    double u = scale > 0 ? v[k] / scale : 0;
    shares[i] = share(i, u * at, allowed_error(u, 1, t) * at);
  }
  std::sort(shares.begin(), shares.end());
  // Any positive multiple: the length is free, so the narrowest window is not counted.
  if (any) return shares[1] * shares[2];
  return shares[0] * shares[1] * shares[2];
}

std::vector<std::size_t> ChangeSearch::Impl::verdicts_given(const std::vector<double>& given,
                                                            bool& wrong) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    if (!leaves[i].value.is_boolean() || std::isnan(given[i])) continue;
    out.push_back(i);
    wrong = wrong || given[i] != reference[i];
  }
  return out;
}

Discovery ChangeSearch::explain(const nlohmann::json& answer) const {
  using namespace discover_internal;  // NOLINT: this file's own functions
  const Impl& m = *impl_;
  Discovery d;
  std::optional<std::string> named;  // the object the student names, in a first-hit answer
  std::vector<StudentNumber> student(m.leaves.size());
  std::vector<double> given(m.leaves.size(), NAN);
  for (std::size_t i = 0; i < m.leaves.size(); ++i) {
    const Leaf& l = m.leaves[i];
    const nlohmann::json* found = answer_at(answer, l.path);
    if (!found) continue;
    const nlohmann::json& s = *found;
    if (static_cast<std::ptrdiff_t>(i) == m.name_leaf && s.is_string()) {
      named = s.get<std::string>();  // the object hit first: a change may move it
      continue;
    }
    if (l.value.is_boolean() && s.is_boolean() && m.computed[i]) {
      given[i] = s.get<bool>() ? 1 : 0;  // a verdict a step computes: a change may move it
      continue;
    }
    if (!l.value.is_number()) {
      if (s != l.value) return d;  // a word or a verdict no change of a number explains
      continue;
    }
    std::optional<StudentNumber> x =
        student_number(s, m.symbol_values.empty() ? nullptr : &m.symbols, m.symbol_values);
    if (!x) return d;
    student[i] = *x;
    given[i] = x->value;
  }
  // The values given whole, and whether one is wrong by the grader's comparison.
  std::vector<std::size_t> complete;
  for (std::size_t g = 0; g < m.groups.size(); ++g) {
    bool all = true;
    for (std::size_t i : m.groups[g].leaves) all = all && !std::isnan(given[i]);
    if (all) complete.push_back(g);
  }
  bool wrong = !m.names_fit(named, m.reference);
  std::vector<std::size_t> right_at = m.counterparts(given, m.reference);
  for (std::size_t g : complete) {
    // Right to the digits typed but not by the tolerance is not right: a change may explain it.
    if (m.compare(g, student, right_at[g], m.reference).verdict.match == Match::kRight) continue;
    for (std::size_t i : m.groups[right_at[g]].leaves)
      if (!m.computed[i]) return d;  // a number no step computes
    wrong = true;
  }
  std::vector<std::size_t> verdicts = m.verdicts_given(given, wrong);
  if (complete.empty() || !wrong) return d;
  // The changed answers that fit, told apart by the values the student gave alone (a direction
  // by its unit vector); and the chance that a random answer of those numbers fits some
  // changed answer.
  auto on_given = [&](const std::vector<double>& numbers, const std::vector<std::size_t>& at) {
    std::vector<double> out;
    for (std::size_t g : complete) {
      const Group& c = m.groups[at[g]];
      double scale = 1;
      if (c.leaves.size() == 3 && (c.rule.compare == Comparison::kDirection))
        scale = length(Vec3d{numbers[c.leaves[0]], numbers[c.leaves[1]], numbers[c.leaves[2]]});
      for (std::size_t i : c.leaves) out.push_back(numbers[i] / scale);
    }
    if (named) out.push_back(numbers[static_cast<std::size_t>(m.name_leaf)]);
    return out;
  };
  std::vector<const Prediction*> fits;
  std::size_t distinct = 0;
  std::vector<std::vector<double>> seen{on_given(m.reference, right_at)};
  for (const auto& p : m.predictions) {
    std::vector<std::size_t> at = m.counterparts(given, p.numbers);
    double chance = 1;
    bool fit = true;
    for (std::size_t g : complete) {
      chance *= m.chance(at[g], p.numbers);
      // Right, not right to the digits given: an integer typed is not every number within ½.
      fit = fit && m.compare(g, student, at[g], p.numbers).verdict.match == Match::kRight;
    }
    // Another object named: a random answer names it one time in as many as there are objects.
    if (named) {
      auto nl = static_cast<std::size_t>(m.name_leaf);
      if (p.numbers[nl] != m.reference[nl]) chance /= static_cast<double>(m.objects.size());
    }
    fit = fit && m.names_fit(named, p.numbers);
    // A verdict is right or not; random answers are not credited with one (the guard counts
    // the numbers' chance alone, which is the larger).
    for (std::size_t i : verdicts) fit = fit && p.numbers[i] == given[i];
    std::vector<double> mine = on_given(p.numbers, at);
    bool repeated = std::any_of(seen.begin(), seen.end(), [&](const std::vector<double>& q) {
      for (std::size_t k = 0; k < q.size(); ++k)
        if (!same_number(q[k], mine[k])) return false;
      return true;
    });
    if (repeated) {
      if (fit) fits.push_back(&p);
      continue;
    }
    seen.push_back(std::move(mine));
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
    // The simplest change first: of the operators' ranks, the lowest.
    std::stable_sort(d.changes.begin(), d.changes.end(),
                     [](const StepChange& a, const StepChange& b) {
                       return change_rank(a.kind) < change_rank(b.kind);
                     });
  }
  return d;
}

}  // namespace raygrade
