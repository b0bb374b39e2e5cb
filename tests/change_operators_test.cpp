// The operators of the mistake search, each by a slip planted in an answer to a real kind and
// worked out here by hand: the search must explain the answer by a change of that operator in
// that step (among the changes giving the same numbers). Without the operator the change is
// not among them and the test fails.
#include "grading/change_operators.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "grading/discover.h"
#include "test_util.h"

namespace raygrade {
// Named rather than anonymous: a unity batch of tests shares one anonymous namespace.
namespace change_operators_test {

using nlohmann::json;

// The sphere of centre (0, 0, 10) and radius 5, from O = (3, 0, 0) along D = (0, 0, 1), worked
// geometrically: L = C − O = (−3, 0, 10), t_ca = L·D = 10, L² = 109, r² = 25,
// d² = L² − t_ca² = 9, t_hc = √(r² − d²) = 4, t = 6 and 14, P = (3, 0, t). By the quadratic
// (f = O − C = (3, 0, −10)): a = 1, b = 2·(D·f) = −20, c = f·f − r² = 84, Δ = b² − 4ac = 64.
constexpr const char* kSphere = R"({"id": "sphere", "ray": {"origin": [3, 0, 0],
    "direction": [0, 0, 1]}, "object": {"type": "sphere", "center": [0, 0, 10], "radius": 5}})";

json hits(double t0, double t1) {
  return {{"hits", {{{"t", t0}, {"point", {3, 0, t0}}}, {{"t", t1}, {"point", {3, 0, t1}}}}}};
}

struct Planted {
  const char* what;
  const char* problem;
  json answer;
  const char* step;  // the step the slip is in
  const char* kind;  // the operator that makes it
};

// Whether the search explains `answer` by a change of `kind` in `step`; the changes it names
// otherwise, for the failure message.
std::string explained_by(const Planted& p) {
  Problem problem = testing::problem(p.problem);
  ChangeSearch search(problem);
  Discovery d = search.explain(p.answer);
  std::string seen = to_string(d.verdict);
  for (const auto& c : d.changes) {
    if (c.step == p.step && c.kind == p.kind) return "";
    seen += " | " + c.kind + ": " + c.text();
  }
  return seen;
}

TEST(ChangeOperators, EachOperatorNamesItsSlip) {
  const Planted planted[] = {
      // A diameter for a radius: r² = (2r)² = 100, d² = 9, t_hc = √91 = 9.539392.
      {"factor", kSphere, hits(10 - 9.539392, 10 + 9.539392), "r2", "factor"},
      // Δ = b² − 2ac (4 halved): 400 − 168 = 232, √232 = 15.231546, t = (20 ∓ 15.231546)/2.
      {"constant", kSphere, hits(2.384227, 17.615773), "discriminant", "constant"},
      // t0 = (−b − √Δ)·(2a) = 12·2 = 24; t1 stays 14: the hits in the order of t.
      {"operator", kSphere, hits(14, 24), "t0", "operator"},
      // t_hc = √(t_ca − d²): t_ca for r², √(10 − 9) = 1, t = 9 and 11.
      {"operand", kSphere, hits(9, 11), "t_hc", "operand"},
      // L = C − D for C − O: (0, 0, 9), t_ca = 9, L² = 81, d² = 0, t_hc = 5, t = 4 and 14.
      {"vector-swap", kSphere, hits(4, 14), "L", "vector-swap"},
      // d² subtracted with its sign changed: t_hc = √(r² + d²) = √34 = 5.830952,
      // t = 10 ∓ 5.830952.
      {"sign", kSphere, hits(10 - 5.830952, 10 + 5.830952), "t_hc", "sign"},
      // t_ca = (L·D)² = 100: d² = 109 − 100² = −9891, t_hc = √(25 + 9891) = 99.579114,
      // t = 100 ∓ 99.579114.
      {"square", kSphere, hits(100 - 99.579114, 100 + 99.579114), "t_ca", "square"},
      // A root put in: t_hc = √(r² − √d²) = √(25 − 3) = 4.690416, t = 10 ∓ 4.690416.
      {"sqrt", kSphere, hits(10 - 4.690416, 10 + 4.690416), "t_hc", "sqrt"},
      // A term dropped: t0 = t_ca − t_hc without t_hc (or (−b − √Δ)/(2a) without √Δ):
      // t0 = 10, t1 = 14.
      {"drop-term", kSphere, hits(10, 14), "t0", "drop-term"},
  };
  for (const Planted& p : planted) EXPECT_EQ(explained_by(p), "") << p.what;
}

