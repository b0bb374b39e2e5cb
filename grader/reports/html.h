// HTML worked solutions: math as MathML, the sketch as inline SVG, the style inline; no network.
// No script either, unless DocumentOptions::scene_view_src names the 3D view's script beside
// the page (the solutions folder), which then draws each problem's scene.
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
