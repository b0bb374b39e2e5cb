// The sketch of a worked solution as SVG: an orthographic view of a Sketch in the plane that
// shows it best (the figure's main direction left to right, its widest spread up).
#pragma once

#include <string>

#include "shapes/sketch.h"

namespace raygrade {

struct SvgFigure {
  std::string svg;      // a complete <svg> element, no scripts, no external references
  std::string caption;  // plain text: which directions the view shows
};

// `title` becomes the SVG's accessible name (escaped here).
SvgFigure render_svg(const Sketch& figure, const std::string& title);

}  // namespace raygrade
