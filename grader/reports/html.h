// Self-contained HTML worked solutions: math as MathML, the sketch as inline SVG, the style
// inline; no script, no network.
#pragma once

#include <string>
#include <vector>

#include "reports/markdown.h"
#include "reports/solution.h"

namespace raygrade {

// One page holding every solution given (usually one).
std::string render_html(const std::vector<const Solution*>& solutions,
                        const DocumentOptions& options = {});

}  // namespace raygrade
