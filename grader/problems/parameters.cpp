// Reading a problem's parameters, drawing their values and filling them into the problem.
#include "problems/parameters.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "derivation/formula.h"
#include "sampling/lattice.h"

namespace raygrade {
namespace {

// At most this many values in one domain: far more than any exercise needs, few enough that a
// domain is listed and checked in a moment.
constexpr std::uint64_t kMaxDomain = 1000000;
// A draw that hits an excluded value is drawn again at most this many times.
constexpr int kMaxRedraws = 1000;
// A step is given with at most this many decimals (0.001 is fine; 1e-9 is not a course's).
constexpr int kMaxStepDecimals = 6;

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

// The decimals of a number as it is written: 0.25 → 2, 3 → 0.
int decimals_of(double v) {
  for (int d = 0; d <= 15; ++d) {
    double scaled = v * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) <= 1e-9 * std::max(1.0, std::abs(scaled))) return d;
  }
  return 16;
}

double rounded(double v, int decimals) {
  double s = std::pow(10.0, decimals);
  double r = std::round(v * s) / s;
  return r == 0 ? 0.0 : r;  // no "-0"
}

bool is_vector(const nlohmann::json& v) {
  if (!v.is_array() || v.size() != 3) return false;
  for (const auto& x : v) {
    if (!x.is_number()) return false;
  }
  return true;
}

bool same_value(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_number() && b.is_number()) return a.get<double>() == b.get<double>();
  return a == b;
}

// The symbols an expression may use: the scalar parameters.
SymbolTable scalar_symbols(const ParameterSet& set) {
  SymbolTable t;
  for (const auto& p : set.parameters) t.add(p.name);
  return t;
}

std::vector<double> scalar_values(const ParameterSet& set, const ParameterValues& values) {
  std::vector<double> out;
  for (const auto& p : set.parameters) {
    auto it = values.find(p.name);
    out.push_back(it != values.end() && it->second.is_number() ? it->second.get<double>()
                                                               : std::nan(""));
  }
  return out;
}

const Parameter* find_parameter(const ParameterSet& set, std::string_view name) {
  for (const auto& p : set.parameters) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

// Evaluates one expression (without its leading '=' or braces): a parameter's name, which may
// stand for a vector, or a formula over the numeric parameters.
nlohmann::json evaluate(std::string_view expr, const ParameterSet& set,
                        const ParameterValues& values, const Cursor& at,
                        std::set<std::string>* used) {
  std::string trimmed(expr);
  while (!trimmed.empty() && trimmed.front() == ' ') trimmed.erase(trimmed.begin());
  while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
  if (const Parameter* p = find_parameter(set, trimmed)) {
    if (used) used->insert(p->name);
    auto it = values.find(p->name);
    if (it != values.end() && !it->second.is_number()) return it->second;
  }
  SymbolTable symbols = scalar_symbols(set);
  FormulaParse parse = parse_formula(trimmed, &symbols);
  if (!parse.ok)
    at.fail(fmt::format("the expression '{}' does not read: {}", trimmed, parse.message));
  if (used) {
    for (const auto& in : parse.formula.program) {
      if (in.op == Formula::Op::kSymbol)
        used->insert(symbols.names()[static_cast<std::size_t>(in.slot)]);
    }
  }
  double v = parse.formula.evaluate(scalar_values(set, values));
  if (!std::isfinite(v)) {
    at.fail(
        fmt::format("the expression '{}' has no finite value for these parameters (a vector "
                    "parameter can stand only alone)",
                    trimmed));
  }
  // Rounding noise of the arithmetic (0.1 + 0.2) is cut at 12 decimals, so that the numbers
  // written into the problem are the ones a person computes.
  return number_json(rounded(v, 12));
}

// Fills "{expression}" in a text.
std::string fill_text(const std::string& text, const ParameterSet& set,
                      const ParameterValues& values, const Cursor& at,
                      std::set<std::string>* used) {
  std::string out;
  for (const TextPiece& piece : split_text(text, at)) {
    out +=
        piece.expression ? parameter_text(evaluate(piece.text, set, values, at, used)) : piece.text;
  }
  return out;
}

// Keys whose values are never filled in.
bool kept_as_is(std::string_view key) {
  return key == "id" || key == "tags" || key == "source" || key == "parameters" ||
         key == "nice_numbers" || key == "mistakes";
}

nlohmann::json fill(const Cursor& c, const ParameterSet& set, const ParameterValues& values,
                    std::set<std::string>* used, bool text) {
  const nlohmann::json& j = c.json();
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    if (!s.empty() && s[0] == '=')
      return evaluate(std::string_view(s).substr(1), set, values, c, used);
    return text ? nlohmann::json(fill_text(s, set, values, c, used)) : j;
  }
  if (j.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& item : c.items()) out.push_back(fill(item, set, values, used, false));
    return out;
  }
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, value] : j.items()) {
      if (kept_as_is(key)) {
        out[key] = value;
      } else {
        out[key] = fill(c.at(key), set, values, used, false);
      }
    }
    return out;
  }
  return j;
}

