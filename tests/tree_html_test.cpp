// Seed 001's ray tree in the rendered worked solutions: SVG in the HTML page, DOT in the JSON,
// the text drawing in the terminal format.
#include <gtest/gtest.h>

#include "problems/problem.h"
#include "reports/render.h"

namespace raygrade {
namespace {

const Problem& seed() {
  static const Bank bank = [] {
    std::vector<std::string> paths(1);
    paths[0] = fmt::format("{}/problems/seeds/seed001-ray-tree.json", RAYGRADE_SOURCE_DIR);
    return load_bank(paths);
  }();
  return bank.problems.at(0);
}

std::string render(Format f) {
  Solution s = make_solution(seed(), "", NumberFormat{});
  return render_document(f, {&s});
}

TEST(RayTreeSolution, HtmlEmbedsTheTreeAsSvg) {
  std::string html = render(Format::kHtml);
  std::size_t svg = html.find("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"ray-tree\"");
  ASSERT_NE(svg, std::string::npos);
  std::size_t end = html.find("</svg>", svg);
  ASSERT_NE(end, std::string::npos);
  std::string tree = html.substr(svg, end - svg);
  for (const char* label : {">I1<", ">I2<", ">I3<", ">I4<", ">I5<"}) {
    EXPECT_NE(tree.find(label), std::string::npos) << label;
  }
  // Two blocked shadow rays are drawn red and name their blocker.
  EXPECT_NE(tree.find("L: blocked by glass sphere"), std::string::npos);
}

TEST(RayTreeSolution, JsonCarriesTheDot) {
  std::string text = render(Format::kJson);
  EXPECT_NE(text.find("digraph ray_tree"), std::string::npos);
}

TEST(RayTreeSolution, TextDrawsTheTree) {
  std::string text = render(Format::kText);
  EXPECT_NE(text.find("├─ I2 R → mirror ceiling"), std::string::npos) << text.substr(0, 2000);
  EXPECT_NE(text.find("All three Phong terms (ambient, diffuse, specular): I1, I2, I3."),
            std::string::npos);
}

}  // namespace
}  // namespace raygrade
