// Markdown rendering: headings and notes as escaped text, every formula as LaTeX math.
#include "reports/markdown.h"

#include <fmt/format.h>

#include "core/escape.h"

namespace raygrade {
namespace {

std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return s;
}

// Text inside a ``` fence: a line of its own starting with ``` would close it early.
std::string fence_safe(const std::string& s) {
  std::string out;
  bool line_start = true;
  for (char c : s) {
    if (line_start && c == '`') out += ' ';
    out += c;
    line_start = c == '\n';
  }
  if (!out.empty() && out.back() != '\n') out += '\n';
  return out;
}

std::string markdown_step_math(const StepView& v, const NumberFormat& numbers) {
  const Step& s = *v.step;
  RenderOptions plain{nullptr, numbers, false};
  RenderOptions subst{&v.before, numbers, false};
  RenderOptions result{nullptr, numbers, true};
  std::string m = to_latex(s.symbol, plain) + " = ";
  if (v.show_formula) m += to_latex(s.formula, plain) + " = ";
  if (v.show_substituted) m += to_latex(s.formula, subst) + " = ";
  return m + value_latex(s.value, result);
}

void markdown_part(std::string& out, const SolutionPart& part, const NumberFormat& numbers,
                   const char* level) {
  out += fmt::format("\n{} {}\n", level, markdown_escape(one_line(part_title(part))));
  for (const auto& f : part.figures) {
    if (!f.caption.empty()) out += "\n*" + markdown_escape(one_line(f.caption)) + "*\n";
    if (!f.text.empty()) out += "\n```text\n" + fence_safe(f.text) + "```\n";
  }
  RenderOptions plain{nullptr, numbers, false};
  for (const auto& group : step_groups(part.derivation, numbers)) {
    if (group.given) {
      out += "\nGiven:\n\n";
      std::vector<std::string> bare;  // givens without a note share a bullet
      auto flush = [&] {
        if (!bare.empty()) out += fmt::format("- {}\n", fmt::join(bare, ", "));
        bare.clear();
      };
      for (const auto& v : group.steps) {
        std::string g =
            "$" + to_latex(v.step->symbol, plain) + " = " + value_latex(v.step->value, plain) + "$";
        if (v.step->note.empty()) {
          bare.push_back(g);
        } else {
          flush();
          out += "- " + g + " — " + markdown_escape(one_line(v.step->note)) + "\n";
        }
      }
      flush();
      continue;
    }
    for (const auto& v : group.steps) {
      out += "\n**`" + v.step->name + "`**";
      if (!v.step->note.empty()) out += " — " + markdown_escape(one_line(v.step->note));
      out += "\n\n$$" + markdown_step_math(v, numbers) + "$$\n";
    }
  }
  if (!part.derivation.sentences.empty()) {
    out += "\n";
    for (const auto& s : part.derivation.sentences) {
      out += "> " + markdown_escape(one_line(sentence_text(s, numbers))) + "\n";
    }
  }
}

}  // namespace

std::string render_markdown(const Solution& solution, const DocumentOptions& options) {
  const Problem& p = *solution.problem;
  std::string out;
  if (!options.generated.empty())
    out += "<!-- " + html_escape(one_line(options.generated)) + " -->\n";
  out += "# " + markdown_escape(one_line(p.title.empty() ? p.id : p.title)) + "\n\n";
  out += "Problem " + markdown_escape(p.id) + " (" + markdown_escape(p.kind) + ")\n";
  if (!p.statement.empty()) out += "\n" + markdown_escape(p.statement) + "\n";
  if (!options.html_link.empty()) {
    out += "\nThe same solution with a sketch of the ray and the objects: [" +
           markdown_escape(options.html_link) + "](" + options.html_link + ")\n";
  }
  bool several = solution.methods.size() > 1;
  for (const auto& m : solution.methods) {
    bool heading = several || m.parts.size() > 1;
    if (heading) out += "\n## Method: " + markdown_escape(m.method) + "\n";
    for (const auto& part : m.parts)
      markdown_part(out, part, solution.numbers, heading ? "###" : "##");
  }
  return out;
}

}  // namespace raygrade
