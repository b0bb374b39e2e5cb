// SVG drawing of ray trees: a layered tree, the eye on top, one row per ray generation; shadow
// rays are dashed leaves, green when the light is reached and red when it is blocked.
#include "core/escape.h"
#include "derivation/number_format.h"
#include "scenes/colour.h"
#include "scenes/tree_draw.h"
#include "scenes/tree_json.h"

namespace raygrade {
namespace {

constexpr double kMinColumn = 170;  // px per leaf, at the least
// Text is 12 px sans-serif: 7 px per byte of UTF-8 is more than any of its characters takes
// (Chromium lays out 6.3 px per character on average), and 20 px a line more than its box
// (14.4 px high in DejaVu Sans, 17.9 px in the tallest sans-serif fonts Chromium was seen to
// pick), so that no two texts of the drawing overlap.
constexpr double kCharWidth = 7;
constexpr double kLine = 20;
constexpr double kRow = 110;    // px per generation
constexpr double kRadius = 18;  // of a hit node's circle
constexpr double kTreeMargin = 20;

struct Placed {
  double x = 0, y = 0;
};

class Layout {
 public:
  Layout(const RayTree& tree, double column) : tree_(tree), column_(column) {
    nodes_.resize(tree.nodes.size());
    shadows_.resize(tree.nodes.size());
    place(0);
  }
  double leaves() const { return next_leaf_; }
  const Placed& node(int i) const { return nodes_[i]; }
  const Placed& shadow(int i, std::size_t k) const { return shadows_[i][k]; }
  int depth() const {
    int d = 1;
    for (const auto& n : tree_.nodes) d = std::max(d, n.depth + (n.lights.empty() ? 0 : 1));
    return d;
  }

 private:
  double x_of(double leaf) const { return kTreeMargin + (leaf + 0.5) * column_; }
  static double y_of(int depth) { return kTreeMargin + 30 + depth * kRow; }

  // Leaves left to right: the node's shadow rays, then its children; the node sits centred
  // above them.
  void place(int i) {
    const TreeNode& n = tree_.nodes[i];
    double first = next_leaf_;
    for (std::size_t k = 0; k < n.lights.size(); ++k) {
      shadows_[i].push_back({x_of(next_leaf_), y_of(n.depth + 1)});
      next_leaf_ += 1;
    }
    for (int c : tree_.children(i)) place(c);
    if (next_leaf_ == first) next_leaf_ += 1;
    double last = next_leaf_ - 1;
    nodes_[i] = {(x_of(first) + x_of(last)) / 2, y_of(n.depth)};
  }

  const RayTree& tree_;
  double column_;
  std::vector<Placed> nodes_;
  std::vector<std::vector<Placed>> shadows_;
  double next_leaf_ = 0;
};

std::string text_at(double x, double y, std::string_view s, const char* extra = "") {
  return fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\"{}>{}</text>\n", x, y,
                     extra, xml_escape(s));
}

std::string object_caption(const Scene& scene, const TreeNode& n) {
  return fmt::format("{}, t = {}", scene.objects[n.object].name, format_number(n.t));
}

std::string terms_caption(const TreeNode& n) {
  return fmt::format("{}", fmt::join(node_terms(n), " + "));
}

// A leaf's width: wide enough for the widest text centred on a node or a shadow ray.
double column_width(const RayTree& tree, const Scene& scene) {
  std::size_t widest = 0;
  for (const auto& n : tree.nodes) {
    if (!n.hit) continue;
    widest = std::max(widest, object_caption(scene, n).size());
    if (n.shaded) widest = std::max(widest, terms_caption(n).size());
    for (const auto& s : n.lights) widest = std::max(widest, shadow_caption(scene, s).size() + 2);
  }
  return std::max(kMinColumn, kCharWidth * static_cast<double>(widest) + 20);
}

std::string line(const Placed& a, const Placed& b, const char* style) {
  return fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" {}/>\n", a.x,
                     a.y, b.x, b.y, style);
}

}  // namespace