Parameter read_parameter(const Cursor& c, const std::string& name) {
  if (!is_identifier(name)) {
    c.fail(
        fmt::format("'{}' is not a parameter name (letters, digits and _, not starting with "
                    "a digit)",
                    name));
  }
  if (name == "pi" || name == "e")
    c.fail(fmt::format("'{}' is a constant, not a parameter name", name));
  FormulaParse as_function = parse_formula(name + "(1)");
  if (as_function.ok) c.fail(fmt::format("'{}' is a function, not a parameter name", name));
  c.allow_only({"integer", "range", "step", "choices", "exclude", "default"});
  Parameter p;
  p.name = name;
  int domains = c.has("integer") + c.has("range") + c.has("choices");
  if (domains != 1) c.fail("a parameter has exactly one of 'integer', 'range' or 'choices'");
  auto bounds = [&c](std::string_view key) {
    auto items = c.at(key).items();
    if (items.size() != 2) c.at(key).fail("expected [lowest, highest]");
    double lo = items[0].number(), hi = items[1].number();
    if (lo > hi) c.at(key).fail(fmt::format("the lowest value {} is above the highest {}", lo, hi));
    return std::pair{lo, hi};
  };
  if (c.has("integer")) {
    p.domain = Parameter::Domain::kInteger;
    auto items = c.at("integer").items();
    if (items.size() != 2) c.at("integer").fail("expected [lowest, highest]");
    p.lo = items[0].integer();
    p.hi = items[1].integer();
    if (p.lo > p.hi) c.at("integer").fail("the lowest value is above the highest");
    if (c.has("step")) c.at("step").fail("'step' goes with 'range'; an integer's step is 1");
  } else if (c.has("range")) {
    p.domain = Parameter::Domain::kRange;
    std::tie(p.lo, p.hi) = bounds("range");
    if (!c.has("step")) c.fail("a 'range' needs a 'step' (0.5, 0.25, ...)");
    p.step = c.at("step").positive_number();
    p.step_decimals = std::max(decimals_of(p.step), decimals_of(p.lo));
    if (p.step_decimals > kMaxStepDecimals) {
      c.at("step").fail(fmt::format("at most {} decimals in a step", kMaxStepDecimals));
    }
    if ((p.hi - p.lo) / p.step >= static_cast<double>(kMaxDomain)) {
      c.at("step").fail(fmt::format("more than {} values in the range", kMaxDomain));
    }
  } else {
    p.domain = Parameter::Domain::kChoices;
    for (const auto& item : c.at("choices").items()) {
      if (item.json().is_number()) {
        (void)item.number();
      } else if (!is_vector(item.json())) {
        item.fail("a choice is a number or a vector [x, y, z]");
      }
      p.choices.push_back(item.json());
    }
    if (p.choices.empty()) c.at("choices").fail("no choices");
    if (p.choices.size() > kMaxDomain) c.at("choices").fail("too many choices");
  }
  if (auto ex = c.find("exclude")) {
    for (const auto& item : ex->items()) p.exclude.push_back(item.json());
  }
  p.default_value = c.at("default").json();
  bool in_domain = false, excluded = false;
  for (const auto& e : p.exclude) excluded = excluded || same_value(e, p.default_value);
  for (std::uint64_t i = 0; i < p.size() && !in_domain; ++i)
    in_domain = same_value(p.value(i), p.default_value);
  if (!in_domain || excluded) {
    c.at("default").fail(
        fmt::format("the default {} is not one of the parameter's values", p.default_value.dump()));
  }
  return p;
}

}  // namespace

std::uint64_t Parameter::size() const {
  switch (domain) {
    case Domain::kInteger: return static_cast<std::uint64_t>(hi - lo) + 1;
    case Domain::kRange: return static_cast<std::uint64_t>(std::floor((hi - lo) / step + 1e-9)) + 1;
    case Domain::kChoices: return choices.size();
  }
  return 0;
}

nlohmann::json Parameter::value(std::uint64_t i) const {
  switch (domain) {
    case Domain::kInteger: return static_cast<long long>(lo) + static_cast<long long>(i);
    case Domain::kRange:
      return number_json(rounded(lo + static_cast<double>(i) * step, step_decimals));
    case Domain::kChoices: return choices[i];
  }
  return nullptr;
}

ParameterValues ParameterSet::defaults() const {
  ParameterValues v;
  for (const auto& p : parameters) v[p.name] = p.default_value;
  return v;
}