// The refraction from glass (n1 = 1.5) into air (n2 = 1) of d = (1, −2, 0) at the normal
// (0, 1, 0): d̂ = (1, −2, 0)/√5, cos θi = 2/√5 = 0.894427, θi = 26.565051°, η = n1/n2 = 1.5,
// k = 1 − η²(1 − cos²θi) = 1 − 2.25·0.2 = 0.55, t = η·d̂ + (η·cos θi − √k)·n̂
// = (0.670820, −0.741620, 0).
constexpr const char* kRefract = R"({"id": "refract", "kind": "refract", "direction": [1, -2, 0],
    "normal": [0, 1, 0], "n1": 1.5, "n2": 1})";

TEST(ChangeOperators, TwoIndicesExchangedAndTheAngleFromTheSurface) {
  // n1 and n2 exchanged: η = 2/3, k = 1 − (4/9)·0.2 = 0.911111, √k = 0.954521,
  // t = (2/3)·d̂ + ((2/3)·0.894427 − 0.954521)·n̂ = (0.298142, −0.954521, 0).
  Planted exchanged{"exchange",
                    kRefract,
                    {{"total_internal_reflection", false}, {"direction", {0.298142, -0.954521, 0}}},
                    "eta",
                    "exchange"};
  EXPECT_EQ(explained_by(exchanged), "");
  // The angle of incidence from the surface: 90° − 26.565051° = 63.434949°.
  Planted surface{"function",
                  kRefract,
                  {{"total_internal_reflection", false},
                   {"direction", {0.670820, -0.741620, 0}},
                   {"angle_of_incidence", 63.434949}},
                  "theta_i",
                  "function"};
  EXPECT_EQ(explained_by(surface), "");
}

// A direction answered as a unit vector where any positive multiple is asked: d = (1, −1, 0) off
// the floor n = (0, 1, 0) is r = d − 2(d·n)n = (1, 1, 0); with + for −, r = (1, −3, 0), given
// as its unit vector (0.316228, −0.948683, 0). Compared by components it fits no change.
TEST(ChangeOperators, ADirectionGivenAsAUnitVectorIsMatchedAsTheGraderMatchesIt) {
  Planted p{"unit",
            R"({"id": "reflect", "kind": "reflect", "direction": [1, -1, 0], "normal": [0, 1, 0]})",
            {{"direction", {0.316228, -0.948683, 0}}},
            "r",
            "sign"};
  EXPECT_EQ(explained_by(p), "");
}

// max(0, x) → x: no derivation of the bundled kinds clamps yet, so the clamp is checked on a
// formula: max(0, N·L) with N·L = −0.5 is 0, and −0.5 without the clamp.
TEST(ChangeOperators, AClampRemoved) {
  Env values{{"N", Value(Vec3d{0, 1, 0})}, {"L", Value(Vec3d{0, -0.5, 0})}};
  std::map<std::string, E, std::less<>> symbols{{"N", sym("N")}, {"L", sym("L")}};
  ChangeScope scope{&values, &symbols};
  E f = max({E(0), dot(sym("N"), sym("L"))});
  std::size_t left = count_changes(f, scope, ChangeTier::kAll);
  bool found = false;
  each_change(f, scope, ChangeTier::kAll, left, [&](FormulaChange&& c) {
    if (c.kind == "clamp") found = found || evaluate(c.eval, values).scalar == -0.5;
  });
  EXPECT_TRUE(found);
}

}  // namespace change_operators_test
}  // namespace raygrade

namespace raygrade {
namespace change_operators_test {

// The camera of the bank's camera-ray variant (eye at the origin looking along (0, 0, −1), up
// (0, 1, 0), f = 2, 8 × 6 pixels) through the centre of pixel (6, 1): x_diff = 6 + 0.5 − 4 = 2.5,
// y_diff = 1 + 0.5 − 3 = −1.5, d × u = (1, 0, 0), d_r = f·d + x_diff·(d × u) + y_diff·u =
// (2.5, −1.5, −2). With the half pixel left out of x_diff (the constant 0.5 for 0), x_diff = 2
// and d_r = (2, −1.5, −2), given as twice that: any positive multiple is the same direction.
TEST(ChangeOperators, ACameraRayGivenAsAMultiple) {
  Planted p{"camera",
            R"({"id": "camera", "kind": "camera-ray", "camera": {"eye": [0, 0, 0],
                "direction": [0, 0, -1], "up": [0, 1, 0], "focal_length": 2,
                "resolution": [8, 6]}, "pixel": [6, 1], "convention": "center"})",
            {{"ray", {{"origin", {0, 0, 0}}, {"direction", {4, -3, -4}}}}},
            "x_diff",
            "constant"};
  EXPECT_EQ(explained_by(p), "");
}

}  // namespace change_operators_test
}  // namespace raygrade

