// Colour: intensities and coefficients as [r, g, b], worked and graded channel by channel.
#include "scenes/colour.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "grading/grade.h"
#include "kinds/ray_tree.h"
#include "problems/problem.h"
#include "scenes/pattern.h"
#include "test_util.h"

namespace raygrade {
namespace {

// kTwoLightShade with colours: the ambient light [2, 2, 1], light A [1, 0.5, 0], k_d
// [0.5, 1, 1]. By hand, with L = (0.6, 0.8, 0), N·L = 0.8, R = V, R·V = 1:
//   ambient  0.1·[2, 2, 1]               = [0.2, 0.2, 0.1]
//   diffuse  [0.5, 1, 1] ⊙ [1, 0.5, 0]·0.8 = [0.4, 0.4, 0]
//   specular 0.3·[1, 0.5, 0]·1            = [0.3, 0.15, 0]
//   total                                 = [0.9, 0.75, 0.1]
constexpr const char* kColourShade = R"({"id": "c", "kind": "shade",
    "point": [0, 0, 0], "normal": [0, 1, 0], "eye": [-3, 4, 0], "ambient_light": [2, 2, 1],
    "material": {"ambient": 0.1, "diffuse": [0.5, 1, 1], "specular": 0.3, "shininess": 12},
    "lights": [{"name": "A", "position": [3, 4, 0], "intensity": [1, 0.5, 0]},
               {"name": "B", "position": [0, 9, 0], "blocked": true}]})";

void expect_colour(const nlohmann::json& j, Vec3d want, double tol = 1e-14) {
  ASSERT_TRUE(j.is_array()) << j.dump();
  ASSERT_EQ(j.size(), 3u);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(j[c].get<double>(), want[c], tol) << kChannelNames[c];
}

TEST(Colour, ShadeWorksEveryChannel) {
  Problem p = testing::problem(kColourShade);
  nlohmann::json a = p.task->answer();
  expect_colour(a["ambient"], {0.2, 0.2, 0.1});
  expect_colour(a["diffuse"], {0.4, 0.4, 0});
  expect_colour(a["specular"], {0.3, 0.15, 0});
  expect_colour(a["intensity"], {0.9, 0.75, 0.1});
  expect_colour(a["lights"][0]["diffuse"], {0.4, 0.4, 0});
  // The worked solution reaches the same colour.
  auto parts = p.task->derive("");
  const Step* total = parts[0].derivation.find("I");
  ASSERT_NE(total, nullptr);
  ASSERT_TRUE(total->value.is_vector());
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(total->value.vector[c], (Vec3d{0.9, 0.75, 0.1})[c], 1e-14);
}

// A number meets a colour on every channel alike: a white light [1, 1, 1] gives the same
// numbers as the light 1, as colours.
TEST(Colour, WhiteLightGivesTheScalarAnswerOnEveryChannel) {
  std::string text = testing::kTwoLightShade;
  text.replace(text.find("\"position\": [3, 4, 0]"), 21,
               "\"position\": [3, 4, 0], \"intensity\": [1, 1, 1]");
  nlohmann::json a = testing::problem(text).task->answer();
  expect_colour(a["intensity"], {0.9, 0.9, 0.9});
  expect_colour(a["ambient"], {0.2, 0.2, 0.2});
}

TEST(Colour, PublishedColourIsGradedRightAndAChangedChannelWrong) {
  Problem p = testing::problem(kColourShade);
  GradeResult right = grade_answer(p, nlohmann::json::parse(R"({"intensity": [0.9, 0.75, 0.1]})"));
  ASSERT_FALSE(right.parts.empty());
  EXPECT_EQ(right.parts[0].name, "intensity");
  EXPECT_EQ(right.parts[0].status, PartStatus::kRight);
  GradeResult wrong = grade_answer(p, nlohmann::json::parse(R"({"intensity": [0.9, 0.65, 0.1]})"));
  EXPECT_NE(wrong.parts[0].status, PartStatus::kRight);
  ASSERT_FALSE(wrong.parts[0].feedback.empty());
  const std::string& f = wrong.parts[0].feedback[0];
  EXPECT_NE(f.find("wrong channel: g is 0.75, not 0.65"), std::string::npos) << f;
  EXPECT_EQ(f.find(" r is"), std::string::npos) << f;
}

TEST(Colour, AScalarWhereAColourIsAskedIsANamedMistake) {
  Problem p = testing::problem(kColourShade);
  GradeResult r = grade_answer(p, nlohmann::json::parse(R"({"intensity": 0.9})"));
  EXPECT_NE(r.parts[0].status, PartStatus::kRight);
  ASSERT_FALSE(r.mistakes.empty());
  EXPECT_EQ(r.mistakes[0].id, "scalar-for-colour");
}