ParameterValues ParameterSet::draw(Prng& rng) const {
  ParameterValues v;
  for (const auto& p : parameters) {
    nlohmann::json value = p.default_value;
    for (int k = 0; k < kMaxRedraws; ++k) {
      nlohmann::json candidate = p.value(rng.below(p.size()));
      bool excluded = false;
      for (const auto& e : p.exclude) excluded = excluded || same_value(e, candidate);
      if (!excluded) {
        value = candidate;
        break;
      }
    }
    v[p.name] = value;
  }
  return v;
}

ParameterSet read_parameters(const Cursor& problem) {
  ParameterSet set;
  auto params = problem.find("parameters");
  if (!params) {
    if (problem.has("nice_numbers")) {
      problem.at("nice_numbers").fail("'nice_numbers' goes with 'parameters'");
    }
    return set;
  }
  if (!params->is_object() || params->json().empty()) {
    params->fail("parameters is an object: name → {integer | range | choices, default}");
  }
  for (const auto& [name, value] : params->json().items()) {
    set.parameters.push_back(read_parameter(params->at(name), name));
  }
  if (auto nice = problem.find("nice_numbers")) {
    nice->allow_only({"decimals", "fields"});
    NiceNumbers n;
    n.decimals = nice->at("decimals").integer();
    if (n.decimals < 0 || n.decimals > 6) nice->at("decimals").fail("decimals is from 0 to 6");
    if (auto f = nice->find("fields")) {
      n.fields.clear();
      for (const auto& item : f->items()) n.fields.push_back(item.string());
      if (n.fields.empty()) f->fail("no fields named");
    }
    set.nice = n;
  }
  // Every use names known parameters (checked by filling in the defaults), and every
  // parameter is used.
  std::set<std::string> used;
  ParameterValues defaults = set.defaults();
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, value] : problem.json().items()) {
    if (kept_as_is(key)) continue;
    (void)fill(problem.at(key), set, defaults, &used, key == "title" || key == "statement");
  }
  for (const auto& p : set.parameters) {
    if (!used.count(p.name)) {
      params->at(p.name).fail(
          fmt::format("the parameter '{}' is not used (write \"={}\" where a "
                      "number should take its value)",
                      p.name, p.name));
    }
  }
  return set;
}

std::vector<TextPiece> split_text(const std::string& text, const Cursor& at) {
  std::vector<TextPiece> pieces;
  std::string literal;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if ((c == '{' || c == '}') && i + 1 < text.size() && text[i + 1] == c) {
      literal += c;
      ++i;
    } else if (c == '{') {
      std::size_t close = text.find('}', i);
      if (close == std::string::npos) at.fail("a '{' without its '}' (write '{{' for a brace)");
      if (!literal.empty()) pieces.push_back({false, std::move(literal)});
      literal.clear();
      pieces.push_back({true, text.substr(i + 1, close - i - 1)});
      i = close;
    } else if (c == '}') {
      at.fail("a '}' without its '{' (write '}}' for a brace)");
    } else {
      literal += c;
    }
  }
  if (!literal.empty()) pieces.push_back({false, std::move(literal)});
  return pieces;
}

nlohmann::json evaluate_expression(std::string_view expr, const ParameterSet& set,
                                   const ParameterValues& values, const Cursor& at) {
  return evaluate(expr, set, values, at, nullptr);
}

nlohmann::json instantiate(const Cursor& problem, const ParameterSet& set,
                           const ParameterValues& values) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, value] : problem.json().items()) {
    if (key == "parameters" || key == "nice_numbers") continue;
    if (kept_as_is(key)) {
      out[key] = value;
    } else {
      out[key] = fill(problem.at(key), set, values, nullptr, key == "title" || key == "statement");
    }
  }
  return out;
}

bool has_nice_numbers(const nlohmann::json& answer, const NiceNumbers& nice) {
  bool ok = true;
  auto all_nice = [&](const nlohmann::json& v, auto&& self) -> void {
    if (v.is_number()) {
      ok = ok && decimals_of(v.get<double>()) <= nice.decimals;
    } else if (v.is_array()) {
      for (const auto& x : v) self(x, self);
    }
  };
  auto walk = [&](const nlohmann::json& v, auto&& self) -> void {
    if (v.is_object()) {
      for (const auto& [key, value] : v.items()) {
        if (std::find(nice.fields.begin(), nice.fields.end(), key) != nice.fields.end()) {
          all_nice(value, all_nice);
        } else {
          self(value, self);
        }
      }
    } else if (v.is_array()) {
      for (const auto& x : v) self(x, self);
    }
  };
  walk(answer, walk);
  return ok;
}

std::string parameter_text(const nlohmann::json& value) {
  if (value.is_array()) {
    std::vector<std::string> parts;
    for (const auto& x : value) parts.push_back(parameter_text(x));
    return fmt::format("({})", fmt::join(parts, ", "));
  }
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) {
    double v = value.get<double>();
    if (v == std::round(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    return fmt::format("{}", v);
  }
  return value.dump();
}

}  // namespace raygrade