namespace raygrade {
namespace change_operators_test {

// Whether the search explains `answer` by a change in `step` made in every step of its form.
std::string explained_everywhere(const char* problem, const json& answer, const char* step) {
  Problem p = testing::problem(problem);
  ChangeSearch search(p);
  Discovery d = search.explain(answer);
  std::string seen = to_string(d.verdict);
  for (const auto& c : d.changes) {
    if (c.everywhere && c.step == step) return "";
    seen += " | " + c.kind + ": " + c.text();
  }
  return seen;
}

// A slip in a formula used twice is made twice. The sphere of centre (0, 0, 10), radius 5, from
// O = (3, 0, 0) along D = (0, 0, 2): f = O − C = (3, 0, −10), a = D·D = 4, b = 2·(D·f) = −40,
// c = f·f − r² = 84, Δ = b² − 4ac = 256, t = (40 ∓ 16)/(2·4) = 3 and 7. Divided by 2 and
// multiplied by a ((−b ∓ √Δ)/2·a) in both roots: t = 12·4 = 48 and 28·4 = 112, P = (3, 0, 2t).
// One root alone changed (48 and 7) is a single change; both need the change everywhere.
TEST(ChangeOperators, AChangeMadeInEveryStepOfItsForm) {
  const char* sphere = R"({"id": "sphere", "ray": {"origin": [3, 0, 0], "direction": [0, 0, 2]},
      "object": {"type": "sphere", "center": [0, 0, 10], "radius": 5}})";
  json both = {
      {"hits", {{{"t", 48}, {"point", {3, 0, 96}}}, {{"t", 112}, {"point", {3, 0, 224}}}}}};
  std::string t0 = explained_everywhere(sphere, both, "t0");
  std::string t1 = explained_everywhere(sphere, both, "t1");
  EXPECT_TRUE(t0.empty() || t1.empty()) << t0;
}

// The form of a node alike for the quantities of one indexed family: L_2 = (S_2 − P)/‖S_2 − P‖
// changed as L_1's (S_1 − P)/‖S_1 − P‖ → S_1 − P is S_2 − P; with S_2 = (0, 9, 0) and P = 0,
// (0, 9, 0) rather than (0, 1, 0).
TEST(ChangeOperators, TheChangeOfOneLightMadeForAnother) {
  E p = sym("P");
  E from = (sym("S_1") - p) / norm(sym("S_1") - p);
  E to = sym("S_1") - p;
  E l2 = (sym("S_2") - p) / norm(sym("S_2") - p);
  std::optional<E> changed = change_everywhere(l2, from, to, form_hash(from));
  ASSERT_TRUE(changed.has_value());
  Env values{{"P", Value(Vec3d{0, 0, 0})}, {"S_2", Value(Vec3d{0, 9, 0})}};
  Value v = evaluate(*changed, values);
  EXPECT_EQ(v.vector.y, 9);
  // A formula of another form is left alone.
  EXPECT_FALSE(change_everywhere(sym("S_2") - p, from, to, form_hash(from)).has_value());
  // One quantity of a family for the same-indexed one of another, carried over: c_1 → r_1
  // makes c_2 · n into r_2 · n, (1, 2, 3)·(0, 1, 0) = 2 rather than (5, 7, 9)·(0, 1, 0) = 7.
  E c1 = sym("c_1"), r1 = sym("r_1");
  FormulaChange swap{r1, r1, "vector-swap", c1, r1};
  ASSERT_TRUE(made_everywhere(swap));
  std::optional<E> m2 = change_everywhere(dot(sym("c_2"), sym("n")), c1, r1, form_hash(c1));
  ASSERT_TRUE(m2.has_value());
  Env more{
      {"c_2", Value(Vec3d{5, 7, 9})}, {"r_2", Value(Vec3d{1, 2, 3})}, {"n", Value(Vec3d{0, 1, 0})}};
  EXPECT_EQ(evaluate(*m2, more).scalar, 2);
  // Not one of a family for another of the same family (S_1 for S_2 is one quantity for another).
  FormulaChange same{sym("S_2"), sym("S_2"), "vector-swap", sym("S_1"), sym("S_2")};
  EXPECT_FALSE(made_everywhere(same));
}

