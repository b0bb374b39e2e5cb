// Kinds reflect, refract and shade: answers against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.h"

namespace raygrade {
namespace {

TEST(ReflectKind, NonUnitNormalIsNormalizedFirst) {
  Problem p = testing::problem(R"({"id": "r", "kind": "reflect",
    "direction": [1, -2, 0], "normal": [0, 5, 0]})");
  EXPECT_EQ(p.task->answer()["direction"], nlohmann::json({1.0, 2.0, 0.0}));
  auto parts = p.task->derive("");
  EXPECT_NE(parts[0].derivation.find("n_hat"), nullptr);
}

// From air into water (n = 4/3) at 60°: sin θt = (√3/2)/(4/3) = 3√3/8 ≈ 0.6495, θt ≈ 40.5°.
TEST(RefractKind, SnellAngles) {
  Problem p = testing::problem(R"({"id": "w", "kind": "refract",
    "direction": [0.8660254037844386, -0.5, 0], "normal": [0, 1, 0], "n1": 1, "n2": 1.3333333333333333})");
  nlohmann::json a = p.task->answer();
  EXPECT_FALSE(a["total_internal_reflection"].get<bool>());
  EXPECT_NEAR(a["angle_of_incidence"].get<double>(), 60, 1e-12);
  EXPECT_NEAR(a["angle_of_refraction"].get<double>(),
              std::asin(3 * std::sqrt(3.0) / 8) * 180 / 3.141592653589793, 1e-12);
  EXPECT_NEAR(a["direction"][0].get<double>(), 3 * std::sqrt(3.0) / 8, 1e-15);
  EXPECT_FALSE(a.contains("critical_angle"));
}

// The angles the conclusion states are steps of their own: θi = arccos(cos θi) = 60° and
// θt = arccos(√k) with k = 1 − (3/4)²·(1 − 1/4) = 37/64, the same angle as asin(3√3/8).
TEST(RefractKind, AnglesAreComputedBySteps) {
  Problem p = testing::problem(R"({"id": "w", "kind": "refract",
    "direction": [0.8660254037844386, -0.5, 0], "normal": [0, 1, 0], "n1": 1, "n2": 1.3333333333333333})");
  Derivation d = p.task->derive("")[0].derivation;
  const Step* theta_i = d.find("theta_i");
  const Step* theta_t = d.find("theta_t");
  ASSERT_NE(theta_i, nullptr);
  ASSERT_NE(theta_t, nullptr);
  EXPECT_NEAR(theta_i->value.scalar, 60, 1e-12);
  double expected = std::asin(3 * std::sqrt(3.0) / 8) * 180 / 3.141592653589793;
  EXPECT_NEAR(theta_t->value.scalar, expected, 1e-12);
  EXPECT_NEAR(std::cos(theta_t->value.scalar * 3.141592653589793 / 180), std::sqrt(37.0 / 64),
              1e-12);
  EXPECT_EQ(to_text(theta_t->formula), "arccos(√k)");
  EXPECT_EQ(to_text(theta_i->formula), "arccos(cos_i)");
  // The conclusion quotes the steps' values.
  ASSERT_FALSE(d.conclusion.empty());
  EXPECT_NE(d.conclusion[0].find("θi = 60°, θt = 40.5"), std::string::npos) << d.conclusion[0];
}

// From glass (1.5) into air at 60° (normal given pointing along the ray, so it is turned):
// sin θt would be 1.5·√3/2 ≈ 1.3: total internal reflection; the critical angle is 41.81°.
TEST(RefractKind, TotalInternalReflection) {
  Problem p = testing::problem(R"({"id": "g", "kind": "refract",
    "direction": [0.8660254037844386, 0.5, 0], "normal": [0, 1, 0], "n1": 1.5, "n2": 1})");
  nlohmann::json a = p.task->answer();
  EXPECT_TRUE(a["total_internal_reflection"].get<bool>());
  EXPECT_TRUE(a["direction"].is_null());
  EXPECT_NEAR(a["critical_angle"].get<double>(), 41.8103148957786, 1e-10);
  EXPECT_NEAR(a["reflected_direction"][1].get<double>(), -0.5, 1e-15);
  auto parts = p.task->derive("");
  ASSERT_FALSE(parts[0].derivation.conclusion.empty());
  EXPECT_NE(parts[0].derivation.conclusion[0].find("Total internal reflection"), std::string::npos);
}

// P = origin, N = y, eye at (−3, 4, 0): V = (−0.6, 0.8, 0). Light at (3, 4, 0):
// L = (0.6, 0.8, 0), N·L = 0.8, R = (−0.6, 0.8, 0) = V, R·V = 1.
// ambient 0.1·2 = 0.2; diffuse 0.5·1·0.8 = 0.4; specular 0.3·1·1 = 0.3; total 0.9.
// A second light is blocked: it adds nothing.
TEST(ShadeKind, TermByTerm) {
  Problem p = testing::problem(testing::kTwoLightShade);
  nlohmann::json a = p.task->answer();
  EXPECT_NEAR(a["ambient"].get<double>(), 0.2, 1e-15);
  EXPECT_NEAR(a["diffuse"].get<double>(), 0.4, 1e-15);
  EXPECT_NEAR(a["specular"].get<double>(), 0.3, 1e-14);
  EXPECT_NEAR(a["intensity"].get<double>(), 0.9, 1e-14);
  EXPECT_FALSE(a["lights"][1]["reaches"].get<bool>());
  auto parts = p.task->derive("");
  const Step* total = parts[0].derivation.find("I");
  ASSERT_NE(total, nullptr);
  EXPECT_NEAR(total->value.scalar, 0.9, 1e-14);
}

// The same point with k_s = 0: light A still gives its diffuse 0.4, and the specular term,
// whose coefficient is 0, is neither listed nor worked (no specular_1). R_1 is worked: the
// answer gives each light's R·V.
TEST(ShadeKind, NoSpecularTermWhenItsCoefficientIsZero) {
  std::string text = testing::kTwoLightShade;
  text.replace(text.find("\"specular\": 0.3"), 15, "\"specular\": 0  ");
  Problem p = testing::problem(text);
  nlohmann::json a = p.task->answer();
  EXPECT_EQ(a["terms"], nlohmann::json::array({"ambient", "diffuse"}));
  EXPECT_NEAR(a["intensity"].get<double>(), 0.6, 1e-15);
  auto parts = p.task->derive("");
  EXPECT_EQ(parts[0].derivation.find("specular_1"), nullptr);
  ASSERT_NE(parts[0].derivation.find("RV_1"), nullptr);
  EXPECT_NEAR(parts[0].derivation.find("RV_1")->value.scalar, 1, 1e-15);  // R = V
  const Step* total = parts[0].derivation.find("I");
  ASSERT_NE(total, nullptr);
  EXPECT_NEAR(total->value.scalar, 0.6, 1e-15);
}

TEST(ShadeKind, UnknownLightKeyIsAnError) {
  EXPECT_THROW(testing::problem(R"({"id": "s", "kind": "shade",
    "point": [0, 0, 0], "normal": [0, 1, 0], "eye": [0, 1, 0],
    "lights": [{"position": [3, 4, 0], "blockd": true}]})"),
               Error);
}

}  // namespace
}  // namespace raygrade
