// Drawing a Sketch as SVG: choosing the view, projecting, clipping lines to the frame.
#include "reports/svg_figure.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "core/escape.h"
#include "derivation/number_format.h"

namespace raygrade {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Directions shorter than this (they are unit or zero) count as zero: a candidate up
// direction parallel to the main one, a cylinder seen along its axis.
constexpr double kTinyDirection = 1e-9;
// Rims of cylinders are drawn as polygons with this many sides.
constexpr int kRimSides = 48;
// The drawing's size in pixels, and the blank border around the figure, as a fraction.
constexpr double kMaxWidth = 560, kMaxHeight = 380, kMargin = 0.12;
// Neither side of the frame is shorter than this fraction of the other, so that a figure
// along one line still has room for its labels.
constexpr double kMinAspect = 0.45;
// A flat object whose unit normal is this close to the page (|n·m| below it, about 15° from
// edge-on) gets a second drawing, seen face-on.
constexpr double kEdgeOn = 0.26;

struct P2 {
  double x = 0, y = 0;
};

struct View {
  Vec3d ref, u, v, m;  // origin of the view, right, up, and toward the viewer
  P2 at(const Vec3d& p) const { return {dot(p - ref, u), dot(p - ref, v)}; }
};

// Two unit vectors perpendicular to the unit `a`.
void basis(const Vec3d& a, Vec3d& e1, Vec3d& e2) {
  Vec3d helper = std::abs(a.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  e1 = normalized(cross(a, helper));
  e2 = cross(a, e1);
}

std::vector<Vec3d> rim(const Vec3d& center, const Vec3d& axis, double r) {
  Vec3d e1, e2;
  basis(axis, e1, e2);
  std::vector<Vec3d> out;
  for (int i = 0; i < kRimSides; ++i) {
    double a = 2 * kPi * i / kRimSides;
    out.push_back(center + r * std::cos(a) * e1 + r * std::sin(a) * e2);
  }
  return out;
}

// The points that decide the view and the frame (lines and planes have no extent).
void samples(const SketchItem& item, std::vector<Vec3d>& pts,
             std::vector<std::pair<Vec3d, double>>& balls) {
  using T = SketchItem::Type;
  switch (item.type) {
    case T::kPath:
    case T::kArrow:
    case T::kPoint:
    case T::kText: pts.insert(pts.end(), item.points.begin(), item.points.end()); break;
    case T::kCircle: balls.emplace_back(item.points[0], item.radius); break;
    case T::kCylinder:
      if (item.height > 0) {
        for (const auto& p : rim(item.points[0], item.points[1], item.radius)) pts.push_back(p);
        Vec3d top = item.points[0] + item.height * item.points[1];
        for (const auto& p : rim(top, item.points[1], item.radius)) pts.push_back(p);
      } else {
        balls.emplace_back(item.points[0], item.radius);
      }
      break;
    case T::kLine:
    case T::kPlane: pts.push_back(item.points[0]); break;
  }
}

std::string direction_name(const Vec3d& v) {
  static const char* names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    Vec3d e{};
    e[i] = 1;
    if (length(v - e) < 1e-9) return std::string("+") + names[i];
    if (length(v + e) < 1e-9) return std::string("−") + names[i];
  }
  // A vector as the worked solutions print points: (0.333, −0.667, 0.667), real minus signs.
  std::string out;
  for (char c : format_vector(v, NumberFormat{3, -1})) {
    out += c == '-' ? std::string("−") : std::string(1, c);
  }
  return out;
}

// A direction's name with its value: "the surface normal (+y)", "the ray's direction
// (0.707, 0.707, 0)": a vector brings its own parentheses.
std::string named_direction(const std::string& name, const Vec3d& v) {
  std::string value = direction_name(v);
  if (name.empty()) return value;
  return value.front() == '(' ? name + " " + value : name + " (" + value + ")";
}

View choose_view(const Sketch& f, const std::vector<Vec3d>& pts,
                 const std::vector<std::pair<Vec3d, double>>& balls) {
  View view;
  view.u = length(f.across) > 0 ? normalized(f.across) : Vec3d{1, 0, 0};
  for (const auto& item : f.items) {
    if (item.type == SketchItem::Type::kArrow) {
      view.ref = item.points[0];
      break;
    }
  }
  // Up: the figure's own up direction when it names one (a surface's normal); otherwise the
  // direction across the main one along which the figure is widest; among equals, the first
  // of +z, +y, +x and the direction toward the figure's middle.
  Vec3d own_up = f.up - dot(f.up, view.u) * view.u;
  if (length(own_up) > kTinyDirection * std::max(1.0, length(f.up))) {
    view.v = normalized(own_up);
    view.m = cross(view.u, view.v);
    return view;
  }
  Vec3d middle{};
  for (const auto& p : pts) middle = middle + p;
  for (const auto& b : balls) middle = middle + b.first;
  if (!pts.empty() || !balls.empty())
    middle = middle / static_cast<double>(pts.size() + balls.size());
  std::vector<Vec3d> candidates = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, middle - view.ref};
  double best = -1;
  for (const auto& c : candidates) {
    Vec3d w = c - dot(c, view.u) * view.u;
    if (length(w) < kTinyDirection * std::max(1.0, length(c))) continue;
    w = normalized(w);
    double lo = kInf, hi = -kInf;
    for (const auto& p : pts) {
      lo = std::min(lo, dot(p, w));
      hi = std::max(hi, dot(p, w));
    }
    for (const auto& [center, r] : balls) {
      lo = std::min(lo, dot(center, w) - r);
      hi = std::max(hi, dot(center, w) + r);
    }
    double spread = hi - lo;
    if (spread > best * (1 + 1e-9) + 1e-12) {
      best = spread;
      view.v = w;
    }
  }
  if (best < 0) basis(view.u, view.v, view.m);
  view.m = cross(view.u, view.v);
  return view;
}