// Which object is hit first, under a change: three spheres along the x axis from the origin,
// listed "mid" (centre (7, 0, 0), r = 1: t = 6), "near" ((4, 0, 0), r = 1: t = 3) and "far"
// ((10, 1, 0), r = 2: t_ca = 10, d² = 1, t_hc = √3, t = 10 − √3 = 8.267949, N = (P − C)/r =
// (−0.866025, −0.5, 0)). "near" is hit first. The largest t for the smallest names "far" with
// its own hit (min → max of t_first); the first listed for the nearest names "mid" (the
// minimum left out, its first argument kept). Names compare as the grader compares them.
TEST(ChangeOperators, AnotherObjectHitFirstUnderAChange) {
  const char* problem = R"({"id": "first", "kind": "first-hit",
      "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]}, "objects": [
      {"name": "mid", "type": "sphere", "center": [7, 0, 0], "radius": 1},
      {"name": "near", "type": "sphere", "center": [4, 0, 0], "radius": 1},
      {"name": "far", "type": "sphere", "center": [10, 1, 0], "radius": 2}]})";
  Planted largest{
      "other-root",
      problem,
      {{"object", "Far"},
       {"hits",
        {{{"t", 8.267949}, {"point", {8.267949, 0, 0}}, {"normal", {-0.866025, -0.5, 0}}}}}},
      "t_first",
      "other-root"};
  EXPECT_EQ(explained_by(largest), "");
  Planted listed{
      "clamp",
      problem,
      {{"object", "mid"}, {"hits", {{{"t", 6}, {"point", {6, 0, 0}}, {"normal", {-1, 0, 0}}}}}},
      "t_first",
      "clamp"};
  EXPECT_EQ(explained_by(listed), "");
  // The far sphere's numbers with the near one's name fit no change.
  json mixed = {
      {"object", "near"},
      {"hits", {{{"t", 8.267949}, {"point", {8.267949, 0, 0}}, {"normal", {-0.866025, -0.5, 0}}}}}};
  ChangeSearch search(testing::problem(problem));
  EXPECT_NE(search.explain(mixed).verdict, Discovery::Verdict::kExplained);
}

}  // namespace change_operators_test
}  // namespace raygrade

namespace raygrade {
namespace change_operators_test {

// Air into glass (n1 = 1, n2 = 1.5, η = 2/3) along d = (1, −2, 0) at n = (0, 1, 0), worked on
// the angles: cos θi = 2/√5, θi = 26.565051°, sin θt = η·sin θi = 0.298142, θt = 17.346065°,
// t = sin θt·(1, 0, 0) − cos θt·(0, 1, 0) = (0.298142, −0.954521, 0).
constexpr const char* kIntoGlass = R"({"id": "refract", "kind": "refract",
    "direction": [1, -2, 0], "normal": [0, 1, 0], "n1": 1, "n2": 1.5})";

json refracted(double theta_i, double theta_t, double x, double y) {
  return {{"total_internal_reflection", false},
          {"angle_of_incidence", theta_i},
          {"angle_of_refraction", theta_t},
          {"direction", {x, y, 0}}};
}

TEST(ChangeOperators, TheAnglesOfSnellsLaw) {
  const Planted planted[] = {
      // The ratio applied to the angles (arcsin(η·sin θi) taken as η·arcsin(sin θi)):
      // θt = (2/3)·26.565051° = 17.710034°, t = (0.304200, −0.952608, 0).
      {"linear", kIntoGlass, refracted(26.565051, 17.710034, 0.304200, -0.952608), "theta_t",
       "linear"},
      // sin of θi in degrees read as radians: sin(26.565051) = 0.990426, sin θt = 0.660284,
      // θt = 41.321540°, t = (0.660284, −0.751016, 0).
      {"degrees", kIntoGlass, refracted(26.565051, 41.321540, 0.660284, -0.751016), "theta_t",
       "degrees"},
      // θi from the surface, 63.434949°, carried through: sin θt = (2/3)·0.894427 = 0.596285,
      // θt = 36.604276°, t = (0.596285, −0.802773, 0).
      {"function", kIntoGlass, refracted(63.434949, 36.604276, 0.596285, -0.802773), "theta_i",
       "function"},
      // cos for sin along the surface: t = cos θt·(1, 0, 0) − cos θt·(0, 1, 0)
      // = (0.954521, −0.954521, 0).
      {"sin-cos", kIntoGlass, refracted(26.565051, 17.346065, 0.954521, -0.954521), "t",
       "function"},
  };
  for (const Planted& p : planted) EXPECT_EQ(explained_by(p), "") << p.what;
}

}  // namespace change_operators_test
}  // namespace raygrade