std::string tree_svg(const RayTree& tree, const Scene& scene, const std::vector<Vec3d>* colours) {
  double column = column_width(tree, scene);
  Layout layout(tree, column);
  double width = 2 * kTreeMargin + layout.leaves() * column;
  // Room below the deepest row for its two lines of text (kRadius + 2·kLine and descenders).
  double height = 2 * kTreeMargin + 80 + layout.depth() * kRow;
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"ray-tree\" width=\"{0:.0f}\" "
      "height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" "
      "font-size=\"12\" role=\"img\">\n<title>Ray tree</title>\n",
      width, height);
  Placed eye{layout.node(0).x, kTreeMargin + 10};
  out += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"40\" height=\"20\" fill=\"#eee\" "
      "stroke=\"#333\"/>\n",
      eye.x - 20, eye.y - 10);
  out += text_at(eye.x, eye.y + 4, "eye");
  // Edges first, so that nodes are drawn over them.
  for (const auto& n : tree.nodes) {
    Placed from = n.parent < 0 ? Placed{eye.x, eye.y + 10} : layout.node(n.parent);
    Placed to = layout.node(n.index);
    out += line(from, to, "stroke=\"#333\" stroke-width=\"1.5\"");
    const char* letter = n.kind == RayKind::kReflection   ? "R"
                         : n.kind == RayKind::kRefraction ? "T"
                                                          : "";
    if (*letter) {
      // Three quarters of the way down the edge: below the parent's two lines of text (its
      // object and t, its terms, down to kRadius + 2·kLine px under its centre), above the
      // child.
      double at = 0.75;
      out += text_at(from.x + at * (to.x - from.x) - 8, from.y + at * (to.y - from.y) + 4, letter,
                     " font-weight=\"bold\" fill=\"#036\"");
    }
    for (std::size_t k = 0; k < n.lights.size(); ++k) {
      out += line(to, layout.shadow(n.index, k),
                  n.lights[k].reaches() ? "stroke=\"#080\" stroke-dasharray=\"5,4\""
                                        : "stroke=\"#c00\" stroke-dasharray=\"5,4\"");
    }
  }
  for (const auto& n : tree.nodes) {
    const Placed& p = layout.node(n.index);
    if (colours && n.index < static_cast<int>(colours->size())) {
      // The point's colour (a miss: the background's) as a small square to its right.
      Vec3d c = (*colours)[static_cast<std::size_t>(n.index)];
      out += fmt::format(
          "<rect class=\"swatch\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"14\" height=\"14\" "
          "fill=\"{}\" stroke=\"#333\"><title>{}</title></rect>\n",
          p.x + kRadius + 4, p.y - 7, swatch_hex(c), colour_text(c));
    }
    if (!n.hit) {
      out += fmt::format(
          "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"6\" fill=\"#fff\" stroke=\"#999\"/>\n", p.x,
          p.y);
      out += text_at(p.x, p.y + 22, "miss", " fill=\"#666\"");
      continue;
    }
    bool shadowed = shadow_reading(tree, n).in_shadow;
    out +=
        fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{}\" fill=\"{}\" stroke=\"#333\"/>\n",
                    p.x, p.y, kRadius, shadowed ? "#ddd" : "#ffd");
    out += text_at(p.x, p.y + 4, n.label, " font-weight=\"bold\"");
    out += text_at(p.x, p.y + kRadius + kLine, object_caption(scene, n));
    if (n.shaded) {
      out += text_at(p.x, p.y + kRadius + 2 * kLine, terms_caption(n), " fill=\"#555\"");
    }
    for (std::size_t k = 0; k < n.lights.size(); ++k) {
      const ShadowCheck& s = n.lights[k];
      const Placed& q = layout.shadow(n.index, k);
      const char* color = s.reaches() ? "#080" : "#c00";
      out += fmt::format(
          "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.0f}\" height=\"22\" fill=\"#fff\" "
          "stroke=\"{}\" stroke-dasharray=\"5,4\"/>\n",
          q.x - column / 2 + 8, q.y - 11, column - 16, color);
      out += text_at(q.x, q.y + 4, shadow_caption(scene, s),
                     fmt::format(" fill=\"{}\"", color).c_str());
    }
  }
  return out + "</svg>\n";
}

}  // namespace raygrade
