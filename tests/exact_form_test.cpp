// Exact forms of numbers (9 − √3, 1/6) and how formulas show negative numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "derivation/expr.h"
#include "derivation/number_format.h"

namespace raygrade {
namespace {

std::string exact(double v) {
  auto x = exact_form(v);
  return x ? exact_text(*x) : "none";
}

// Seed 001's third sphere: t_hc = √3 and t0 = 9 − √3 = 7.2679…
TEST(ExactForm, RecognisesSeedRoots) {
  EXPECT_EQ(exact(std::sqrt(3.0)), "√3");
  EXPECT_EQ(exact(9 - std::sqrt(3.0)), "9 − √3");
  EXPECT_EQ(exact(9 + std::sqrt(3.0)), "9 + √3");
  EXPECT_EQ(exact((18 - std::sqrt(12.0)) / 2), "9 − √3");  // the algebraic method's route
}

TEST(ExactForm, ReducesRadicandsAndFractions) {
  EXPECT_EQ(exact(std::sqrt(12.0)), "2√3");
  EXPECT_EQ(exact(-std::sqrt(2.0)), "−√2");
  EXPECT_EQ(exact((1 + std::sqrt(5.0)) / 2), "(1 + √5)/2");
  EXPECT_EQ(exact(1.0 / 6), "1/6");
  EXPECT_EQ(exact(-2.0 / 3), "−2/3");
  EXPECT_EQ(exact(0.5 * std::sqrt(2.0)), "√2/2");
}

// Integers and short decimals are written as they are; numbers with no small exact form too.
TEST(ExactForm, LeavesOrdinaryNumbersAlone) {
  EXPECT_EQ(exact(7), "none");
  EXPECT_EQ(exact(0.5), "none");
  EXPECT_EQ(exact(1.25), "none");
  EXPECT_EQ(exact(M_PI), "none");
  EXPECT_EQ(exact(0.1234567891), "none");
  EXPECT_EQ(exact(std::sqrt(3.0) + 1e-7), "none");  // close to 1 + … but not within rounding
  EXPECT_EQ(exact(std::sqrt(97.0)), "none");        // radicand too large to be "natural"
}

TEST(ExactForm, ValuesShowBothForms) {
  RenderOptions o;
  o.exact = true;
  EXPECT_EQ(value_text(9 - std::sqrt(3.0), o), "9 − √3 ≈ 7.268");
  o.numbers.decimals = 2;
  EXPECT_EQ(value_text(9 - std::sqrt(3.0), o), "9 − √3 ≈ 7.27");
  EXPECT_EQ(value_latex(9 - std::sqrt(3.0), o), "9 - \\sqrt{3} \\approx 7.27");
  EXPECT_EQ(value_text(2, o), "2");
}

// 125 − √125² in doubles is −1.42e-14 (5√5 rounds up): a zero up to rounding. It prints as an
// exact 0, never "0 ≈ 0", and needs no parentheses where it is substituted: √(1 − 0).
TEST(ExactForm, ZeroUpToRoundingIsAnExactZero) {
  double d2 = 125 - std::sqrt(125.0) * std::sqrt(125.0);
  ASSERT_NE(d2, 0);
  ASSERT_LT(std::abs(d2), 1e-13);
  EXPECT_EQ(exact(d2), "none");
  EXPECT_EQ(exact(1e-13), "none");
  EXPECT_EQ(exact(3e-12), "none");  // within 1e-11 of the fraction 0/2
  EXPECT_EQ(exact(1 - 2e-16), "none");
  RenderOptions o;
  o.exact = true;
  EXPECT_EQ(value_text(d2, o), "0");
  EXPECT_EQ(value_latex(d2, o), "0");
  Env env{{"r2", Value(1.0)}, {"d2", Value(d2)}};
  RenderOptions subst{&env, {}};
  EXPECT_EQ(to_text(sqrt(sym("r2") - sym("d2")), subst), "√(1 − 0)");
  EXPECT_EQ(to_latex(sym("r2") - sym("d2"), subst), "1 - 0");
  EXPECT_FALSE(prints_negative(d2));
  EXPECT_TRUE(prints_negative(-1e-3));
  EXPECT_TRUE(prints_negative(-std::numeric_limits<double>::infinity()));
}

// Negative numbers substituted into a formula get parentheses unless they lead it.
TEST(ExprRender, NegativeNumbersInParentheses) {
  Env env{{"b", Value(-20.0)}, {"a", Value(1.0)}, {"x", Value(-3.0)}, {"D", Value(-6.0)}};
  RenderOptions subst{&env, {}};
  EXPECT_EQ(to_text(-sym("b"), subst), "−(−20)");
  EXPECT_EQ(to_text(square(sym("b")) - 4 * sym("a"), subst), "(−20)² − 4 · 1");
  EXPECT_EQ(to_text(sym("a") + sym("x") * sym("a"), subst), "1 + (−3) · 1");
  EXPECT_EQ(to_text(sym("x") * sym("a"), subst), "−3 · 1");
  EXPECT_EQ(to_text(sym("a") - sym("D"), subst), "1 − (−6)");
  EXPECT_EQ(to_latex(sym("a") - sym("D"), subst), "1 - \\left(-6\\right)");
}

TEST(ExprRender, SymbolShownAsFormula) {
  E n = sym("N"), r = sym("R");
  E den = sym("denominator", dot(n, r));
  EXPECT_EQ(to_text(den), "N · R");
  EXPECT_EQ(to_text(sym("t") / den), "t / (N · R)");
  Env env{{"denominator", Value(-1.0)}, {"t", Value(2.0)}};
  RenderOptions subst{&env, {}};
  EXPECT_EQ(to_text(sym("t") / den, subst), "2 / (−1)");
}

// d × u for d = (0, 0, −1), u = (0, 1, 0) (seed 004): ⟨d_y u_z − d_z u_y, d_z u_x − d_x u_z,
// d_x u_y − d_y u_x⟩ = ⟨0·0 − (−1)·1, (−1)·0 − 0·0, 0·1 − 0·0⟩ = ⟨1, 0, 0⟩.
TEST(ExprRender, CrossProductWrittenOut) {
  Env env{{"d", Value(Vec3d{0, 0, -1})}, {"u", Value(Vec3d{0, 1, 0})}};
  E c = cross_written_out(sym("d"), sym("u"));
  EXPECT_EQ(to_text(c), "d × u");
  RenderOptions subst{&env, {}};
  EXPECT_EQ(to_text(c, subst), "⟨0 · 0 − (−1) · 1, −1 · 0 − 0 · 0, 0 · 1 − 0 · 0⟩");
  EXPECT_EQ(evaluate(c, env).vector, Vec3d(1, 0, 0));
}

}  // namespace
}  // namespace raygrade
