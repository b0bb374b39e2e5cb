// Plain-text worked solutions: each step as "symbol = formula = numbers = value".
#include "reports/text.h"

#include <fmt/format.h>

#include "core/escape.h"

namespace raygrade {
namespace {

constexpr const char* kIndent = "  ";
constexpr const char* kNoteIndent = "      ";

std::string step_line(const StepView& v, const NumberFormat& numbers) {
  const Step& s = *v.step;
  RenderOptions plain{nullptr, numbers, false};
  RenderOptions subst{&v.before, numbers, false};
  RenderOptions result{nullptr, numbers, true};
  std::string line = to_text(s.symbol, plain) + " = ";
  if (v.show_formula) line += to_text(s.formula, plain) + " = ";
  if (v.show_substituted) line += to_text(s.formula, subst) + " = ";
  return line + value_text(s.value, result);
}

void text_part(std::string& out, const SolutionPart& part, const NumberFormat& numbers) {
  const Derivation& d = part.derivation;
  out += "\n" + text_escape(part_title(part)) + "\n";
  for (const auto& f : part.figures) {
    if (!f.caption.empty()) out += std::string(kIndent) + text_escape(f.caption) + "\n";
    out += text_escape(f.text);
  }
  RenderOptions plain{nullptr, numbers, false};
  for (const auto& group : step_groups(d, numbers)) {
    if (group.given) {
      out += std::string(kIndent) + "Given:\n";
      std::vector<std::string> bare;  // givens without a note share a line
      auto flush = [&] {
        if (!bare.empty())
          out += std::string(kIndent) + kIndent + fmt::format("{}\n", fmt::join(bare, ", "));
        bare.clear();
      };
      for (const auto& v : group.steps) {
        std::string g = to_text(v.step->symbol, plain) + " = " + value_text(v.step->value, plain);
        if (v.step->note.empty()) {
          bare.push_back(g);
        } else {
          flush();
          out += std::string(kIndent) + kIndent + g + "  (" + text_escape(v.step->note) + ")\n";
        }
      }
      flush();
      continue;
    }
    for (const auto& v : group.steps) {
      out += std::string(kIndent) + step_line(v, numbers) + "\n";
      std::string note = v.step->note;
      if (name_differs_from_symbol(*v.step)) {
        note = note.empty() ? fmt::format("[{}]", v.step->name)
                            : fmt::format("[{}] {}", v.step->name, note);
      }
      if (!note.empty()) out += std::string(kNoteIndent) + text_escape(note) + "\n";
    }
  }
  for (const auto& s : d.sentences) {
    out += std::string(kIndent) + text_escape(sentence_text(s, numbers)) + "\n";
  }
}

std::string header(const Problem& problem) {
  std::string out = fmt::format("Problem {}", text_escape(problem.id));
  if (!problem.title.empty()) out += ": " + text_escape(problem.title);
  out += "\n";
  if (!problem.statement.empty()) out += text_escape(problem.statement) + "\n";
  return out;
}

}  // namespace

std::string render_text(const Solution& solution) {
  std::string out = header(*solution.problem);
  bool several = solution.methods.size() > 1;
  for (const auto& m : solution.methods) {
    if (several) out += "\n== Method: " + m.method + " ==\n";
    for (const auto& part : m.parts) text_part(out, part, solution.numbers);
  }
  return out;
}

std::string render_text(const Problem& problem, const std::vector<SolutionPart>& parts,
                        const NumberFormat& numbers) {
  std::string out = header(problem);
  for (const auto& part : parts) text_part(out, part, numbers);
  return out;
}

}  // namespace raygrade
