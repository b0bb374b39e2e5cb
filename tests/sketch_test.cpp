// The sketches of the kinds reflect, refract, shade and derive: what they draw, against values
// worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "assignments/handout.h"
#include "reports/svg_figure.h"
#include "test_util.h"

namespace raygrade {
namespace {

using Type = SketchItem::Type;

// The one item of `type` whose label is `label`; fails the test when there is none or several.
const SketchItem& item(const Sketch& f, Type type, const std::string& label) {
  const SketchItem* found = nullptr;
  int count = 0;
  for (const auto& i : f.items) {
    if (i.type == type && i.label == label) {
      found = &i;
      ++count;
    }
  }
  EXPECT_EQ(count, 1) << "items labelled '" << label << "'";
  static const SketchItem kNone;
  return found ? *found : kNone;
}

bool has_label_starting(const Sketch& f, const std::string& prefix) {
  for (const auto& i : f.items) {
    if (i.label.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

// The unit direction of an arrow.
Vec3d direction(const SketchItem& arrow) {
  if (arrow.points.size() != 2) return {};
  return normalized(arrow.points[1] - arrow.points[0]);
}

void expect_near(const Vec3d& a, const Vec3d& b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance) << "x";
  EXPECT_NEAR(a.y, b.y, tolerance) << "y";
  EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

// The bank's floor: d = (1, −2, 0), n = (0, 5, 0), so n̂ = (0, 1, 0), d·n̂ = −2 and
// r = d − 2(d·n̂)n̂ = (1, −2, 0) + 4·(0, 1, 0) = (1, 2, 0), drawn as its unit (1, 2, 0)/√5.
TEST(ReflectSketch, FloorShowsSurfaceNormalAndBothRays) {
  Problem p = testing::problem(R"({"id": "r", "kind": "reflect",
    "direction": [1, -2, 0], "normal": [0, 5, 0]})");
  Sketch f = p.task->sketch();
  const SketchItem& surface = item(f, Type::kPlane, "surface");
  expect_near(surface.points[1], {0, 1, 0});
  const SketchItem& normal = item(f, Type::kArrow, "n̂");
  expect_near(normal.points[0], {0, 0, 0});
  expect_near(normal.points[1], {0, 1, 0});
  const SketchItem& in = item(f, Type::kArrow, "d = (1, −2, 0)");
  expect_near(direction(in), Vec3d{1, -2, 0} / std::sqrt(5.0));
  const SketchItem& out = item(f, Type::kArrow, "r = (1, 2, 0)");
  expect_near(out.points[0], {0, 0, 0});
  expect_near(direction(out), Vec3d{1, 2, 0} / std::sqrt(5.0));
  EXPECT_EQ(out.ink, Ink::kRay);
  // Seen edge-on: along the floor to the right, the normal up.
  expect_near(f.across, {1, 0, 0});
  expect_near(f.up, {0, 1, 0});
  SvgFigure svg = render_svg(f, "reflect");
  EXPECT_NE(svg.svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.caption.find("along the surface (+x) points right, the normal (+y) points up"),
            std::string::npos)
      << svg.caption;
}

// A unit normal given along the ray, (0, −1, 0): the figure turns it to face d and says so;
// the reflected direction does not change.
TEST(ReflectSketch, NormalAlongTheRayIsTurned) {
  Problem p = testing::problem(R"({"id": "r", "kind": "reflect",
    "direction": [1, -2, 0], "normal": [0, -1, 0]})");
  Sketch f = p.task->sketch();
  const SketchItem& normal = item(f, Type::kArrow, "−n (turned to face d)");
  expect_near(normal.points[1], {0, 1, 0});
  expect_near(direction(item(f, Type::kArrow, "r = (1, 2, 0)")), Vec3d{1, 2, 0} / std::sqrt(5.0));
}

// Air into water at 60°: η = 3/4, cos θi = 1/2, k = 1 − (9/16)(3/4) = 37/64, so
// t = η·d̂ + (η·cos θi − √k)·n̂ = (3√3/8, −3/8 + 3/8 − √37/8, 0) = (3√3/8, −√37/8, 0) and
// θt = asin(3√3/8) ≈ 40.505°.
TEST(RefractSketch, WaterShowsTheRefractedRayAndItsAngle) {
  Problem p = testing::problem(R"({"id": "w", "kind": "refract",
    "direction": [0.8660254037844386, -0.5, 0], "normal": [0, 1, 0], "n1": 1,
    "n2": 1.3333333333333333})");
  Sketch f = p.task->sketch();
  item(f, Type::kPlane, "surface");
  expect_near(item(f, Type::kArrow, "n̂").points[1], {0, 1, 0});
  expect_near(direction(item(f, Type::kArrow, "d, θi = 60°")), {std::sqrt(3.0) / 2, -0.5, 0});
  const SketchItem& t = item(f, Type::kArrow, "t, θt = 40.51°");
  expect_near(t.points[0], {0, 0, 0});
  expect_near(t.points[1], {3 * std::sqrt(3.0) / 8, -std::sqrt(37.0) / 8, 0});
  item(f, Type::kText, "n₁ = 1");
  item(f, Type::kText, "n₂ = 1.333");
  EXPECT_FALSE(has_label_starting(f, "r:"));
}

// Glass into air at 60° with the normal given along the ray: the figure turns it to
// (0, −1, 0); sin θt would be 1.5·√3/2 > 1, so the ray is reflected: r = d̂ − 2(d̂·n̂)n̂ =
// (√3/2, 1/2, 0) − 2·(−1/2)·(0, −1, 0) = (√3/2, −1/2, 0).
TEST(RefractSketch, TotalInternalReflectionIsDrawnAndLabelled) {
  Problem p = testing::problem(R"({"id": "g", "kind": "refract",
    "direction": [0.8660254037844386, 0.5, 0], "normal": [0, 1, 0], "n1": 1.5, "n2": 1})");
  Sketch f = p.task->sketch();
  expect_near(item(f, Type::kArrow, "n̂").points[1], {0, -1, 0});
  expect_near(f.up, {0, -1, 0});
  const SketchItem& r = item(f, Type::kArrow, "r: total internal reflection");
  expect_near(r.points[1], {std::sqrt(3.0) / 2, -0.5, 0});
  item(f, Type::kText, "no refracted ray (k < 0)");
  EXPECT_FALSE(has_label_starting(f, "t,"));
}

// The bank's two lights: V = (−3, 4, 0)/5; light A at (3, 4, 0): L_1 = (0.6, 0.8, 0),
// N·L_1 = 0.8, R_1 = 2·0.8·(0, 1, 0) − L_1 = (−0.6, 0.8, 0) (= V: the full highlight);
// light B at (0, 9, 0) is blocked: L_2 = (0, 1, 0), dotted, and no R_2.
TEST(ShadeSketch, ShowsNormalViewLightsAndReflection) {
  Problem p = testing::problem(testing::kTwoLightShade);
  Sketch f = p.task->sketch();
  item(f, Type::kPlane, "surface");
  expect_near(item(f, Type::kPoint, "P").points[0], {0, 0, 0});
  expect_near(item(f, Type::kArrow, "N").points[1], {0, 1, 0});
  expect_near(item(f, Type::kArrow, "V (to the eye)").points[1], {-0.6, 0.8, 0});
  const SketchItem& l1 = item(f, Type::kArrow, "L_1, light A");
  EXPECT_EQ(l1.ink, Ink::kRay);
  expect_near(l1.points[1], {0.6, 0.8, 0});
  expect_near(item(f, Type::kArrow, "R_1").points[1], {-0.6, 0.8, 0});
  const SketchItem& l2 = item(f, Type::kArrow, "L_2, light B: blocked");
  EXPECT_EQ(l2.ink, Ink::kMiss);
  expect_near(l2.points[1], {0, 1, 0});
  EXPECT_FALSE(has_label_starting(f, "R_2"));
  // V's part along the surface, (−0.6, 0, 0), points right.
  expect_near(f.across, {-1, 0, 0});
}

// A light below the surface: N·L = −1 ≤ 0, drawn dotted with the reason.
TEST(ShadeSketch, LightBehindTheSurfaceIsDotted) {
  Problem p = testing::problem(R"({"id": "s", "kind": "shade",
    "point": [0, 0, 0], "normal": [0, 1, 0], "eye": [0, 4, 0],
    "lights": [{"name": "low", "position": [0, -2, 0]}]})");
  Sketch f = p.task->sketch();
  const SketchItem& l = item(f, Type::kArrow, "L_1, light low: behind the surface");
  EXPECT_EQ(l.ink, Ink::kMiss);
  expect_near(l.points[1], {0, -1, 0});
  // V runs along the normal: the view takes a direction along the surface.
  EXPECT_NEAR(dot(f.across, f.up), 0, 1e-15);
  EXPECT_NEAR(length(f.across), 1, 1e-15);
}