// Clips the line p + s·d to the rectangle; false when it misses it.
bool clip_line(P2 p, P2 d, P2 lo, P2 hi, P2& a, P2& b) {
  double s0 = -kInf, s1 = kInf;
  auto side = [&](double pc, double dc, double l, double h) {
    if (dc == 0) return pc >= l && pc <= h;
    double x = (l - pc) / dc, y = (h - pc) / dc;
    if (x > y) std::swap(x, y);
    s0 = std::max(s0, x);
    s1 = std::min(s1, y);
    return s0 <= s1;
  };
  if (!side(p.x, d.x, lo.x, hi.x) || !side(p.y, d.y, lo.y, hi.y)) return false;
  a = {p.x + s0 * d.x, p.y + s0 * d.y};
  b = {p.x + s1 * d.x, p.y + s1 * d.y};
  return true;
}

const char* ink_class(Ink ink) {
  switch (ink) {
    case Ink::kObject: return "object";
    case Ink::kGuide: return "guide";
    case Ink::kRay: return "ray";
    case Ink::kHit: return "hit";
    case Ink::kMiss: return "miss";
    case Ink::kPoint: return "point";
  }
  return "object";
}

class Sheet {
 public:
  Sheet(P2 lo, P2 hi, double scale) : lo_(lo), hi_(hi), scale_(scale) {}
  double width() const { return (hi_.x - lo_.x) * scale_; }
  double height() const { return (hi_.y - lo_.y) * scale_; }
  P2 lo() const { return lo_; }
  P2 hi() const { return hi_; }
  P2 px(P2 p) const { return {(p.x - lo_.x) * scale_, (hi_.y - p.y) * scale_}; }
  double scale() const { return scale_; }

