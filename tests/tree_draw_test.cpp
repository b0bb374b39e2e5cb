// Drawings of ray trees: DOT and SVG carry every node, shadow ray and edge, with names escaped.
#include "scenes/tree_draw.h"

#include <gtest/gtest.h>

#include "kinds/ray_tree.h"
#include "test_util.h"

namespace raygrade {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

// A mirror floor under a ball, seen from above: the primary ray hits the floor at the origin
// and reflects straight up into the ball; the light at (5, 1, 0) is visible from both points.
Problem mirror_problem(const std::string& ball_name) {
  return testing::problem(R"({"id": "d", "kind": "ray-tree",
    "ray": {"origin": [0, 10, 0], "direction": [0, -1, 0]},
    "scene": {"objects": [
      {"name": "floor", "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0],
       "material": {"reflectivity": 0.5}},
      {"name": ")" + ball_name +
                          R"(", "type": "sphere", "center": [0, 30, 0], "radius": 1}],
      "lights": [{"name": "lamp", "position": [5, 1, 0]}]}})");
}

TEST(TreeDraw, DotHasEveryNodeAndEdge) {
  Problem p = mirror_problem("ball");
  const auto& task = dynamic_cast<const RayTreeTask&>(*p.task);
  std::string dot = tree_dot(task.tree(), task.scene());
  EXPECT_EQ(dot.rfind("digraph ray_tree {", 0), 0u);
  EXPECT_NE(dot.find("eye -> n0"), std::string::npos);
  EXPECT_NE(dot.find("n0 -> n1 [label=\"R\"]"), std::string::npos);
  EXPECT_EQ(count(dot, "style=dashed, color="), 4u);  // two shadow boxes and their edges
  // The reflected ray goes up past the primary ray's origin and hits the ball at y = 29.
  EXPECT_NE(dot.find("I2\\nball, t = 30"), std::string::npos);
  EXPECT_EQ(dot.back(), '\n');
}

TEST(TreeDraw, DotEscapesQuotes) {
  Problem p = mirror_problem(R"(big \"ball\")");
  const auto& task = dynamic_cast<const RayTreeTask&>(*p.task);
  std::string dot = tree_dot(task.tree(), task.scene());
  EXPECT_NE(dot.find(R"(big \"ball\")"), std::string::npos);
}

TEST(TreeDraw, SvgDrawsTheNodesAndEscapesNames) {
  Problem p = mirror_problem("<b>&ball");
  const auto& task = dynamic_cast<const RayTreeTask&>(*p.task);
  std::string svg = tree_svg(task.tree(), task.scene());
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(count(svg, "<circle"), 2u);
  EXPECT_EQ(count(svg, "stroke-dasharray"), 4u);  // two shadow rays: a line and a box each
  EXPECT_NE(svg.find("&lt;b&gt;&amp;ball"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_NE(svg.find(">I2</text>"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(TreeDraw, TextShowsTheBranches) {
  Problem p = mirror_problem("ball");
  const auto& task = dynamic_cast<const RayTreeTask&>(*p.task);
  std::string text = tree_text(task.tree(), task.scene());
  EXPECT_NE(text.find("└─ I1 primary → floor, t = 11"), std::string::npos);
  EXPECT_NE(text.find("S → lamp: visible"), std::string::npos);
  EXPECT_NE(text.find("I2 R → ball"), std::string::npos);
}

// The worked solution carries the drawing as a figure on its first part.
TEST(TreeDraw, WorkedSolutionHasTheFigure) {
  Problem p = mirror_problem("ball");
  auto parts = p.task->derive("");
  ASSERT_FALSE(parts.empty());
  ASSERT_EQ(parts[0].figures.size(), 1u);
  EXPECT_NE(parts[0].figures[0].svg.find("<svg"), std::string::npos);
  EXPECT_NE(parts[0].figures[0].dot.find("digraph"), std::string::npos);
  EXPECT_EQ(parts.size(), 4u);  // overview, I1, I2, answer
}

}  // namespace
}  // namespace raygrade
