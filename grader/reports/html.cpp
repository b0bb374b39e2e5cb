// HTML rendering: escaped text, MathML formulas, an SVG sketch per problem.
#include "reports/html.h"

#include <fmt/format.h>

#include "core/escape.h"
#include "reports/scene_view.h"
#include "reports/svg_figure.h"

namespace raygrade {
namespace {

constexpr const char* kStyle = R"(
:root{color-scheme:light;--ink:#1d232b;--muted:#5b6673;--line:#dfe4ea;--accent:#2d5f8b;--hit:#b83227}
*{box-sizing:border-box}
body{margin:0;background:#f6f7f9;color:var(--ink);font:16px/1.55 system-ui,-apple-system,"Segoe UI",Roboto,"DejaVu Sans",sans-serif}
main{max-width:900px;margin:0 auto;padding:24px 20px 48px}
article{background:#fff;border:1px solid var(--line);border-radius:10px;padding:24px 28px;margin:0 0 28px}
.kicker{margin:0;color:var(--muted);font-size:.85rem;letter-spacing:.02em}
h1{margin:.2rem 0 .6rem;font-size:1.6rem;line-height:1.25}
h2{margin:1.8rem 0 .6rem;font-size:1.25rem;border-bottom:2px solid var(--line);padding-bottom:.2rem}
h3{margin:1.4rem 0 .5rem;font-size:1.08rem}
.statement{margin:.2rem 0 1rem}
figure.sketch{margin:1rem 0 1.2rem;text-align:center}
figure.sketch svg{max-width:100%;height:auto;background:#fff}
figcaption{color:var(--muted);font-size:.85rem;margin-top:.3rem}
.given{background:#f3f6fa;border-radius:8px;padding:.6rem 1rem;margin:.6rem 0 1rem}
.given h3,.given h4{margin:0 0 .3rem;font-size:.8rem;text-transform:uppercase;letter-spacing:.06em;color:var(--muted)}
.given ul{margin:0;padding:0;list-style:none;display:flex;flex-wrap:wrap;gap:.25rem 1.6rem}
.given li{white-space:nowrap;max-width:100%}
.given li .note{white-space:normal}
.note{color:var(--muted);font-size:.9rem}
ol.steps{list-style:none;margin:0;padding:0;counter-reset:step}
ol.steps li{counter-increment:step;border-left:3px solid var(--line);padding:.35rem 0 .35rem 1rem;margin:.5rem 0}
.step-head{margin:0;font-size:.9rem}
.step-head::before{content:counter(step) ". ";color:var(--muted)}
code.name{background:#eef2f6;border-radius:4px;padding:.05rem .35rem;font-size:.85rem;color:var(--accent)}
math[display=block]{margin:.35rem 0;font-size:1.08rem}
.chain{display:flex;flex-wrap:wrap;align-items:baseline;column-gap:.25em;margin:.35rem 0;font-size:1.08rem}
.chain math{math-style:normal}
.conclusion{border-left:4px solid var(--hit);background:#fbf3f2;border-radius:0 8px 8px 0;padding:.6rem 1rem;margin:1rem 0 .4rem}
.conclusion p{margin:.2rem 0}
)";

std::string text_html(const std::string& s) {
  std::string out = html_escape(s);
  std::string with_breaks;
  for (char c : out) {
    if (c == '\n') {
      with_breaks += "<br>";
    } else if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') {
      with_breaks += c;
    }
  }
  return with_breaks;
}

std::string math(const std::string& inner, bool block) {
  return std::string(block ? "<math display=\"block\">" : "<math>") + "<mrow>" + inner +
         "</mrow></math>";
}

// The top-level elements of a MathML row, each from its opening tag to its matching end.
std::vector<std::string> row_elements(const std::string& row) {
  std::vector<std::string> out;
  std::size_t start = 0;
  int depth = 0;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (row[i] != '<') continue;
    bool closing = i + 1 < row.size() && row[i + 1] == '/';
    std::size_t end = row.find('>', i);
    if (end == std::string::npos) break;
    bool self_closing = row[end - 1] == '/';
    if (!closing && !self_closing) ++depth;
    if (closing) --depth;
    i = end;
    if (depth == 0) {
      out.push_back(row.substr(start, end + 1 - start));
      start = end + 1;
    }
  }
  return out;
}

// A formula's MathML cut before each + and − between its terms: "= a", "+ b", "− c". Signs
// inside parentheses, fractions or roots are nested deeper and stay; a sign that follows
// another operator is a sign of the term (a unary minus), not a place to cut.
std::vector<std::string> terms(const std::string& row) {
  std::vector<std::string> out;
  bool after_operator = true;
  for (const auto& e : row_elements(row)) {
    bool is_operator = e.rfind("<mo>", 0) == 0;
    bool cut = (e == "<mo>+</mo>" || e == "<mo>−</mo>") && !after_operator;
    if (out.empty() || cut) out.emplace_back();
    out.back() += e;
    after_operator = is_operator;
  }
  return out;
}

// A step as a chain "symbol = formula = numbers = value", one link per "= ..." and per term of
// a sum, each its own <math>, so that a chain too long for the page breaks before an "=", a
// "+" or a "−" (the browser wraps the links like words; MathML Core, as browsers implement
// it, never breaks a formula by itself).
std::string html_step_math(const StepView& v, const NumberFormat& numbers) {
  const Step& s = *v.step;
  RenderOptions plain{nullptr, numbers, false};
  RenderOptions subst{&v.before, numbers, false};
  RenderOptions result{nullptr, numbers, true};
  std::string out = "<div class=\"chain\">";
  // A link that opens with =, + or − keeps the spacing of a binary operator (first in its
  // <math>, an operator would otherwise be spaced as a prefix sign: "+t").
  auto link = [&out](const std::string& t) {
    bool sign = t.rfind("<mo>", 0) == 0;
    out += "<math displaystyle=\"true\"><mrow>" + (sign ? "<mo form=\"infix\">" + t.substr(4) : t) +
           "</mrow></math>";
  };
  auto links = [&link](const std::string& row) {
    for (const auto& t : terms(row)) link(t);
  };
  const std::string eq = "<mo>=</mo>";
  links(to_mathml(s.symbol, plain));
  if (v.show_formula) links(eq + to_mathml(s.formula, plain));
  if (v.show_substituted) links(eq + to_mathml(s.formula, subst));
  link(eq + value_mathml(s.value, result));  // the value stays whole: "9 − √3 ≈ 7.268"
  return out + "</div>";
}

void html_part(std::string& out, const SolutionPart& part, const NumberFormat& numbers,
               const char* tag) {
  out += fmt::format("<{0}>{1}</{0}>\n", tag, text_html(part_title(part)));
  for (const auto& f : part.figures) {
    // The kind drew it, with its text escaped (Figure::svg's contract).
    out += "<figure class=\"sketch\">\n" + f.svg + "\n<figcaption>" + text_html(f.caption) +
           "</figcaption>\n</figure>\n";
  }
  RenderOptions plain{nullptr, numbers, false};
  // "Given" is a heading one level below the part's own.
  const char* given_tag = std::string_view(tag) == "h2" ? "h3" : "h4";
  bool in_steps = false;
  for (const auto& group : step_groups(part.derivation, numbers)) {
    if (group.given) {
      if (in_steps) out += "</ol>\n";
      in_steps = false;
      out += fmt::format("<div class=\"given\"><{0}>Given</{0}><ul>\n", given_tag);
      for (const auto& v : group.steps) {
        out += "<li>" + math(to_mathml(v.step->symbol, plain) + "<mo>=</mo>" +
                                 value_mathml(v.step->value, plain),
                             false);
        if (!v.step->note.empty())
          out += " <span class=\"note\">" + text_html(v.step->note) + "</span>";
        out += "</li>\n";
      }
      out += "</ul></div>\n";
      continue;
    }
    if (!in_steps) out += "<ol class=\"steps\">\n";
    in_steps = true;
    for (const auto& v : group.steps) {
      out += "<li><p class=\"step-head\"><code class=\"name\">" + html_escape(v.step->name) +
             "</code>";
      if (!v.step->note.empty())
        out += " <span class=\"note\">" + text_html(v.step->note) + "</span>";
      out += "</p>\n" + html_step_math(v, numbers) + "</li>\n";
    }
  }
  if (in_steps) out += "</ol>\n";
  if (!part.derivation.sentences.empty()) {
    out += "<div class=\"conclusion\">\n";
    for (const auto& s : part.derivation.sentences) {
      out += "<p>" + text_html(sentence_text(s, numbers)) + "</p>\n";
    }
    out += "</div>\n";
  }
}

// Returns whether it drew a 3D view (the page then loads the view's script).
bool render_article(std::string& out, const Solution& solution, const DocumentOptions& options) {
  const Problem& p = *solution.problem;
  std::string title = p.title.empty() ? p.id : p.title;
  out += "<article id=\"" + html_escape(safe_file_name(p.id)) + "\">\n<header>\n";
  out += "<p class=\"kicker\">Problem <code>" + html_escape(p.id) + "</code> · " +
         html_escape(p.kind) + "</p>\n";
  out += "<h1>" + text_html(title) + "</h1>\n";
  if (!p.statement.empty()) out += "<p class=\"statement\">" + text_html(p.statement) + "</p>\n";
  out += "</header>\n";
  if (!solution.sketch.empty()) {
    SvgFigure svg = render_svg(solution.sketch, "Sketch: " + title);
    out += "<figure class=\"sketch\">\n" + svg.svg + "\n<figcaption>" + text_html(svg.caption) +
           "</figcaption>\n</figure>\n";
  }
  bool viewed = false;
  if (!options.scene_view_src.empty()) {
    if (std::optional<SceneView> view = scene_view(p, true)) {
      out += scene_view_html(*view, "scene-" + safe_file_name(p.id), title);
      viewed = true;
    }
  }
  bool several = solution.methods.size() > 1;
  for (const auto& m : solution.methods) {
    bool heading = several || m.parts.size() > 1;
    out += "<section class=\"method\">\n";
    if (heading) out += "<h2>Method: " + html_escape(m.method) + "</h2>\n";
    for (const auto& part : m.parts) html_part(out, part, solution.numbers, heading ? "h3" : "h2");
    out += "</section>\n";
  }
  out += "</article>\n";
  return viewed;
}

}  // namespace

std::string render_html(const std::vector<const Solution*>& solutions,
                        const DocumentOptions& options) {
  std::string out;
  if (!options.generated.empty()) out += "<!-- " + html_escape(options.generated) + " -->\n";
  std::string title = "Worked solutions";
  if (solutions.size() == 1) {
    const Problem& p = *solutions[0]->problem;
    title = (p.title.empty() ? p.id : p.title) + " — worked solution";
  }
  out +=
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta name=\"generator\" content=\"raygrade\">\n<title>" +
      html_escape(text_escape(title)) + "</title>\n<style>" + kStyle +
      "</style>\n</head>\n<body>\n<main>\n";
  bool views = false;
  for (const Solution* s : solutions) views = render_article(out, *s, options) || views;
  if (views) {
    out += "<style>" + std::string(kSceneViewStyle) + "</style>\n<script src=\"" +
           html_escape(options.scene_view_src) + "\"></script>\n";
  }
  out += "</main>\n</body>\n</html>\n";
  return out;
}

}  // namespace raygrade