// The caption names the ray's direction (1, −2, 2)/3 once, in parentheses of its own, with
// real minus signs: "the ray's direction (0.333, −0.667, 0.667)".
TEST(SketchCaption, DirectionWrittenOnceWithMinusSigns) {
  Problem p = testing::problem(R"({"id": "c", "kind": "intersect",
    "ray": {"origin": [0, 0, 0], "direction": [1, -2, 2]},
    "object": {"type": "sphere", "center": [3, -6, 6], "radius": 1}})");
  SvgFigure svg = render_svg(p.task->sketch(), "caption");
  EXPECT_NE(svg.caption.find("the ray's direction (0.333, −0.667, 0.667) points right"),
            std::string::npos)
      << svg.caption;
  EXPECT_EQ(svg.caption.find("(("), std::string::npos) << svg.caption;
  EXPECT_EQ(svg.caption.find('-'), std::string::npos) << svg.caption;
}

// The labels of a sketch: text, x and baseline y, from the SVG.
struct Label {
  std::string text;
  double x, y;
};
std::vector<Label> labels(const std::string& svg) {
  std::vector<Label> out;
  std::regex text(R"re(<text class="[^"]*" x="([-0-9.]+)" y="([-0-9.]+)">([^<]*)</text>)re");
  for (std::sregex_iterator it(svg.begin(), svg.end(), text), end; it != end; ++it) {
    out.push_back({(*it)[3], std::stod((*it)[1]), std::stod((*it)[2])});
  }
  return out;
}

// The ray y = 0.9999 across the cylinder x² + y² = 1 hits at x = ±√(1 − 0.9999²) = ±0.01414,
// t = 3 ∓ 0.01414: the two hits are a fraction of a pixel apart, and so are the places of
// their labels. Each label's box is at least 14.4 px high (the line box Chromium lays out for
// the 12 px label font, measured by the browser test) and starts within a few pixels of the
// other's, so the two must be at least 14.4 px apart vertically.
TEST(SketchLabels, CloseHitsOfACylinderDoNotOverlap) {
  Problem p = testing::problem(R"({"id": "c",
    "ray": {"origin": [-3, 0.9999, 0], "direction": [1, 0, 0]},
    "object": {"type": "cylinder", "base": [0, 0, -1], "axis": [0, 0, 1], "radius": 1,
               "height": 2}})");
  std::vector<Label> found = labels(render_svg(p.task->sketch(), "close").svg);
  const Label* first = nullptr;
  const Label* second = nullptr;
  for (const auto& l : found) {
    if (l.text == "t = 2.986") first = &l;
    if (l.text == "t = 3.014") second = &l;
  }
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  EXPECT_LT(std::abs(first->x - second->x), 10);
  EXPECT_GE(std::abs(first->y - second->y), 14.4);
}

