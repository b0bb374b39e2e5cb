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

// "md", "html", "txt", "json" (the file extensions).
std::optional<Format> parse_format(std::string_view name);
std::string_view format_extension(Format f);
const std::vector<Format>& all_formats();

// A document holding the given solutions. JSON: one solution is an object, several are
// {"solutions": [...]}; `options.generated` becomes the first key, on the first line.
std::string render_document(Format f, const std::vector<const Solution*>& solutions,
                            const DocumentOptions& options = {});

}  // namespace raygrade
