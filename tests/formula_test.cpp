// Formula: typed numbers and formulas, their digits, and faults pointing at the character.
#include "derivation/formula.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string_view>

namespace raygrade {
namespace {

double value_of(const char* text) {
  FormulaParse p = parse_formula(text);
  EXPECT_TRUE(p.ok) << text << ": " << p.message;
  return p.formula.evaluate();
}

TEST(Formula, NumbersAsStudentsTypeThem) {
  EXPECT_DOUBLE_EQ(value_of("7.27"), 7.27);
  EXPECT_DOUBLE_EQ(value_of("1/3"), 1.0 / 3);
  EXPECT_DOUBLE_EQ(value_of("sqrt(3)"), std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(value_of("9 - sqrt(3)"), 9 - std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(value_of("2*sqrt(2)"), 2 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(value_of("2sqrt(2)"), 2 * std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(value_of("-2^2"), -4);    // the power binds tighter than the sign
  EXPECT_DOUBLE_EQ(value_of("2^3^2"), 512);  // right-associative
  EXPECT_DOUBLE_EQ(value_of("2**-1"), 0.5);
  EXPECT_DOUBLE_EQ(value_of("1.5e-3"), 0.0015);
  EXPECT_DOUBLE_EQ(value_of("(1 + 2) * 3"), 9);
}

// Worked solutions print −, ·, ², √ and π; pasted back they read the same.
TEST(Formula, GlyphsFromWorkedSolutions) {
  EXPECT_DOUBLE_EQ(value_of("2\u00b7\u221a3"), 2 * std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(value_of("\u22121 + 3\u00b2"), 8);
  EXPECT_DOUBLE_EQ(value_of("\u03c0"), std::acos(-1.0));
  EXPECT_DOUBLE_EQ(value_of("6 \u00f7 4"), 1.5);
}

// Angles as exercises give them: sin 30° = 1/2, cos 60° = 1/2, atan2(1, −1) = 3π/4 = 135°,
// asin(1/2) = π/6, acos(0) = π/2, atan(1) = π/4.
TEST(Formula, InverseTrigonometryAndDegrees) {
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(value_of("sin(30deg)"), 0.5, 1e-15);
  EXPECT_NEAR(value_of("sin(30 deg)"), 0.5, 1e-15);
  EXPECT_NEAR(value_of("cos(60\u00b0)"), 0.5, 1e-15);
  EXPECT_NEAR(value_of("90\u00b0"), pi / 2, 1e-15);
  EXPECT_NEAR(value_of("asin(1/2)"), pi / 6, 1e-15);
  EXPECT_NEAR(value_of("acos(0)"), pi / 2, 1e-15);
  EXPECT_NEAR(value_of("atan(1)"), pi / 4, 1e-15);
  EXPECT_NEAR(value_of("atan2(1, -1)"), 3 * pi / 4, 1e-15);
  EXPECT_NEAR(value_of("2atan2(1, 1) + 45deg"), 3 * pi / 4, 1e-15);
  EXPECT_FALSE(parse_formula("atan2(1)").ok);
  EXPECT_FALSE(parse_formula("30degrees").ok);
}

// The control characters U+0001 to U+0004 are characters a student cannot mean as a formula:
// they are refused as such, never read as the glyphs √, ², ³ and π that the worked solutions
// print (sqrt(4) is 2, 3² is 9: had they been read so, "\x01" "4" would be 2).
TEST(Formula, ControlCharactersAreRefusedNotReadAsGlyphs) {
  for (const char* text : {"\x01"
                           "4",
                           "3\x02", "3\x03", "\x04", "2*\x04", "1\x1f", "1\x7f"}) {
    FormulaParse p = parse_formula(text);
    EXPECT_FALSE(p.ok) << "control character accepted in byte string of length "
                       << std::string_view(text).size();
    EXPECT_NE(p.message.find("control character"), std::string::npos) << p.message;
  }
  // A tab is blank space, as before.
  EXPECT_DOUBLE_EQ(value_of("1\t+\t2"), 3);
}

TEST(Formula, FaultsPointAtTheCharacter) {
  FormulaParse p = parse_formula("7.2.7");
  ASSERT_FALSE(p.ok);
  EXPECT_EQ(p.column, 4u);
  EXPECT_NE(p.message.find("decimal point"), std::string::npos);
  p = parse_formula("2*(3 + 1");
  ASSERT_FALSE(p.ok);
  EXPECT_EQ(p.column, 9u);
  EXPECT_NE(p.message.find("missing ')'"), std::string::npos);
  p = parse_formula("9 - sqrt 3");
  ASSERT_FALSE(p.ok);
  EXPECT_EQ(p.column, 10u);
  p = parse_formula("1 +");
  ASSERT_FALSE(p.ok);
  EXPECT_EQ(p.column, 4u);
  p = parse_formula("");
  ASSERT_FALSE(p.ok);
  // Columns count characters, not bytes: "−" is three bytes but one character.
  p = parse_formula("\u22121 $");
  ASSERT_FALSE(p.ok);
  EXPECT_EQ(p.column, 4u);
  EXPECT_FALSE(p.over_limit);  // a slip, given back as feedback
}

// "((...(1)...))", n parentheses deep.
std::string nested(int n) {
  std::string s(static_cast<std::size_t>(n), '(');
  s += '1';
  s.append(static_cast<std::size_t>(n), ')');
  return s;
}

// Beyond the limits is told apart from a slip (over_limit); either costs that answer alone.
TEST(Formula, LimitsAreToldApartFromSlips) {
  EXPECT_TRUE(parse_formula(std::string(1001, '1')).over_limit);
  std::string sum = "1";  // 1+1+...+1: 999 characters, within the limit
  while (sum.size() < 999) sum += "+1";
  EXPECT_TRUE(parse_formula(sum).ok);
  // The documented limit: 20 nested parentheses are read, 21 are not.
  EXPECT_TRUE(parse_formula(nested(20)).ok);
  EXPECT_TRUE(parse_formula(nested(21)).over_limit);
  FormulaParse deep = parse_formula(nested(30));
  EXPECT_FALSE(deep.ok);
  EXPECT_TRUE(deep.over_limit);
  // A fault before the depth limit is reached stays a slip.
  EXPECT_FALSE(parse_formula("((1 +) + 2)").over_limit);
}

TEST(Formula, NestingBombIsRefusedNotRecursed) {
  std::string deep(100000, '(');
  deep += "1";
  FormulaParse p = parse_formula(deep);
  EXPECT_FALSE(p.ok);
  std::string bomb(900, '-');
  bomb += "1";
  p = parse_formula(bomb);
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.message.find("parentheses deep"), std::string::npos);
  // The documented limit is 20 nested parentheses: 20 are read, 21 are not.
  std::string twenty(20, '(');
  twenty += '1';
  twenty.append(20, ')');
  FormulaParse at_limit = parse_formula(twenty);
  EXPECT_TRUE(at_limit.ok) << at_limit.message;
  EXPECT_EQ(at_limit.formula.evaluate(), 1);
  std::string over(21, '(');
  over += '1';
  over.append(21, ')');
  EXPECT_FALSE(parse_formula(over).ok);
  EXPECT_TRUE(parse_formula(over).over_limit);
}

TEST(Formula, TooLongIsRefused) {
  std::string s = "1";
  for (int i = 0; i < 600; ++i) s += "+1";
  FormulaParse p = parse_formula(s);
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.message.find("too long"), std::string::npos);
}

TEST(Formula, TypedDigits) {
  TypedDigits d = typed_digits("7.27");
  EXPECT_TRUE(d.literal);
  EXPECT_EQ(d.decimals, 2);
  EXPECT_EQ(d.significant, 3);
  d = typed_digits("-0.0050");
  EXPECT_EQ(d.decimals, 4);
  EXPECT_EQ(d.significant, 2);
  d = typed_digits("1.5e-3");
  EXPECT_EQ(d.decimals, 4);
  EXPECT_EQ(d.significant, 2);
  EXPECT_FALSE(typed_digits("1/3").literal);
  EXPECT_FALSE(typed_digits("sqrt(2)").literal);
}

TEST(Formula, SymbolsAndAliases) {
  SymbolTable t;
  t.add("px", {"p_x"});
  t.add("vx", {"v_x"});
  FormulaParse p = parse_formula("2*(p_x*vx) + px vx", &t);
  ASSERT_TRUE(p.ok) << p.message;
  EXPECT_DOUBLE_EQ(p.formula.evaluate({2, 5}), 30);
  p = parse_formula("2*pz", &t);
  ASSERT_FALSE(p.ok);
  EXPECT_EQ(p.column, 3u);
  EXPECT_NE(p.message.find("did you mean 'px'"), std::string::npos);
  // Without symbols a name is not a number.
  EXPECT_FALSE(parse_formula("px").ok);
}

}  // namespace
}  // namespace raygrade
