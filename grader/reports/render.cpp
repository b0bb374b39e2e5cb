// The table of solution formats, and rendering a document in one of them.
#include "reports/render.h"

#include <algorithm>

#include "core/escape.h"
#include "core/internal_error.h"
#include "json/numbers.h"
#include "reports/html.h"
#include "reports/json_report.h"
#include "reports/text.h"

namespace raygrade {
namespace {

std::string markdown_document(const std::vector<const Solution*>& solutions,
                              const DocumentOptions& options) {
  std::string out;
  for (std::size_t i = 0; i < solutions.size(); ++i) {
    DocumentOptions o = options;
    if (i) {
      o.generated.clear();
      out += "\n---\n\n";
    }
    out += render_markdown(*solutions[i], o);
  }
  return out;
}

std::string text_document(const std::vector<const Solution*>& solutions,
                          const DocumentOptions& options) {
  std::string out;
  if (!options.generated.empty()) out += text_escape(options.generated) + "\n\n";
  for (std::size_t i = 0; i < solutions.size(); ++i) {
    if (i) out += "\n";
    out += render_text(*solutions[i]);
  }
  return out;
}

std::string json_document(const std::vector<const Solution*>& solutions,
                          const DocumentOptions& options) {
  nlohmann::json body;
  if (solutions.size() == 1) {
    body = solution_json(*solutions[0]);
  } else {
    body = {{"solutions", nlohmann::json::array()}};
    for (const Solution* s : solutions) body["solutions"].push_back(solution_json(*s));
  }
  drop_negative_zeros(body);
  std::string dumped = body.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  if (options.generated.empty()) return dumped + "\n";
  // The note goes first, on the first line, like the other formats' notes.
  return "{\"generated\": " + nlohmann::json(options.generated).dump() + "," + dumped.substr(1) +
         "\n";
}

const SolutionFormat& entry(Format f) {
  for (const auto& e : solution_formats()) {
    if (e.format == f) return e;
  }
  throw InternalError("a solution format missing from the table of solution formats");
}

}  // namespace

const std::vector<SolutionFormat>& solution_formats() {
  static const std::vector<SolutionFormat> table = {
      {Format::kMarkdown, "md",
       "Markdown with LaTeX formulas; links to the HTML page for the sketch", &markdown_document},
      {Format::kHtml, "html",
       "one self-contained page: MathML formulas and the sketch as inline SVG", &render_html},
      {Format::kText, "txt", "plain text with Unicode formulas, for a terminal or an LMS comment",
       &text_document},
      {Format::kJson, "json", "the steps as data: named quantities with their formulas and values",
       &json_document},
  };
  return table;
}

std::optional<Format> parse_format(std::string_view name) {
  for (const auto& e : solution_formats()) {
    if (e.name == name) return e.format;
  }
  return std::nullopt;
}

std::string_view format_extension(Format f) { return entry(f).name; }

const std::vector<Format>& all_formats() {
  static const std::vector<Format> formats = [] {
    std::vector<Format> out;
    for (const auto& e : solution_formats()) out.push_back(e.format);
    return out;
  }();
  return formats;
}

std::vector<std::string> solution_format_names() {
  std::vector<std::string> out;
  for (const auto& e : solution_formats()) out.emplace_back(e.name);
  return out;
}

std::string render_document(Format f, const std::vector<const Solution*>& solutions,
                            const DocumentOptions& options) {
  return entry(f).render(solutions, options);
}

}  // namespace raygrade
