// Text and DOT drawings of ray trees (SVG: tree_svg.cpp).
#include "scenes/tree_draw.h"

#include "derivation/number_format.h"
#include "scenes/tree_json.h"

namespace raygrade {

std::string node_caption(const RayTree& tree, const Scene& scene, const TreeNode& node) {
  if (!node.hit) return "miss";
  std::string s = fmt::format("{}, t = {}", scene.objects[node.object].name, format_number(node.t));
  if (node.inside) s += ", from inside";
  if (node.shaded) s += fmt::format(" [{}]", fmt::join(node_terms(node), ", "));
  if (tree.ask == Ask::kIntensity) s += fmt::format(" I = {}", format_number(node.intensity));
  return s;
}

std::string shadow_caption(const Scene& scene, const ShadowCheck& s) {
  std::vector<std::string> by;
  for (int b : s.blockers) by.push_back(scene.objects[b].name);
  switch (s.status) {
    case LightStatus::kVisible: return fmt::format("{}: visible", s.light_name);
    case LightStatus::kBehind: return fmt::format("{}: behind the surface", s.light_name);
    case LightStatus::kBlocked:
      return fmt::format("{}: blocked by {}", s.light_name, fmt::join(by, ", "));
    case LightStatus::kTransmitted:
      return fmt::format("{}: through {} ({})", s.light_name, fmt::join(by, ", "),
                         format_number(s.transmission));
  }
  return "";
}

namespace {

const char* edge_letter(RayKind k) {
  switch (k) {
    case RayKind::kReflection: return "R";
    case RayKind::kRefraction: return "T";
    case RayKind::kShadow: return "S";
    case RayKind::kPrimary: break;
  }
  return "primary";
}

void text_node(const RayTree& tree, const Scene& scene, int index, const std::string& prefix,
               bool last, std::string& out) {
  const TreeNode& n = tree.nodes[index];
  out += prefix + (last ? "└─ " : "├─ ");
  out += fmt::format("{} {} → {}\n", n.hit ? n.label : "·", edge_letter(n.kind),
                     node_caption(tree, scene, n));
  std::string inner = prefix + (last ? "   " : "│  ");
  std::vector<int> kids = tree.children(index);
  std::size_t total = n.lights.size() + kids.size();
  std::size_t k = 0;
  for (const auto& s : n.lights) {
    bool end = ++k == total;
    out += inner + (end ? "└─ " : "├─ ") + "S → " + shadow_caption(scene, s) + "\n";
  }
  for (int c : kids) text_node(tree, scene, c, inner, ++k == total, out);
}

// A DOT string literal.
std::string dot_quote(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string tree_text(const RayTree& tree, const Scene& scene) {
  std::string out = "  eye\n";
  text_node(tree, scene, 0, "  ", true, out);
  return out;
}

std::string tree_dot(const RayTree& tree, const Scene& scene) {
  std::string out = "digraph ray_tree {\n  node [fontname=\"Helvetica\"];\n";
  out += "  eye [shape=box, label=\"eye\"];\n";
  for (const auto& n : tree.nodes) {
    std::string id = fmt::format("n{}", n.index);
    std::string label = n.hit ? n.label + "\n" + node_caption(tree, scene, n) : "miss";
    out += fmt::format("  {} [shape={}, label={}];\n", id, n.hit ? "ellipse" : "point",
                       dot_quote(label));
    std::string from = n.parent < 0 ? "eye" : fmt::format("n{}", n.parent);
    out += fmt::format("  {} -> {} [label={}];\n", from, id, dot_quote(edge_letter(n.kind)));
    for (std::size_t k = 0; k < n.lights.size(); ++k) {
      const ShadowCheck& s = n.lights[k];
      std::string sid = fmt::format("s{}_{}", n.index, k);
      const char* color = s.reaches() ? "darkgreen" : "red";
      out += fmt::format("  {} [shape=box, style=dashed, color={}, label={}];\n", sid, color,
                         dot_quote(shadow_caption(scene, s)));
      out += fmt::format("  {} -> {} [style=dashed, color={}, label=\"S\"];\n", id, sid, color);
    }
  }
  return out + "}\n";
}

}  // namespace raygrade
