// The swatch figure.
#include "kinds/swatch.h"

#include <fmt/format.h>

#include "core/escape.h"
#include "scenes/colour.h"

namespace raygrade {
namespace {

// The SVG's layout, in pixels: a square per row, its text to the right.
constexpr double kSwatchSize = 18;
constexpr double kSwatchRow = 26;
constexpr double kSwatchWidth = 360;

}  // namespace

Figure swatch_figure(const std::vector<std::pair<std::string, Vec3d>>& colours) {
  Figure f;
  f.caption = "The colours, each channel clamped to [0, 1] for display (the numbers are not)";
  double height = 8 + kSwatchRow * static_cast<double>(colours.size());
  f.svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"swatches\" width=\"{0:.0f}\" "
      "height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" "
      "font-size=\"12\" role=\"img\">\n<title>Colour swatches</title>\n",
      kSwatchWidth, height);
  double y = 4;
  for (const auto& [name, rgb] : colours) {
    std::string words = fmt::format("{} = {}", name, colour_text(rgb));
    f.svg += fmt::format(
        "<rect x=\"4\" y=\"{:.0f}\" width=\"{:.0f}\" height=\"{:.0f}\" fill=\"{}\" "
        "stroke=\"#333\"/>\n<text x=\"{:.0f}\" y=\"{:.0f}\">{}</text>\n",
        y, kSwatchSize, kSwatchSize, swatch_hex(rgb), 12 + kSwatchSize, y + 13, xml_escape(words));
    f.text += fmt::format("[{}] {}\n", swatch_hex(rgb), words);
    y += kSwatchRow;
  }
  f.svg += "</svg>\n";
  return f;
}

}  // namespace raygrade