// Seed 000's cylinder x² + y² = 1 and the ray (−3, 0, 0.5) + t(1, 0, 0): a = 1, b = −6,
// c = 8, so t = 2 and t = 4, at (−1, 0, 0.5) and (1, 0, 0.5). The ray is labelled in the
// formulas' symbols and the radius r drawn from the axis toward the ray's side.
TEST(DeriveSketch, CylinderWithTheFormulasSymbols) {
  Problem p = testing::problem(R"({"id": "d", "kind": "derive",
    "ray": {"origin": [-3, 0, 0.5], "direction": [1, 0, 0]},
    "object": {"type": "cylinder", "base": [0, 0, 0], "axis": [0, 0, 1], "radius": 1},
    "find": ["a", "b", "c"]})");
  Sketch f = p.task->sketch();
  const SketchItem& cylinder = item(f, Type::kCylinder, "");
  EXPECT_EQ(cylinder.radius, 1);
  expect_near(cylinder.points[1], {0, 0, 1});
  expect_near(item(f, Type::kPoint, "(0, 0): x² + y² = r²").points[0], {0, 0, 0});
  const SketchItem& r = item(f, Type::kPath, "r");
  expect_near(r.points[0], {-1, 0, 0});
  expect_near(r.points[1], {0, 0, 0});
  expect_near(item(f, Type::kPoint, "p").points[0], {-3, 0, 0.5});
  expect_near(direction(item(f, Type::kArrow, "p + t v")), {1, 0, 0});
  expect_near(item(f, Type::kPoint, "t = 2").points[0], {-1, 0, 0.5});
  expect_near(item(f, Type::kPoint, "t = 4").points[0], {1, 0, 0.5});
}

// Seed 000's second cylinder, axis through (2, 3): the centre is named (c_x, c_y) and r = 2
// points from it against the ray's direction (1, 1, 0.2), i.e. along −(1, 1, 0)/√2.
TEST(DeriveSketch, OffsetCylinderNamesItsCentre) {
  Problem p = testing::problem(R"({"id": "d", "kind": "derive",
    "ray": {"origin": [0, 0, 0], "direction": [1, 1, 0.2]},
    "object": {"type": "cylinder", "base": [2, 3, 0], "axis": [0, 0, 1], "radius": 2},
    "find": ["a", "b", "c"]})");
  Sketch f = p.task->sketch();
  expect_near(item(f, Type::kPoint, "(c_x, c_y): (x − c_x)² + (y − c_y)² = r²").points[0],
              {2, 3, 0});
  const SketchItem& r = item(f, Type::kPath, "r");
  expect_near(r.points[0], {2 - std::sqrt(2.0), 3 - std::sqrt(2.0), 0});
  expect_near(r.points[1], {2, 3, 0});
}

