// Plain-text worked solutions: each step as "name = formula = numbers = value".
#include "reports/text.h"

#include <fmt/format.h>

namespace raygrade {

std::string render_text(const Problem& problem, const std::vector<SolutionPart>& parts,
                        const NumberFormat& numbers) {
  std::string out = fmt::format("Problem {}", problem.id);
  if (!problem.title.empty()) out += ": " + problem.title;
  out += "\n";
  if (!problem.statement.empty()) out += problem.statement + "\n";
  for (const auto& part : parts) {
    const Derivation& d = part.derivation;
    out += "\n";
    if (!part.heading.empty()) out += part.heading + " — ";
    out += d.title + "\n";
    for (const auto& f : part.figures) {
      if (!f.caption.empty()) out += "  " + f.caption + "\n";
      out += f.text;
    }
    Env env;  // the values of the steps so far, for the substituted form
    RenderOptions plain{nullptr, numbers};
    for (const auto& s : d.steps) {
      std::string line = "  " + to_text(s.symbol, plain) + " = ";
      if (!s.given) {
        RenderOptions subst{&env, numbers};
        std::string formula = to_text(s.formula, plain);
        std::string numbers_in = to_text(s.formula, subst);
        line += formula + " = ";
        if (numbers_in != formula) line += numbers_in + " = ";
      }
      line += format_value(s.value, numbers);
      out += line + "\n";
      if (!s.note.empty()) out += "      " + s.note + "\n";
      env[s.name] = s.value;
    }
    for (const auto& c : d.conclusion) out += "  " + c + "\n";
  }
  return out;
}

}  // namespace raygrade