  void polyline(const std::vector<P2>& pts, bool closed, const char* cls) {
    std::string d;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      P2 q = px(pts[i]);
      d += fmt::format("{}{:.1f} {:.1f}", i ? " L" : "M", q.x, q.y);
    }
    if (closed) d += " Z";
    body_ += fmt::format("<path class=\"{}\" d=\"{}\"/>\n", cls, d);
  }
  void circle(P2 c, double r, const char* cls) {
    P2 q = px(c);
    body_ += fmt::format("<circle class=\"{}\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{:.1f}\"/>\n", cls,
                         q.x, q.y, r * scale_);
  }
  void arrow(P2 a, P2 b, const char* cls) {
    polyline({a, b}, false, cls);
    P2 qa = px(a), qb = px(b);
    double dx = qb.x - qa.x, dy = qb.y - qa.y, len = std::hypot(dx, dy);
    if (len == 0) return;
    dx /= len;
    dy /= len;
    const double size = 10, half = 4.5;
    P2 l{qb.x - size * dx - half * dy, qb.y - size * dy + half * dx};
    P2 r{qb.x - size * dx + half * dy, qb.y - size * dy - half * dx};
    body_ += fmt::format(
        "<path class=\"{}-head\" d=\"M{:.1f} {:.1f} L{:.1f} {:.1f} L{:.1f} {:.1f} Z\"/>\n", cls,
        qb.x, qb.y, l.x, l.y, r.x, r.y);
  }
  void marker(P2 c, const char* cls) {
    P2 q = px(c);
    body_ += fmt::format("<circle class=\"mark-{}\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\"/>\n", cls,
                         q.x, q.y);
  }
  // A label near a point (in pixels), moved down below every earlier label it would overlap.
  // Its box is measured generously: 7 px per byte of its UTF-8 text (12 px sans-serif runs
  // 3 to 8 px a character, and a character not in ASCII takes two bytes or more), and kRow
  // high (Chromium's box of a 12 px line is 14.4 px). Each move puts the label's row below
  // the row of the label it clashed with, and rows only move down, so the loop ends after at
  // most one move per earlier label, with no two boxes overlapping.
  void label(P2 at_px, const std::string& text, const char* cls) {
    if (text.empty()) return;
    constexpr double kRow = 15;
    double w = 7.0 * static_cast<double>(text.size());
    double x = std::min(at_px.x + 7, std::max(2.0, width() - w - 2));
    double y = std::max(kRow, at_px.y - 7);
    for (bool clash = true; clash;) {
      clash = false;
      for (const auto& [bx, by, bw] : placed_) {
        if (x < bx + bw && bx < x + w && y > by - kRow && y < by + kRow) {
          y = by + kRow;
          clash = true;
        }
      }
    }
    placed_.push_back({x, y, w});
    bottom_ = std::max(bottom_, y + 4);  // the baseline, and the descenders below it
    labels_ += fmt::format("<text class=\"label-{}\" x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", cls, x,
                           y, html_escape(text));
  }
  // How far down the labels reach, in pixels (they may reach below the drawing).
  double labels_bottom() const { return bottom_; }
  std::string body() const { return body_ + labels_; }

 private:
  P2 lo_, hi_;
  double scale_;
  std::string body_, labels_;
  std::vector<std::array<double, 3>> placed_;
  double bottom_ = 0;
};

constexpr const char* kFigureStyle =
    "<style>"
    ".object{fill:#dce9f7;fill-opacity:.55;stroke:#2d5f8b;stroke-width:1.6}"
    ".guide{fill:none;stroke:#8a8a8a;stroke-width:1.1;stroke-dasharray:5 4}"
    ".ray{fill:none;stroke:#b83227;stroke-width:2}.ray-head{fill:#b83227}"
    ".object-head{fill:#2d5f8b}.guide-head{fill:#8a8a8a}"
    ".point{fill:none;stroke:#222;stroke-width:1.6}.point-head{fill:#222}"
    ".miss{fill:none;stroke:#777;stroke-width:1.2;stroke-dasharray:2 3}.miss-head{fill:#777}"
    ".mark-hit{fill:#b83227;stroke:#fff;stroke-width:1.2}"
    ".mark-point{fill:#222}.mark-miss{fill:#fff;stroke:#777;stroke-width:1.2}"
    ".mark-object,.mark-guide,.mark-ray{fill:#555}"
    "text{font:12px sans-serif;fill:#222}.label-hit{fill:#8e241c;font-weight:bold}"
    ".label-guide{fill:#666}.label-object{fill:#2d5f8b}.label-miss{fill:#777}"
    "</style>";

}  // namespace