TEST(Colour, BadColoursAreErrorsAtTheirPath) {
  std::string text = kColourShade;
  std::string negative = text;
  negative.replace(negative.find("[1, 0.5, 0]"), 11, "[1, -0.5, 0]");
  try {
    testing::problem(negative);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().code, "range");
    EXPECT_NE(e.diagnostic().message.find("g channel"), std::string::npos)
        << e.diagnostic().message;
  }
  std::string two = text;
  two.replace(two.find("[1, 0.5, 0]"), 11, "[1, 0.5]");
  EXPECT_THROW(testing::problem(two), Error);
  std::string word = text;
  word.replace(word.find("[2, 2, 1]"), 9, "\"red\"");
  EXPECT_THROW(testing::problem(word), Error);
}

// A swatch shows the colour clamped to [0, 1]: 1.9 shows as full red, 0.5 as 128 of 255.
TEST(Colour, SwatchIsClamped) {
  EXPECT_EQ(swatch_hex({1.9, 0.5, 0}), "#ff8000");
  EXPECT_EQ(swatch_hex({-1, 0, 1}), "#0000ff");
}

// The worked solution shows each colour as a swatch clamped for display beside its unclamped
// number: a white light on k_d = k_s = 0.9 sums to 1.9 in every channel, drawn white (#ffffff);
// the ambient 0.1 is 0.1·255 = 25.5, drawn #1a1a1a.
TEST(Colour, ShadeSolutionShowsSwatches) {
  std::string text = testing::kTwoLightShade;
  const std::string ambient = "\"ambient_light\": 2";
  text.replace(text.find(ambient), ambient.size(), "\"ambient_light\": [1, 1, 1]");
  const std::string coefficients = "\"diffuse\": 0.5, \"specular\": 0.3";
  text.replace(text.find(coefficients), coefficients.size(), "\"diffuse\": 0.9, \"specular\": 0.9");
  auto parts = testing::problem(text).task->derive("");
  ASSERT_EQ(parts[0].figures.size(), 1u);
  const Figure& f = parts[0].figures[0];
  // The point of kTwoLightShade: N·L = 0.8, R·V = 1: 0.1 + 0.9·0.8 + 0.9 = 1.72.
  EXPECT_NE(f.svg.find("fill=\"#ffffff\""), std::string::npos) << f.svg;
  EXPECT_NE(f.text.find("[#1a1a1a] I_amb = [0.1, 0.1, 0.1]"), std::string::npos) << f.text;
  EXPECT_NE(f.text.find("I = [1.72, 1.72, 1.72]"), std::string::npos) << f.text;
}

// k_s = 0: the shade answer lists no specular term at all (none at the top, none per light),
// and a student's specular 0 is still right.
TEST(Colour, ShadeWithoutSpecularListsNoSpecular) {
  std::string text = testing::kTwoLightShade;
  text.replace(text.find("\"specular\": 0.3"), 15, "\"specular\": 0  ");
  Problem p = testing::problem(text);
  nlohmann::json a = p.task->answer();
  EXPECT_FALSE(a.contains("specular"));
  EXPECT_FALSE(a["lights"][0].contains("specular"));
  GradeResult r = grade_answer(p, nlohmann::json::parse(R"({"intensity": 0.6, "specular": 0})"));
  for (const auto& part : r.parts) {
    if (part.name == "specular" || part.name == "intensity") {
      EXPECT_EQ(part.status, PartStatus::kRight) << part.name;
    }
  }
  GradeResult bad =
      grade_answer(p, nlohmann::json::parse(R"({"intensity": 0.6, "specular": 0.3})"));
  for (const auto& part : bad.parts) {
    if (part.name == "specular") {
      EXPECT_NE(part.status, PartStatus::kRight);
    }
  }
}

// A ray tree whose material has k_s = 0: the hit point's steps work the diffuse term and say
// there is no specular one, without its mirror direction R_1 or a specular_1.
TEST(Colour, RayTreeWithoutSpecularWorksNoSpecularTerm) {
  Problem p = testing::problem(R"({"id": "t", "kind": "ray-tree", "ask": "intensity",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "scene": {"objects": [{"type": "sphere", "center": [0, 0, 5], "radius": 1,
                           "material": {"ambient": 0.1, "diffuse": 0.5, "specular": 0}}],
              "lights": [{"position": [0, 0, -10]}]}})");
  auto parts = p.task->derive("whitted");
  bool seen = false;
  for (const auto& part : parts) {
    if (part.derivation.find("diffuse_1")) {
      seen = true;
      EXPECT_EQ(part.derivation.find("R_1"), nullptr);
      EXPECT_EQ(part.derivation.find("specular_1"), nullptr);
    }
  }
  EXPECT_TRUE(seen);
}

