// Markdown worked solutions with LaTeX math ($...$ and $$...$$), as GitHub renders them.
#pragma once

#include <string>

#include "reports/solution.h"

namespace raygrade {

struct DocumentOptions {
  std::string generated;  // the first line's note (who generated the file, how); empty: none
  std::string html_link;  // Markdown: a link to the HTML page with the sketch; empty: none
  // HTML: the file of the 3D view's script (kSceneViewScript) beside the page, loaded with
  // <script src>; each problem then gets its 3D view. Empty: no view and no script.
  std::string scene_view_src;
};

std::string render_markdown(const Solution& solution, const DocumentOptions& options = {});

}  // namespace raygrade
