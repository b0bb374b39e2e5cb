// Rendering a document of worked solutions in a chosen format.
#include "reports/render.h"

#include "core/escape.h"
#include "reports/html.h"
#include "reports/json_report.h"
#include "reports/text.h"

namespace raygrade {

std::optional<Format> parse_format(std::string_view name) {
  if (name == "md") return Format::kMarkdown;
  if (name == "html") return Format::kHtml;
  if (name == "txt") return Format::kText;
  if (name == "json") return Format::kJson;
  return std::nullopt;
}

std::string_view format_extension(Format f) {
  switch (f) {
    case Format::kMarkdown: return "md";
    case Format::kHtml: return "html";
    case Format::kText: return "txt";
    case Format::kJson: return "json";
  }
  return "txt";
}

const std::vector<Format>& all_formats() {
  static const std::vector<Format> formats = {Format::kMarkdown, Format::kHtml, Format::kText,
                                              Format::kJson};
  return formats;
}

std::string render_document(Format f, const std::vector<const Solution*>& solutions,
                            const DocumentOptions& options) {
  std::string out;
  switch (f) {
    case Format::kHtml: return render_html(solutions, options);
    case Format::kMarkdown:
      for (std::size_t i = 0; i < solutions.size(); ++i) {
        DocumentOptions o = options;
        if (i) {
          o.generated.clear();
          out += "\n---\n\n";
        }
        out += render_markdown(*solutions[i], o);
      }
      return out;
    case Format::kText:
      if (!options.generated.empty()) out += text_escape(options.generated) + "\n\n";
      for (std::size_t i = 0; i < solutions.size(); ++i) {
        if (i) out += "\n";
        out += render_text(*solutions[i]);
      }
      return out;
    case Format::kJson: {
      nlohmann::json body;
      if (solutions.size() == 1) {
        body = solution_json(*solutions[0]);
      } else {
        body = {{"solutions", nlohmann::json::array()}};
        for (const Solution* s : solutions) body["solutions"].push_back(solution_json(*s));
      }
      std::string dumped = body.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
      if (options.generated.empty()) return dumped + "\n";
      // The note goes first, on the first line, like the other formats' notes.
      return "{\"generated\": " + nlohmann::json(options.generated).dump() + "," +
             dumped.substr(1) + "\n";
    }
  }
  return out;
}

}  // namespace raygrade