// A coloured ball seen along +z, worked by hand: the hit P = (0, 0, 4), N = L = V = (0, 0, −1),
// N·L = R·V = 1. Ambient 0.1·[1, 1, 1]; diffuse [0.6, 0.6, 0.2] ⊙ [1, 0.5, 0.25] = [0.6, 0.3,
// 0.05]; specular 0.2·[1, 0.5, 0.25] = [0.2, 0.1, 0.05]; local [0.9, 0.5, 0.2]. The reflection
// (k_r = 0.5) leaves the scene and brings the background [0.2, 0.4, 0.6]: I = [1, 0.7, 0.5].
constexpr const char* kColourTree = R"({"id": "t", "kind": "ray-tree", "ask": "intensity",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "scene": {"objects": [{"name": "ball", "type": "sphere", "center": [0, 0, 5], "radius": 1,
        "material": {"ambient": 0.1, "diffuse": [0.6, 0.6, 0.2], "specular": 0.2,
                     "shininess": 10, "reflectivity": 0.5}}],
      "lights": [{"position": [0, 0, -10], "intensity": [1, 0.5, 0.25]}],
      "ambient_light": [1, 1, 1], "background": [0.2, 0.4, 0.6]}})";

TEST(Colour, RayTreeIntensityIsAColour) {
  Problem p = testing::problem(kColourTree);
  nlohmann::json a = p.task->answer();
  expect_colour(a["intensity"], {1, 0.7, 0.5});
  expect_colour(a["nodes"][0]["intensity"]["local"], {0.9, 0.5, 0.2});
  expect_colour(a["nodes"][0]["intensity"]["diffuse"], {0.6, 0.3, 0.05});
  expect_colour(a["nodes"][1]["background"], {0.2, 0.4, 0.6});
  const auto& task = dynamic_cast<const RayTreeTask&>(*p.task);
  EXPECT_EQ(task.ask(), Ask::kIntensity);
  // The tree's shape is the scene's: one hit, its reflection, one shadow ray.
  EXPECT_EQ(task.tree().nodes.size(), 2u);
  EXPECT_EQ(task.tree().counts.shadow, 1);
}

TEST(Colour, RayTreeColourIsGradedByChannel) {
  Problem p = testing::problem(kColourTree);
  nlohmann::json base = p.task->answer();
  auto intensity_part = [&](const nlohmann::json& given) {
    nlohmann::json a = base;
    a["intensity"] = given;
    GradeResult r = grade_answer(p, a);
    for (const auto& part : r.parts) {
      if (part.name == "intensity") return std::make_pair(part, r.mistakes);
    }
    ADD_FAILURE() << "no intensity part";
    return std::make_pair(PartResult{}, r.mistakes);
  };
  EXPECT_EQ(intensity_part({1, 0.7, 0.5}).first.status, PartStatus::kRight);
  auto [blue, none] = intensity_part({1, 0.7, 0.25});
  EXPECT_NE(blue.status, PartStatus::kRight);
  ASSERT_FALSE(blue.feedback.empty());
  EXPECT_NE(blue.feedback[0].find("wrong channel: b is 0.5, not 0.25"), std::string::npos)
      << blue.feedback[0];
  auto [scalar, mistakes] = intensity_part(0.7);
  EXPECT_NE(scalar.status, PartStatus::kRight);
  ASSERT_FALSE(mistakes.empty());
  EXPECT_EQ(mistakes.back().id, "scalar-for-colour");
}

TEST(Colour, RayTreeSolutionShowsSwatches) {
  auto parts = testing::problem(kColourTree).task->derive("whitted");
  const Figure* swatches = nullptr;
  for (const auto& part : parts) {
    for (const auto& f : part.figures) {
      if (f.svg.find("swatches") != std::string::npos) swatches = &f;
    }
  }
  ASSERT_NE(swatches, nullptr);
  // [1, 0.7, 0.5] is #ffb380; the background [0.2, 0.4, 0.6] is #336699.
  EXPECT_NE(swatches->text.find("[#ffb380] I at I1 = [1, 0.7, 0.5]"), std::string::npos)
      << swatches->text;
  EXPECT_NE(swatches->text.find("[#336699]"), std::string::npos) << swatches->text;
  // The tree's own figure has the same swatches beside its points.
  ASSERT_FALSE(parts.front().figures.empty());
  const std::string& tree = parts.front().figures.front().svg;
  EXPECT_NE(tree.find("class=\"swatch\""), std::string::npos) << tree;
  EXPECT_NE(tree.find("fill=\"#ffb380\""), std::string::npos) << tree;
}

