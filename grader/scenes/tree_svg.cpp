// SVG drawing of ray trees: a layered tree, the eye on top, one row per ray generation; shadow
// rays are dashed leaves, green when the light is reached and red when it is blocked.
#include "core/escape.h"
#include "derivation/number_format.h"
#include "scenes/tree_draw.h"
#include "scenes/tree_json.h"

namespace raygrade {
namespace {

constexpr double kColumn = 170;  // px per leaf
constexpr double kRow = 100;     // px per generation
constexpr double kRadius = 18;   // of a hit node's circle
constexpr double kMargin = 20;

struct Placed {
  double x = 0, y = 0;
};

class Layout {
 public:
  explicit Layout(const RayTree& tree) : tree_(tree) {
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
  static double x_of(double leaf) { return kMargin + (leaf + 0.5) * kColumn; }
  static double y_of(int depth) { return kMargin + 30 + depth * kRow; }

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
  std::vector<Placed> nodes_;
  std::vector<std::vector<Placed>> shadows_;
  double next_leaf_ = 0;
};

std::string text_at(double x, double y, std::string_view s, const char* extra = "") {
  return fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\"{}>{}</text>\n", x, y,
                     extra, xml_escape(s));
}

std::string line(const Placed& a, const Placed& b, const char* style) {
  return fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" {}/>\n", a.x,
                     a.y, b.x, b.y, style);
}

}  // namespace

std::string tree_svg(const RayTree& tree, const Scene& scene) {
  Layout layout(tree);
  double width = 2 * kMargin + layout.leaves() * kColumn;
  double height = 2 * kMargin + 60 + layout.depth() * kRow;
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"ray-tree\" width=\"{0:.0f}\" "
      "height=\"{1:.0f}\" viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" "
      "font-size=\"12\" role=\"img\">\n<title>Ray tree</title>\n",
      width, height);
  Placed eye{layout.node(0).x, kMargin + 10};
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
      out += text_at((from.x + to.x) / 2 - 8, (from.y + to.y) / 2, letter,
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
    if (!n.hit) {
      out += fmt::format(
          "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"6\" fill=\"#fff\" stroke=\"#999\"/>\n", p.x,
          p.y);
      out += text_at(p.x, p.y + 22, "miss", " fill=\"#666\"");
      continue;
    }
    bool shadowed = in_shadow(n);
    out +=
        fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{}\" fill=\"{}\" stroke=\"#333\"/>\n",
                    p.x, p.y, kRadius, shadowed ? "#ddd" : "#ffd");
    out += text_at(p.x, p.y + 4, n.label, " font-weight=\"bold\"");
    out += text_at(p.x, p.y + kRadius + 14,
                   fmt::format("{}, t = {}", scene.objects[n.object].name, format_number(n.t)));
    if (n.shaded) {
      out += text_at(p.x, p.y + kRadius + 28, fmt::format("{}", fmt::join(node_terms(n), " + ")),
                     " fill=\"#555\"");
    }
    for (std::size_t k = 0; k < n.lights.size(); ++k) {
      const ShadowCheck& s = n.lights[k];
      const Placed& q = layout.shadow(n.index, k);
      const char* color = s.reaches() ? "#080" : "#c00";
      out += fmt::format(
          "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.0f}\" height=\"22\" fill=\"#fff\" "
          "stroke=\"{}\" stroke-dasharray=\"5,4\"/>\n",
          q.x - kColumn / 2 + 8, q.y - 11, kColumn - 16, color);
      out += text_at(q.x, q.y + 4, shadow_caption(scene, s),
                     fmt::format(" fill=\"{}\"", color).c_str());
    }
  }
  return out + "</svg>\n";
}

}  // namespace raygrade