// One drawing of the sketch in `view`, at most max_w by max_h pixels (labels may reach lower).
struct Panel {
  std::string body;
  int width = 0, height = 0;
};

Panel draw_panel(const Sketch& f, const View& view, const std::vector<Vec3d>& pts,
                 const std::vector<std::pair<Vec3d, double>>& balls, double max_w, double max_h) {
  // The frame: every sample, with a margin, not too thin either way.
  P2 lo{kInf, kInf}, hi{-kInf, -kInf};
  auto grow = [&](P2 p, double r) {
    lo = {std::min(lo.x, p.x - r), std::min(lo.y, p.y - r)};
    hi = {std::max(hi.x, p.x + r), std::max(hi.y, p.y + r)};
  };
  grow(view.at(view.ref), 0);
  for (const auto& p : pts) grow(view.at(p), 0);
  for (const auto& [c, r] : balls) grow(view.at(c), r);
  double w = std::max(hi.x - lo.x, 1e-9), h = std::max(hi.y - lo.y, 1e-9);
  if (h < kMinAspect * w) {
    double grow_by = (kMinAspect * w - h) / 2;
    lo.y -= grow_by;
    hi.y += grow_by;
  } else if (w < kMinAspect * h) {
    double grow_by = (kMinAspect * h - w) / 2;
    lo.x -= grow_by;
    hi.x += grow_by;
  }
  w = hi.x - lo.x;
  h = hi.y - lo.y;
  lo = {lo.x - kMargin * w, lo.y - kMargin * h};
  hi = {hi.x + kMargin * w, hi.y + kMargin * h};
  double scale = std::min(max_w / (hi.x - lo.x), max_h / (hi.y - lo.y));
  Sheet sheet(lo, hi, scale);

  auto project = [&](const std::vector<Vec3d>& v) {
    std::vector<P2> out;
    out.reserve(v.size());
    for (const auto& p : v) out.push_back(view.at(p));
    return out;
  };
  auto draw_line = [&](P2 p, P2 d, const char* cls) -> std::optional<P2> {
    P2 a, b;
    if (!clip_line(p, d, sheet.lo(), sheet.hi(), a, b)) return std::nullopt;
    sheet.polyline({a, b}, false, cls);
    return a.y > b.y ? a : b;
  };

  // Objects and guides first, then the ray, then the points, so that marks stay on top.
  for (int pass = 0; pass < 3; ++pass) {
    for (const auto& item : f.items) {
      bool on_top = item.type == SketchItem::Type::kPoint || item.type == SketchItem::Type::kText;
      int layer = on_top ? 2 : item.ink == Ink::kRay ? 1 : 0;
      if (layer != pass) continue;
      const char* cls = ink_class(item.ink);
      using T = SketchItem::Type;
      switch (item.type) {
        case T::kPath: {
          auto p2 = project(item.points);
          sheet.polyline(p2, item.closed, cls);
          if (!p2.empty()) sheet.label(sheet.px(p2[0]), item.label, cls);
          break;
        }
        case T::kCircle: {
          P2 c = view.at(item.points[0]);
          sheet.circle(c, item.radius, cls);
          sheet.label(sheet.px({c.x, c.y + item.radius}), item.label, cls);
          break;
        }
        case T::kLine: {
          P2 d{dot(item.points[1], view.u), dot(item.points[1], view.v)};
          if (std::hypot(d.x, d.y) < kTinyDirection) break;
          if (auto top = draw_line(view.at(item.points[0]), d, cls)) {
            sheet.label(sheet.px(*top), item.label, cls);
          }
          break;
        }
        case T::kPlane: {
          const Vec3d& n = item.points[1];
          P2 n2{dot(n, view.u), dot(n, view.v)};
          double nn = n2.x * n2.x + n2.y * n2.y;
          if (nn < kTinyDirection * length_squared(n)) break;  // parallel to the page
          double k = dot(n, item.points[0] - view.ref) / nn;
          if (auto top = draw_line({k * n2.x, k * n2.y}, {-n2.y, n2.x}, cls)) {
            sheet.label(sheet.px(*top), item.label, cls);
          }
          break;
        }
        case T::kCylinder: {
          const Vec3d& b = item.points[0];
          const Vec3d& a = item.points[1];
          Vec3d s = cross(a, view.m);
          P2 base = view.at(b);
          if (length(s) < kTinyDirection) {
            sheet.circle(base, item.radius, cls);  // seen along its axis
            sheet.label(sheet.px(base), item.label, cls);
            break;
          }
          s = normalized(s);
          if (item.height > 0) {
            Vec3d top = b + item.height * a;
            sheet.polyline(project(rim(b, a, item.radius)), true, cls);
            sheet.polyline(project(rim(top, a, item.radius)), true, cls);
            for (double side : {-1.0, 1.0}) {
              sheet.polyline(project({b + side * item.radius * s, top + side * item.radius * s}),
                             false, cls);
            }
          } else {
            P2 d{dot(a, view.u), dot(a, view.v)};
            draw_line(view.at(b), d, "guide");
            for (double side : {-1.0, 1.0}) draw_line(view.at(b + side * item.radius * s), d, cls);
          }
          sheet.label(sheet.px(base), item.label, cls);
          break;
        }
        case T::kArrow:
          sheet.arrow(view.at(item.points[0]), view.at(item.points[1]), cls);
          sheet.label(sheet.px(view.at(item.points[1])), item.label, cls);
          break;
        case T::kPoint: {
          P2 c = view.at(item.points[0]);
          sheet.marker(c, cls);
          sheet.label(sheet.px(c), item.label, cls);
          break;
        }
        case T::kText: sheet.label(sheet.px(view.at(item.points[0])), item.label, cls); break;
      }
    }
  }

  Panel panel;
  panel.width = static_cast<int>(std::ceil(sheet.width()));
  panel.height = static_cast<int>(std::ceil(std::max(sheet.height(), sheet.labels_bottom())));
  panel.body = sheet.body();
  return panel;
}