// Without colours nothing changes: the same tree with numbers gives numbers.
TEST(Colour, ANumberStaysANumber) {
  std::string text = kColourTree;
  for (auto [from, to] : {std::pair<std::string, std::string>{"[0.6, 0.6, 0.2]", "0.6"},
                          {"[1, 0.5, 0.25]", "1"},
                          {"[1, 1, 1]", "1"},
                          {"[0.2, 0.4, 0.6]", "0.2"}}) {
    text.replace(text.find(from), from.size(), to);
  }
  nlohmann::json a = testing::problem(text).task->answer();
  ASSERT_TRUE(a["intensity"].is_number());
  // 0.1 + 0.6 + 0.2 + 0.5·0.2 = 1.0
  EXPECT_NEAR(a["intensity"].get<double>(), 1.0, 1e-14);
}

// The ch. 10 definitions, at points worked by hand in pattern space.
TEST(Pattern, TextbookDefinitions) {
  Pattern p;
  p.a = {1, 1, 1};
  p.b = {0, 0, 0};
  p.type = PatternType::kStripe;
  EXPECT_EQ(pattern_at(p, {-0.1, 5, 5}).colour, (Vec3d{0, 0, 0}));  // ⌊−0.1⌋ = −1, odd
  EXPECT_EQ(pattern_at(p, {-1.1, 0, 0}).colour, (Vec3d{1, 1, 1}));  // ⌊−1.1⌋ = −2, even
  p.type = PatternType::kGradient;
  PatternValue g = pattern_at(p, {2.25, 0, 0});  // f = 0.25: a + (b − a)·0.25 = 0.75
  EXPECT_DOUBLE_EQ(g.fraction, 0.25);
  EXPECT_DOUBLE_EQ(g.colour.x, 0.75);
  p.type = PatternType::kRing;
  PatternValue r = pattern_at(p, {3, 100, 4});  // r = 5, odd
  EXPECT_DOUBLE_EQ(r.radius, 5);
  EXPECT_FALSE(r.even);
  p.type = PatternType::kCheckers;
  EXPECT_TRUE(pattern_at(p, {1.5, 0.5, -0.5}).even);  // 1 + 0 − 1 = 0
  EXPECT_FALSE(pattern_at(p, {1.5, 0.5, 0.5}).even);  // 1 + 0 + 0 = 1
}

// A pattern on a moved object is evaluated in object space, then pattern space; the worked
// solution shows both points and the count (here object scale 2, pattern translate 0.5: P =
// (2.5, 0, 0) → (1.25, 0, 0) → (0.75, 0, 0), ⌊0.75⌋ = 0: white).
TEST(Pattern, ObjectThenPatternSpace) {
  Problem p = testing::problem(R"({"id": "p", "kind": "shade",
    "point": [2.5, 0, 0], "normal": [0, 0, -1], "eye": [2.5, 0, -1], "ambient_light": [1, 1, 1],
    "material": {"ambient": 1, "diffuse": 0, "specular": 0,
                 "colour": {"pattern": "stripe", "a": [1, 1, 1], "b": [0, 0, 0],
                            "transform": [{"translate": [0.5, 0, 0]}]}},
    "object_transform": [{"scale": 2}],
    "lights": [{"position": [0, 0, -10]}]})");
  expect_colour(p.task->answer()["colour"], {1, 1, 1});
  auto parts = p.task->derive("");
  const Step* po = parts[0].derivation.find("P_o");
  const Step* pp = parts[0].derivation.find("P_pat");
  ASSERT_NE(po, nullptr);
  ASSERT_NE(pp, nullptr);
  EXPECT_EQ(po->value.vector, (Vec3d{1.25, 0, 0}));
  EXPECT_EQ(pp->value.vector, (Vec3d{0.75, 0, 0}));
  ASSERT_NE(parts[0].derivation.find("floor_x"), nullptr);
  EXPECT_EQ(parts[0].derivation.find("floor_x")->value.scalar, 0);
}

TEST(Pattern, BadPatternsAreErrors) {
  const char* base = R"({"id": "p", "kind": "shade", "point": [0, 0, 0], "normal": [0, 0, -1],
    "eye": [0, 0, -1], "material": {"colour": %s}, "lights": [{"position": [0, 0, -10]}]})";
  for (const char* bad :
       {R"({"pattern": "zigzag", "a": 1, "b": 0})", R"({"pattern": "stripe", "a": 1})",
        R"({"pattern": "stripe", "a": 1, "b": 0, "scale": 2})", R"([1, 2])"}) {
    std::string text = base;
    text.replace(text.find("%s"), 2, bad);
    EXPECT_THROW(testing::problem(text), Error) << bad;
  }
  // object_transform places a pattern: without a colour it is an error.
  EXPECT_THROW(testing::problem(R"({"id": "p", "kind": "shade", "point": [0, 0, 0],
    "normal": [0, 0, -1], "eye": [0, 0, -1], "object_transform": [{"scale": 2}],
    "lights": [{"position": [0, 0, -10]}]})"),
               Error);
}

}  // namespace
}  // namespace raygrade