// A camera's ray through a pixel is the answer of camera-ray and view-ray problems: the
// statement's figure draws the eye and the image plane, never that ray (the worked solution's
// figure draws it).
// The area (in px², by the shoelace formula) of the first closed path of class "object" in
// `svg`, from its "M x y L x y … Z" data.
double first_object_area(const std::string& svg) {
  static const std::regex path(R"re(<path class="object" d="M([^"]*) Z"/>)re");
  std::smatch m;
  if (!std::regex_search(svg, m, path)) return -1;
  std::vector<std::pair<double, double>> pts;
  static const std::regex xy(R"re((-?[0-9.]+) (-?[0-9.]+))re");
  std::string d = m[1];
  for (auto it = std::sregex_iterator(d.begin(), d.end(), xy); it != std::sregex_iterator(); ++it) {
    pts.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  }
  double twice = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& [x0, y0] = pts[i];
    const auto& [x1, y1] = pts[(i + 1) % pts.size()];
    twice += x0 * y1 - x1 * y0;
  }
  return std::abs(twice) / 2;
}

// A ray straight down onto a triangle in the plane y = 0: the side view along the ray shows
// the triangle as a line (area 0), so a second drawing looks along the normal, where the
// triangle (−2, 0, −2), (2, 0, −2), (0, 0, 2), of area ½·4·4 = 8 square units, has an area
// well above zero.
TEST(SketchViews, AFlatObjectSeenEdgeOnGetsAFaceOnView) {
  Problem p = testing::problem(R"({"id": "t",
    "ray": {"origin": [0, 5, 0], "direction": [0, -1, 0]},
    "object": {"type": "triangle", "vertices": [[-2, 0, -2], [2, 0, -2], [0, 0, 2]]}})");
  SvgFigure svg = render_svg(p.task->sketch(), "triangle");
  std::size_t face = svg.svg.find("<g class=\"face-view\"");
  ASSERT_NE(face, std::string::npos) << svg.svg;
  std::string side_part = svg.svg.substr(0, face), face_part = svg.svg.substr(face);
  EXPECT_LT(first_object_area(side_part), 1.0) << side_part;
  EXPECT_GT(first_object_area(face_part), 1000.0) << face_part;
  EXPECT_NE(svg.caption.find("seen face-on, looking along its normal"), std::string::npos)
      << svg.caption;
  // Turned 45° about z (normal (1, −1, 0)/√2), the triangle shows its width in the side view,
  // the plane of −y and +z: one drawing is enough.
  Problem tilted = testing::problem(R"({"id": "t",
    "ray": {"origin": [0, 5, 0], "direction": [0, -1, 0]},
    "object": {"type": "triangle", "vertices": [[-2, -2, -2], [2, 2, -2], [0, 0, 2]]}})");
  SvgFigure one = render_svg(tilted.task->sketch(), "triangle");
  EXPECT_EQ(one.svg.find("face-view"), std::string::npos);
  EXPECT_GT(first_object_area(one.svg), 1000.0) << one.svg;
}

TEST(Sketch, AStatementNeverDrawsTheCameraRayItAsksFor) {
  for (const char* source : {R"({"id": "c", "kind": "camera-ray", "camera": {"eye": [0, 0, 0],
        "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 1, "resolution": [640, 480]},
        "pixel": [320, 240], "convention": "corner"})",
                             R"({"id": "v", "kind": "view-ray", "camera": {"eye": [0, 0, 0],
        "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 1,
        "bounds": [-2, 2, -1.5, 1.5], "resolution": [8, 6], "pixel_origin": "bottom-left"},
        "pixel": [2, 1], "convention": "center"})"}) {
    Problem p = testing::problem(source);
    std::string solution = render_svg(p.task->sketch(), "solution").svg;
    std::string statement = statement_figure_svg(p);
    EXPECT_NE(solution.find("class=\"ray\""), std::string::npos) << p.id;
    EXPECT_EQ(statement.find("class=\"ray\""), std::string::npos) << p.id << statement;
    EXPECT_NE(statement.find("class=\"guide\""), std::string::npos) << p.id;
    EXPECT_EQ(statement.find("pixel ("), std::string::npos) << p.id;
  }
}

}  // namespace
}  // namespace raygrade
