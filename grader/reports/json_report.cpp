// Steps as data, for tools and for the JSON worked solutions.
#include "reports/json_report.h"

#include "core/escape.h"

namespace raygrade {

nlohmann::json value_json(const Value& v) {
  switch (v.kind) {
    case Value::Kind::kScalar:
      return std::isfinite(v.scalar) ? nlohmann::json(v.scalar) : nlohmann::json(nullptr);
    case Value::Kind::kVector: return vec_json(v.vector);
    case Value::Kind::kBool: return v.truth;
    case Value::Kind::kNone: break;
  }
  return nullptr;
}

nlohmann::json derivation_json(const Derivation& d, const NumberFormat& numbers) {
  nlohmann::json steps = nlohmann::json::array();
  Env env;
  for (const auto& s : d.steps) {
    nlohmann::json j = {{"name", s.name},
                        {"symbol", to_latex(s.symbol)},
                        {"symbol_text", to_text(s.symbol)},
                        {"value", value_json(s.value)},
                        {"shown", format_value(s.value, numbers)}};
    if (s.given) {
      j["given"] = true;
    } else {
      RenderOptions subst{&env, numbers};
      j["formula"] = to_latex(s.formula);
      j["substituted"] = to_latex(s.formula, subst);
      j["formula_text"] = to_text(s.formula);
      j["substituted_text"] = to_text(s.formula, subst);
    }
    if (!s.note.empty()) j["note"] = s.note;
    if (s.value.is_scalar()) {
      if (auto x = exact_form(s.value.scalar)) j["exact"] = exact_text(*x);
    }
    steps.push_back(std::move(j));
    env[s.name] = s.value;
  }
  nlohmann::json conclusion = nlohmann::json::array();
  for (const auto& s : d.sentences) conclusion.push_back(sentence_text(s, numbers));
  return {{"method", d.method}, {"title", d.title}, {"steps", steps}, {"conclusion", conclusion}};
}

nlohmann::json parts_json(const std::vector<SolutionPart>& parts, const NumberFormat& numbers) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : parts) {
    nlohmann::json j = derivation_json(p.derivation, numbers);
    if (!p.heading.empty()) j["heading"] = p.heading;
    for (const auto& f : p.figures) {
      nlohmann::json fj = {{"caption", f.caption}};
      if (!f.dot.empty()) fj["dot"] = f.dot;
      if (!f.text.empty()) fj["text"] = f.text;
      j["figures"].push_back(std::move(fj));
    }
    out.push_back(std::move(j));
  }
  return out;
}

nlohmann::json solution_json(const Solution& solution) {
  const Problem& p = *solution.problem;
  nlohmann::json methods = nlohmann::json::array();
  for (const auto& m : solution.methods) {
    methods.push_back({{"method", m.method}, {"parts", parts_json(m.parts, solution.numbers)}});
  }
  nlohmann::json j = {{"id", p.id}, {"kind", p.kind}, {"answer", p.task->answer()}};
  if (!p.title.empty()) j["title"] = p.title;
  if (!p.statement.empty()) j["statement"] = p.statement;
  j["methods"] = methods;
  return j;
}

nlohmann::json diagnostic_json(const Diagnostic& d) {
  // printable(): a file name may be ill-formed UTF-8, which nlohmann refuses to dump.
  nlohmann::json j = {{"file", printable(d.file)},
                      {"path", printable(d.path)},
                      {"severity", to_string(d.severity)},
                      {"message", printable(d.message)},
                      {"code", d.code}};
  if (d.line > 0) j["line"] = d.line;
  if (d.column > 0) j["column"] = d.column;
  return j;
}

NumberFormat number_format_for(const Problem& p, int decimals_override) {
  NumberFormat f;
  if (decimals_override >= 0) {
    f.decimals = decimals_override;
  } else if (p.precision >= 0) {
    f.decimals = p.precision;
  }
  return f;
}

}  // namespace raygrade
