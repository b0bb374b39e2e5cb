// The plot of the accuracy report: error against time, log-log, one point per level and
// primitive (peers included).
#include <algorithm>
#include <cmath>

#include "accuracy/report.h"
#include "core/escape.h"

namespace raygrade {
namespace {

// Plot ranges, in decades: errors from 1e-17 (exact, drawn at the floor) to 10, times from
// 1 ns to 1e6 ns.
constexpr double kErrorFloor = 1e-17;
constexpr int kErrorDecadeLow = -17, kErrorDecadeHigh = 1;
constexpr int kTimeDecadeLow = 0, kTimeDecadeHigh = 6;
constexpr double kWidth = 900, kHeight = 560, kLeft = 70, kRight = 260, kTop = 20, kBottom = 50;

double x_of(double ns) {
  double d = std::log10(std::clamp(ns, 1.0, 1e6));
  return kLeft +
         (d - kTimeDecadeLow) / (kTimeDecadeHigh - kTimeDecadeLow) * (kWidth - kLeft - kRight);
}

double y_of(double e) {
  double d = std::log10(std::clamp(e, kErrorFloor, 10.0));
  return kTop +
         (kErrorDecadeHigh - d) / (kErrorDecadeHigh - kErrorDecadeLow) * (kHeight - kTop - kBottom);
}

// The primitives' markers, by index: filled and open circles, squares, triangles and diamonds,
// a cross and a plus, then round again.
std::string marker(Primitive p, double x, double y, const std::string& color) {
  const std::string fill = fmt::format("fill='{}'", color),
                    open = fmt::format("fill='none' stroke='{}' stroke-width='2'", color);
  std::string circle = "<circle cx='{:.1f}' cy='{:.1f}' r='4' {}/>",
              square = "<rect x='{:.1f}' y='{:.1f}' width='8' height='8' {}/>",
              triangle = "<path d='M{:.1f} {:.1f}l5 9h-10z' {}/>",
              diamond = "<path d='M{:.1f} {:.1f}l5 5l-5 5l-5 -5z' {}/>";
  switch (static_cast<std::size_t>(p) % 9) {
    case 0: return fmt::format(fmt::runtime(circle), x, y, fill);
    case 1: return fmt::format(fmt::runtime(square), x - 4, y - 4, fill);
    case 2: return fmt::format(fmt::runtime(triangle), x, y - 5, fill);
    case 3: return fmt::format(fmt::runtime(diamond), x, y - 5, fill);
    case 4: return fmt::format(fmt::runtime(circle), x, y, open);
    case 5: return fmt::format(fmt::runtime(square), x - 4, y - 4, open);
    case 6: return fmt::format(fmt::runtime(triangle), x, y - 5, open);
    case 7: return fmt::format(fmt::runtime(diamond), x, y - 5, open);
    default: return fmt::format("<path d='M{:.1f} {:.1f}l8 8m0 -8l-8 8' {}/>", x - 4, y - 4, open);
  }
}

const char* kColors[] = {"#9e9e9e", "#e53935", "#fb8c00", "#1e88e5", "#3949ab",
                         "#8e24aa", "#00897b", "#6d4c41", "#43a047", "#000000",
                         "#f06292", "#c0ca33", "#26c6da"};

}  // namespace

std::string render_accuracy_svg(const AccuracyReport& r) {
  std::vector<std::string> names;
  for (const auto& row : r.rows) {
    if (std::find(names.begin(), names.end(), row.level) == names.end()) names.push_back(row.level);
  }
  auto color = [&](const std::string& name) {
    auto i = std::find(names.begin(), names.end(), name) - names.begin();
    return std::string(kColors[i % std::size(kColors)]);
  };
  std::string s = fmt::format(
      "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' font-family='sans-serif' "
      "font-size='11'>\n<rect width='100%' height='100%' fill='white'/>\n",
      kWidth, kHeight);
  for (int d = kTimeDecadeLow; d <= kTimeDecadeHigh; ++d) {
    double x = x_of(std::pow(10.0, d));
    s += fmt::format(
        "<line x1='{0:.1f}' x2='{0:.1f}' y1='{1}' y2='{2}' stroke='#ddd'/>"
        "<text x='{0:.1f}' y='{3}' text-anchor='middle'>1e{4}</text>\n",
        x, kTop, kHeight - kBottom, kHeight - kBottom + 15, d);
  }
  for (int d = kErrorDecadeLow; d <= kErrorDecadeHigh; d += 2) {
    double y = y_of(std::pow(10.0, d));
    s += fmt::format(
        "<line x1='{0}' x2='{1}' y1='{2:.1f}' y2='{2:.1f}' stroke='#ddd'/>"
        "<text x='{3}' y='{4:.1f}' text-anchor='end'>1e{5}</text>\n",
        kLeft, kWidth - kRight, y, kLeft - 5, y + 4, d);
  }
  s += fmt::format(
      "<text x='{}' y='{}' text-anchor='middle'>nanoseconds per intersection "
      "(random set)</text>\n",
      (kLeft + kWidth - kRight) / 2, kHeight - 12);
  s += fmt::format(
      "<text transform='translate(16 {}) rotate(-90)' text-anchor='middle'>largest "
      "relative error in t, hard set (wrong decision = 1; exact at the floor)</text>\n",
      (kTop + kHeight - kBottom) / 2);
  for (const auto& row : r.rows) {
    double e = row.hard.wrong_decisions > 0 ? 1.0 : row.hard.max_relative;
    if (row.hard.judged == 0) e = row.random.wrong_decisions > 0 ? 1.0 : row.random.max_relative;
    s += marker(row.primitive, x_of(row.ns_random), y_of(e), color(row.level));
    s +=
        fmt::format("<title>{} {}</title>\n", xml_escape(row.level), primitive_name(row.primitive));
  }
  double lx = kWidth - kRight + 15, ly = kTop + 10;
  for (const auto& name : names) {
    s += fmt::format(
        "<rect x='{}' y='{}' width='10' height='10' fill='{}'/><text x='{}' y='{}'>{}</text>\n", lx,
        ly - 9, color(name), lx + 15, ly, xml_escape(name));
    ly += 16;
  }
  ly += 10;
  for (Primitive p : kAllPrimitives) {
    s += marker(p, lx + 5, ly - 4, "#444");
    s += fmt::format("<text x='{}' y='{}'>{}</text>\n", lx + 15, ly, primitive_name(p));
    ly += 16;
  }
  s += "</svg>\n";
  return s;
}

}  // namespace raygrade