// The first flat object of the sketch (a closed path of three points or more: a triangle, a
// polygon, a disk's rim) that `view` shows nearly edge-on, where a view along its normal shows
// what the side view hides. Its unit normal, or nothing.
std::optional<Vec3d> edge_on_flat(const Sketch& f, const View& view, std::string& label) {
  // A rim joined by lines to other points (a cone's base, its sides drawn to the apex) belongs
  // to a solid whose other lines show its extent: it is not a flat object alone.
  auto joined = [&](const SketchItem& rim) {
    for (const auto& other : f.items) {
      if (other.type != SketchItem::Type::kPath || other.closed || other.ink != Ink::kObject)
        continue;
      for (const Vec3d& p : other.points) {
        for (const Vec3d& q : rim.points) {
          if (p == q) return true;
        }
      }
    }
    return false;
  };
  for (const auto& item : f.items) {
    if (item.type != SketchItem::Type::kPath || !item.closed || item.ink != Ink::kObject ||
        item.points.size() < 3)
      continue;
    Vec3d n{};
    for (std::size_t i = 0; i < item.points.size(); ++i) {  // Newell's method
      const Vec3d& a = item.points[i];
      const Vec3d& b = item.points[(i + 1) % item.points.size()];
      n = n + cross(a, b);
    }
    if (!(length(n) > 0)) continue;
    n = normalized(n);
    // Within about 15° of edge-on: the drawing shows a quarter of the width or less.
    if (std::abs(dot(n, view.m)) < kEdgeOn && !joined(item)) {
      label = item.label;
      return n;
    }
  }
  return std::nullopt;
}

