// Building worked solutions and the presentation rules every format shares.
#include "reports/solution.h"

#include <algorithm>

namespace raygrade {

Solution make_solution(const Problem& problem, const std::string& method,
                       const NumberFormat& numbers) {
  Solution s;
  s.problem = &problem;
  s.numbers = numbers;
  std::vector<std::string> methods;
  std::vector<std::string> known = problem.task->methods();
  if (method == "all") {
    methods = known;
  } else if (!method.empty() && std::find(known.begin(), known.end(), method) != known.end()) {
    methods = {method};
  } else {
    methods = {problem.method};
  }
  for (const auto& m : methods) {
    WorkedMethod ms;
    ms.parts = problem.task->derive(m);
    ms.method = ms.parts.empty() ? m : ms.parts.front().derivation.method;
    s.methods.push_back(std::move(ms));
  }
  s.sketch = problem.task->sketch();
  return s;
}

namespace {

std::string squeeze(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c != ' ') out += c;
  }
  return out;
}

}  // namespace

std::vector<StepGroup> step_groups(const Derivation& d, const NumberFormat& numbers) {
  std::vector<StepGroup> groups;
  Env env;
  RenderOptions plain{nullptr, numbers, false};
  for (const auto& s : d.steps) {
    StepView v;
    v.step = &s;
    v.before = env;
    if (!s.given) {
      RenderOptions subst{&env, numbers, false};
      std::string symbol = squeeze(to_text(s.symbol, plain));
      std::string formula = squeeze(to_text(s.formula, plain));
      std::string with_numbers = squeeze(to_text(s.formula, subst));
      std::string value = squeeze(value_text(s.value, plain));
      // The value as shown, with its exact form: "1/6≈0.1667" repeats the numbers "1/6".
      std::string shown = squeeze(value_text(s.value, RenderOptions{nullptr, numbers, true}));
      v.show_formula = formula != symbol;
      v.show_substituted = with_numbers != formula && with_numbers != value &&
                           shown.rfind(with_numbers + "≈", 0) != 0;
      // The value is always shown: a formula that is already the value is left out.
      if (v.show_formula && !v.show_substituted && formula == value) v.show_formula = false;
    }
    if (groups.empty() || groups.back().given != s.given) groups.push_back(StepGroup{s.given, {}});
    groups.back().steps.push_back(std::move(v));
    env[s.name] = s.value;
  }
  return groups;
}

bool name_differs_from_symbol(const Step& s) { return squeeze(to_text(s.symbol)) != s.name; }

std::string text_number(double v, const NumberFormat& numbers) {
  std::string s = format_number(v, numbers);
  return !s.empty() && s[0] == '-' ? "−" + s.substr(1) : s;
}

std::string sentence_text(const Sentence& s, const NumberFormat& numbers) {
  std::string out;
  for (const auto& p : s.parts()) {
    switch (p.value.kind) {
      case Value::Kind::kNone: out += p.text; break;
      case Value::Kind::kScalar:
        if (auto x = exact_form(p.value.scalar);
            x && exact_text(*x) != text_number(p.value.scalar, numbers)) {
          out += exact_text(*x) + " ≈ " + text_number(p.value.scalar, numbers);
        } else {
          out += text_number(p.value.scalar, numbers);
        }
        break;
      case Value::Kind::kVector:
        out += "(" + text_number(p.value.vector.x, numbers) + ", " +
               text_number(p.value.vector.y, numbers) + ", " +
               text_number(p.value.vector.z, numbers) + ")";
        break;
      case Value::Kind::kBool: out += p.value.truth ? "yes" : "no"; break;
    }
  }
  return out;
}

std::string part_title(const SolutionPart& part) {
  if (part.heading.empty()) return part.derivation.title;
  return part.heading + " — " + part.derivation.title;
}

}  // namespace raygrade