namespace raygrade {
namespace change_operators_test {

// The triangle A = (0, 0, 0), B = (4, 0, 0), C = (0, 4, 0) with the normals N_a = (0, 0, 1),
// N_b = (0.6, 0, 0.8), N_c = (0, 0.6, 0.8) and the texture coordinates (0.5, 0), (1, 0.5),
// (0, 1), at P = (1.2, 0.8, 0): the area is ‖(0, 0, 16)‖/2 = 8, the areas across from A, B and
// C are 4, 2.4 and 1.6, so w = (0.5, 0.3, 0.2); n_s = (0.18, 0.12, 0.9), of length 0.925635,
// n̂ = (0.194461, 0.129641, 0.972306); u = 0.25 + 0.3 + 0 = 0.55, v = 0 + 0.15 + 0.2 = 0.35.
constexpr const char* kSmooth = R"({"id": "smooth", "kind": "interpolate",
    "vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]],
    "normals": [[0, 0, 1], [0.6, 0, 0.8], [0, 0.6, 0.8]],
    "texcoords": [[0.5, 0], [1, 0.5], [0, 1]], "point": [1.2, 0.8, 0]})";

json smooth(std::array<double, 3> w, std::array<double, 3> n, double u, double v) {
  return {{"barycentric", {w[0], w[1], w[2]}}, {"normal", {n[0], n[1], n[2]}}, {"u", u}, {"v", v}};
}

TEST(ChangeOperators, TheWeightsOfAFamilyGivenToOtherVertices) {
  const Planted planted[] = {
      // The weights of a, b, c given to c, a, b (w_b for a, w_c for b, w_a for c) in every
      // step that blends by them: w = (0.3, 0.2, 0.5), n_s = 0.3·N_a + 0.2·N_b + 0.5·N_c =
      // (0.12, 0.3, 0.86), of length 0.918695; u = 0.15 + 0.2 + 0 = 0.35, v = 0 + 0.1 + 0.5 = 0.6.
      {"rotate", kSmooth, smooth({0.3, 0.2, 0.5}, {0.130620, 0.326551, 0.936111}, 0.35, 0.6), "w",
       "rotate"},
      // u and v read from each other's column: u = 0.35, v = 0.55, the normal right.
      {"family-exchange", kSmooth,
       smooth({0.5, 0.3, 0.2}, {0.194461, 0.129641, 0.972306}, 0.35, 0.55), "u", "family-exchange"},
      // v from the other image origin: 1 − 0.35 = 0.65.
      {"complement", kSmooth, smooth({0.5, 0.3, 0.2}, {0.194461, 0.129641, 0.972306}, 0.55, 0.65),
       "v", "complement"},
  };
  for (const Planted& p : planted) EXPECT_EQ(explained_by(p), "") << p.what;
  // The areas not divided by the whole area, in all three weights (a change made in every step
  // of its form, w_x = area_x / area, the vertex letter its index): w = (4, 2.4, 1.6), the
  // normal right (a multiple of the blend), u = 2 + 2.4 + 0 = 4.4, v = 0 + 1.2 + 1.6 = 2.8.
  EXPECT_EQ(explained_everywhere(
                kSmooth, smooth({4, 2.4, 1.6}, {0.194461, 0.129641, 0.972306}, 4.4, 2.8), "w_a"),
            "");
}

