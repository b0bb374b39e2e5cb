// The derive kind: quantities of a derivation asked for as formulas.
#include "kinds/derive.h"

#include <set>

namespace raygrade {
namespace {

void collect_symbols(const E& e, std::vector<std::string>& out) {
  if (e.empty()) return;
  const ExprNode& n = e.node();
  if (n.op == Op::kSymbol) {
    if (std::find(out.begin(), out.end(), n.name) == out.end()) out.push_back(n.name);
    return;
  }
  for (const auto& a : n.args) collect_symbols(a, out);
}

// The display of a symbol as typed text: "p_x" for base p, subscript x.
std::string typed_display(const E& s) {
  const ExprNode& n = s.node();
  std::string d = n.base.empty() ? n.name : n.base;
  if (!n.sub.empty()) d += "_" + n.sub;
  if (!n.sup.empty()) d += "^" + n.sup;
  return d;
}

}  // namespace

std::unique_ptr<Task> DeriveTask::read(const Cursor& problem) {
  Ray ray = read_ray(problem.at("ray"));
  std::unique_ptr<Shape> object = read_shape(problem.at("object"));
  Derivation d = object->derive(ray, problem.string_or("method", ""));
  Cursor find = problem.at("find");
  auto items = find.items();
  if (items.empty()) find.fail("name at least one quantity to find", "invalid");
  std::vector<DerivedQuantity> quantities;
  std::vector<std::string> used;
  for (const auto& item : items) {
    std::string name = item.string();
    const Step* s = d.find(name);
    if (!s || s->given) {
      std::vector<std::string> names;
      for (const auto& st : d.steps) {
        if (!st.given) names.push_back(st.name);
      }
      item.fail(fmt::format("the derivation has no computed step '{}' (known: {})", name,
                            fmt::join(names, ", ")),
                "unknown-step");
    }
    if (!s->value.is_scalar()) {
      item.fail(fmt::format("'{}' is not a number; formula answers are scalar", name), "invalid");
    }
    std::vector<std::string> syms;
    collect_symbols(s->formula, syms);
    for (const auto& sy : syms) {
      const Step* g = d.find(sy);
      if (!g || !g->given || !g->value.is_scalar()) {
        item.fail(fmt::format("'{}' depends on '{}', which is not a scalar given of the "
                              "derivation: formula answers need scalar symbols",
                              name, sy),
                  "invalid");
      }
      if (std::find(used.begin(), used.end(), sy) == used.end()) used.push_back(sy);
    }
    quantities.push_back({name, s->formula, to_text(s->formula)});
  }
  std::vector<FormulaSymbol> symbols;
  for (const auto& st : d.steps) {
    if (!st.given || std::find(used.begin(), used.end(), st.name) == used.end()) continue;
    symbols.push_back({st.name, typed_display(st.symbol), st.note, st.value.scalar});
  }
  return std::make_unique<DeriveTask>(ray, std::move(object), std::move(quantities),
                                      std::move(symbols));
}

nlohmann::json DeriveTask::answer() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& q : quantities_) j[q.name] = q.display;
  return j;
}

std::vector<SolutionPart> DeriveTask::derive(std::string_view method,
                                             const Overrides* overrides) const {
  return {SolutionPart{"", object_->derive(ray_, method, overrides)}};
}

}  // namespace raygrade
