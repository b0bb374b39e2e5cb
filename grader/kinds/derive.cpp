// The derive kind: quantities of a derivation asked for as formulas.
#include "kinds/derive.h"

#include <set>

#include "kinds/form.h"
#include "kinds/intersect.h"
#include "kinds/sketch.h"

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
  std::unique_ptr<Shape> object = read_lone_object(problem.at("object"));
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

// The object with the parameters the answers name (its radius r, the centre (c_x, c_y)), and
// the problem's example ray written as the formulas write it: p + t v when they use the
// components p_x, v_x, otherwise O + t D. Its hits in the example are marked as a check.
Sketch DeriveTask::sketch() const {
  Sketch f;
  std::vector<std::string> names;
  bool components = false;
  for (const auto& s : symbols_) {
    names.push_back(s.name);
    for (const char* c : {"px", "py", "pz", "vx", "vy", "vz"}) components |= s.name == c;
  }
  object_->sketch(f, "");
  object_->sketch_symbols(f, ray_, names);
  Intersection x = object_->intersect(ray_);
  sketch_ray(f, ray_, {object_.get()}, x.hits, components ? "p" : "O",
             components ? "p + t v" : "O + t D");
  for (const auto& h : x.hits) sketch_hit(f, h, Ink::kHit);
  return f;
}

std::optional<SceneGivens> DeriveTask::scene_givens() const {
  SceneGivens g;
  g.objects.push_back({"", object_.get(), nullptr});
  g.ray = ray_;
  return g;
}

std::unique_ptr<Task> DeriveKind::read(const Cursor& problem) { return DeriveTask::read(problem); }

std::vector<PartSpec> DeriveKind::parts() {
  using C = Comparison;
  return {{"<quantity>", "each quantity the problem names in find", 1, C::kFormula}};
}

nlohmann::json DeriveKind::answer_form(const Problem& p) {
  const auto* task = dynamic_cast<const DeriveTask*>(p.task.get());
  nlohmann::json fields = nlohmann::json::array();
  if (!task) return form::fields(fields);
  nlohmann::json symbols = nlohmann::json::array();
  for (const auto& s : task->symbols()) {
    symbols.push_back(s.name);
    if (s.display != s.name) symbols.push_back(s.display);
  }
  for (const auto& q : task->quantities()) {
    nlohmann::json f = form::field<field_types::Formula>(q.name, q.name + " =");
    f["symbols"] = symbols;
    fields.push_back(f);
  }
  return form::fields(fields);
}

std::string_view DeriveKind::schema() {
  return R"json({
  "required": [
    "ray",
    "object",
    "find"
  ],
  "properties": {
    "ray": {
      "$ref": "#/$defs/ray"
    },
    "object": {
      "$ref": "#/$defs/object"
    },
    "find": {
      "type": "array",
      "items": {
        "type": "string",
        "minLength": 1
      },
      "minItems": 1,
      "description": "the names of the derivation's steps to answer as formulas (docs/steps.md)"
    }
  }
})json";
}

}  // namespace raygrade