// The view that looks along the unit `normal`: the side view's right direction kept as far as
// it lies in the object's plane, or an axis when it does not.
View face_view(const View& side, const Vec3d& normal) {
  View view;
  view.ref = side.ref;
  view.m = dot(normal, side.m) < 0 ? -normal : normal;
  Vec3d u = side.u - dot(side.u, view.m) * view.m;
  // Looking along the ray: the first axis (x, then y, then z) that lies well in the plane.
  for (const Vec3d& axis : {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}}) {
    if (length(u) >= 1e-6) break;
    Vec3d in_plane = axis - dot(axis, view.m) * view.m;
    if (length(in_plane) > 0.5) u = in_plane;
  }
  view.u = normalized(u);
  view.v = cross(view.m, view.u);
  return view;
}

SvgFigure render_svg(const Sketch& f, const std::string& title) {
  std::vector<Vec3d> pts;
  std::vector<std::pair<Vec3d, double>> balls;
  for (const auto& item : f.items) samples(item, pts, balls);
  View view = choose_view(f, pts, balls);
  std::string flat_label;
  std::optional<Vec3d> flat = edge_on_flat(f, view, flat_label);
  std::string across = named_direction(f.across_name, view.u);
  bool own_up =
      !f.up_name.empty() && length(f.up) > 0 && length(view.v - normalized(f.up)) < kTinyDirection;
  std::string up = named_direction(own_up ? f.up_name : "", view.v);
  SvgFigure out;
  std::string side_caption = fmt::format(
      "view, drawn to scale: {} points right, {} points up; the page is the plane that "
      "holds both",
      across, up);
  if (!flat) {
    Panel panel = draw_panel(f, view, pts, balls, kMaxWidth, kMaxHeight);
    out.svg = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"sketch\" width=\"{0}\" "
        "height=\"{1}\" viewBox=\"0 0 {0} {1}\" role=\"img\" aria-label=\"{2}\">\n<title>{2}"
        "</title>\n{3}\n<rect x=\"0.5\" y=\"0.5\" width=\"{4}\" height=\"{5}\" fill=\"none\" "
        "stroke=\"#ddd\"/>\n{6}</svg>",
        panel.width, panel.height, html_escape(title), kFigureStyle, panel.width - 1,
        panel.height - 1, panel.body);
    out.caption = "Side " + side_caption + ".";
    return out;
  }
  // A flat object seen edge-on is a line: a second view, along its normal, shows its shape
  // and where the ray meets it.
  View face = face_view(view, *flat);
  Panel left = draw_panel(f, view, pts, balls, kMaxWidth * 0.6, kMaxHeight);
  Panel right = draw_panel(f, face, pts, balls, kMaxWidth * 0.6, kMaxHeight);
  constexpr int kGap = 12;
  int width = left.width + kGap + right.width;
  int height = std::max(left.height, right.height);
  out.svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"sketch\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" role=\"img\" aria-label=\"{2}\">\n<title>{2}</title>\n{3}\n"
      "<g class=\"side-view\">\n<rect x=\"0.5\" y=\"0.5\" width=\"{4}\" height=\"{5}\" "
      "fill=\"none\" stroke=\"#ddd\"/>\n{6}</g>\n<g class=\"face-view\" "
      "transform=\"translate({7} 0)\">\n<rect x=\"0.5\" y=\"0.5\" width=\"{8}\" "
      "height=\"{9}\" fill=\"none\" stroke=\"#ddd\"/>\n{10}</g>\n</svg>",
      width, height, html_escape(title), kFigureStyle, left.width - 1, left.height - 1, left.body,
      left.width + kGap, right.width - 1, right.height - 1, right.body);
  std::string what = flat_label.empty() ? std::string("the flat object") : "the " + flat_label;
  // A label may already say "triangle ABC": keep it as written.
  if (!flat_label.empty() && flat_label.rfind("the ", 0) == 0) what = flat_label;
  out.caption = fmt::format(
      "Left: side {}; {} is seen edge-on there. Right: {} seen face-on, looking along its normal "
      "{}: {} points right, {} points up.",
      side_caption, what, what, direction_name(face.m), direction_name(face.u),
      direction_name(face.v));
  return out;
}

}  // namespace raygrade