// The same triangle hit at P = (1.2, 0.8, 0) from (1.2, 0.8, 5) along (0, 0, −1): t = 5, the
// normal (b − a) × (c − a) = (0, 0, 16) made unit, (0, 0, 1), and w = (0.5, 0.3, 0.2). Möller
// and Trumbore's (u, v) = (w_b, w_c) given as the weights of a and b, 1 − u − v = w_a as c's:
// (0.3, 0.2, 0.5), the weights rotated.
TEST(ChangeOperators, TheWeightsOfATriangleHitRotated) {
  Planted p{"rotate",
            R"({"id": "triangle", "ray": {"origin": [1.2, 0.8, 5], "direction": [0, 0, -1]},
                "object": {"type": "triangle", "vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]]}})",
            {{"hits",
              {{{"t", 5},
                {"point", {1.2, 0.8, 0}},
                {"normal", {0, 0, 1}},
                {"barycentric", {0.3, 0.2, 0.5}}}}}},
            "w",
            "rotate"};
  EXPECT_EQ(explained_by(p), "");
}

// A renaming at the level of formulas: the family w_a, w_b, w_c rotated by one in
// w_a·x + w_b·y + w_c·z is w_b·x + w_c·y + w_a·z; with w = (1, 2, 3) and x, y, z = 10, 100,
// 1000 that is 20 + 300 + 1000 = 1320 rather than 10 + 200 + 3000 = 3210. The same renaming is
// made in a step that names one of them (w_a + 7 → w_b + 7 = 9), not in one that names none.
TEST(ChangeOperators, AFamilyRenamedInEveryStepThatUsesIt) {
  Env values{{"w_a", Value(1.0)}, {"w_b", Value(2.0)}, {"w_c", Value(3.0)},
             {"x", Value(10.0)},  {"y", Value(100.0)}, {"z", Value(1000.0)}};
  std::map<std::string, E, std::less<>> symbols;
  for (const auto& [name, v] : values) symbols[name] = sym(name);
  ChangeScope scope{&values, &symbols};
  E f = sym("w_a") * sym("x") + sym("w_b") * sym("y") + sym("w_c") * sym("z");
  std::size_t left = count_step_changes(f, scope, ChangeTier::kOperands);
  std::vector<double> rotated;
  std::optional<FormulaChange> one;
  each_step_change(f, scope, ChangeTier::kOperands, left, [&](FormulaChange&& c) {
    if (c.kind != "rotate") return;
    rotated.push_back(evaluate(c.eval, values).scalar);
    if (rotated.back() == 1320) one = c;
  });
  // By one either way: w_c·x + w_a·y + w_b·z = 30 + 100 + 2000 = 2130.
  EXPECT_EQ(rotated, (std::vector<double>{1320, 2130}));
  ASSERT_TRUE(one.has_value());
  ASSERT_TRUE(renames(*one));
  std::optional<E> s = rename_everywhere(sym("w_a") + 7, one->from, one->to);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(evaluate(*s, values).scalar, 9);
  EXPECT_FALSE(rename_everywhere(sym("x") + 7, one->from, one->to).has_value());
}

// 1 − x for a step whose value lies strictly between 0 and 1 (0.35 → 0.65), none for one
// outside (2.5).
TEST(ChangeOperators, TheComplementOfANumberBetweenZeroAndOne) {
  Env values{{"a", Value(0.7)}, {"b", Value(0.5)}, {"c", Value(5.0)}};
  std::map<std::string, E, std::less<>> symbols{{"a", sym("a")}, {"b", sym("b")}, {"c", sym("c")}};
  ChangeScope scope{&values, &symbols};
  auto complements = [&](const E& f) {
    std::vector<double> out;
    std::size_t left = count_step_changes(f, scope, ChangeTier::kOperators);
    each_step_change(f, scope, ChangeTier::kOperators, left, [&](FormulaChange&& c) {
      if (c.kind == "complement") out.push_back(evaluate(c.eval, values).scalar);
    });
    return out;
  };
  std::vector<double> in = complements(sym("a") * sym("b"));
  ASSERT_EQ(in.size(), 1u);
  EXPECT_NEAR(in[0], 0.65, 1e-15);
  EXPECT_TRUE(complements(sym("b") * sym("c")).empty());
}

// Both polarizations' squares left out: n1 = 1, n2 = 2, θi = 60°, so cos θi = 0.5, sin θt =
// sin 60°/2 = √3/4, cos θt = √(1 − 3/16) = √13/4 = 0.901388. The amplitudes r_s = (0.5 −
// 2·0.901388)/(0.5 + 2·0.901388) = −0.565741 and r_p = (0.901388 − 1)/(0.901388 + 1) =
// −0.051863 answered as the reflectances, averaged: F = −0.308802. The square of one alone
// (R_s = r_s, R_p = r_p² = 0.002690) gives another F: only the change made in both fits.
TEST(ChangeOperators, TheSquareLeftOutOfBothPolarizations) {
  const char* fresnel = R"({"id": "fresnel", "kind": "fresnel", "model": "exact", "n1": 1,
      "n2": 2, "angle": 60})";
  json answer = {{"reflectance", -0.308802}, {"r_s", -0.565741}, {"r_p", -0.051863}};
  std::string rs = explained_everywhere(fresnel, answer, "R_s");
  std::string rp = explained_everywhere(fresnel, answer, "R_p");
  EXPECT_TRUE(rs.empty() || rp.empty()) << rs;
}

