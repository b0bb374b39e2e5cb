// The formats of worked solutions, and one entry point that renders a document in any of them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "reports/markdown.h"
#include "reports/solution.h"

namespace raygrade {

enum class Format { kMarkdown, kHtml, kText, kJson };

// One row of the table of solution formats: its name (also the file extension, and what
// --format takes), a line for --help and the docs, and what renders a document in it.
struct SolutionFormat {
  Format format;
  std::string_view name;
  std::string_view summary;
  std::string (*render)(const std::vector<const Solution*>& solutions,
                        const DocumentOptions& options);
};

// The table, in the order the solutions folder is written: md, html, txt, json.
const std::vector<SolutionFormat>& solution_formats();

std::optional<Format> parse_format(std::string_view name);
std::string_view format_extension(Format f);
const std::vector<Format>& all_formats();
// The names of the table, in its order: what a --format option accepts.
std::vector<std::string> solution_format_names();

// A document holding the given solutions. JSON: one solution is an object, several are
// {"solutions": [...]}; `options.generated` becomes the first key, on the first line.
std::string render_document(Format f, const std::vector<const Solution*>& solutions,
                            const DocumentOptions& options = {});

}  // namespace raygrade
