// The operators of the mistake search, each by a slip planted in an answer to a real kind and
// worked out here by hand: the search must explain the answer by a change of that operator in
// that step (among the changes giving the same numbers). Without the operator the change is
// not among them and the test fails.
#include "grading/change_operators.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

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