// Schlick's cosine of θt taken in degrees as radians: n1 = 1.5 into n2 = 1 at θi = 30°, sin θt
// = 1.5·0.5 = 0.75, θt = asin 0.75 = 48.590378°, R0 = (0.5/2.5)² = 0.04; cos(48.590378) in
// radians is −0.104119, F = 0.04 + 0.96·1.104119⁵ = 1.615256 (the right F is 0.044270).
TEST(ChangeOperators, SchlicksAngleInDegreesReadAsRadians) {
  Planted p{"degrees",
            R"({"id": "schlick", "kind": "fresnel", "model": "schlick", "n1": 1.5, "n2": 1,
                "angle": 30})",
            {{"reflectance", 1.615256}, {"transmittance", -0.615256}, {"r0", 0.04}},
            "F",
            "degrees"};
  EXPECT_EQ(explained_by(p), "");
}

}  // namespace change_operators_test
}  // namespace raygrade

namespace raygrade {
namespace change_operators_test {

// The clamp max(0, N·L) left out for every light, in its terms and in its verdict: over the
// floor N = (0, 1, 0) with the eye at (−3, 4, 0) (V = (−0.6, 0.8, 0)), light A at (3, 4, 0) has
// L = (0.6, 0.8, 0), N·L = 0.8, R = (−0.6, 0.8, 0) = V: diffuse 0.5·0.8 = 0.4, specular 0.3·1¹²
// = 0.3. Light C at (4, −3, 0) is below the horizon: L = (0.8, −0.6, 0), N·L = −0.6, R =
// (−0.8, −0.6, 0), R·V = 0. Without the clamp C reaches P and adds 0.5·(−0.6) = −0.3: diffuse
// 0.1, I = 0.2 + 0.1 + 0.3 = 0.6. The verdict "reaches" moves with the terms.
TEST(ChangeOperators, TheClampLeftOutOfEveryLightsTermsAndVerdict) {
  const char* shade = R"({"id": "s", "kind": "shade", "point": [0, 0, 0], "normal": [0, 1, 0],
      "eye": [-3, 4, 0], "ambient_light": 2,
      "material": {"ambient": 0.1, "diffuse": 0.5, "specular": 0.3, "shininess": 12},
      "lights": [{"name": "A", "position": [3, 4, 0]}, {"name": "C", "position": [4, -3, 0]}]})";
  json light_a = {{"light", "A"}, {"reaches", true}, {"n_dot_l", 0.8},
                  {"r_dot_v", 1}, {"diffuse", 0.4},  {"specular", 0.3}};
  json light_c = {{"light", "C"}, {"reaches", true}, {"n_dot_l", -0.6},
                  {"r_dot_v", 0}, {"diffuse", -0.3}, {"specular", 0}};
  json answer = {{"ambient", 0.2},
                 {"diffuse", 0.1},
                 {"specular", 0.3},
                 {"intensity", 0.6},
                 {"lights", {light_a, light_c}}};
  Problem p = testing::problem(shade);
  ChangeSearch search(p);
  Discovery d = search.explain(answer);
  std::string seen = to_string(d.verdict);
  bool clamp = false;
  for (const auto& c : d.changes) {
    clamp = clamp || (c.kind == "clamp" && c.everywhere);
    seen += " | " + c.kind + ": " + c.text();
  }
  EXPECT_TRUE(clamp) << seen;
  // The same numbers with C said not to reach P are the clamp left out of C's diffuse term
  // alone, not of its verdict.
  answer["lights"][1]["reaches"] = false;
  for (const auto& c : search.explain(answer).changes) EXPECT_FALSE(c.everywhere) << c.text();
}

}  // namespace change_operators_test
}  // namespace raygrade
