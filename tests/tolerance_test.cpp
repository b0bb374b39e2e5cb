// Tolerances: each mode just inside and just outside its boundary, and insufficient precision.
#include "grading/tolerance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "grading/answer_reader.h"
#include "test_util.h"

namespace raygrade {
namespace {

StudentNumber typed(const char* text) {
  auto n = parse_student_number(text);
  EXPECT_TRUE(n.value) << n.fault;
  return *n.value;
}

Match match(const char* text, double ref, const Tolerance& t) {
  return compare_number(typed(text), ref, ref, t).match;
}

// Relative 0.1% plus 1e-6 of 10 allows 0.010001.
TEST(Tolerance, RelAbsBoundary) {
  Tolerance t;
  EXPECT_EQ(match("10.0099", 10, t), Match::kRight);
  EXPECT_EQ(match("9.9901", 10, t), Match::kRight);
  EXPECT_EQ(match("10.0101", 10, t), Match::kWrong);
  t.rtol = 0;
  t.atol = 0.5;
  EXPECT_EQ(match("0.4999", 0, t), Match::kRight);
  EXPECT_EQ(match("0.5001", 0, t), Match::kWrong);
}

// Two decimal places: within 0.51 of the last place, 0.0051.
TEST(Tolerance, DecimalsBoundary) {
  Tolerance t;
  t.mode = ToleranceMode::kDecimals;
  t.digits = 2;
  double ref = 9 - std::sqrt(3.0) - 0;  // 7.26795 (seed 001, sphere 3)
  EXPECT_EQ(match("7.27", ref, t), Match::kRight);
  EXPECT_EQ(match("7.2730", ref, t), Match::kRight);  // 0.00505 off
  EXPECT_EQ(match("7.2732", ref, t), Match::kWrong);  // 0.00525 off
  EXPECT_EQ(match("7.26", ref, t), Match::kWrong);    // truncated, not rounded
}

// Three significant figures of 123.456: within 0.51.
TEST(Tolerance, SigFigsBoundary) {
  Tolerance t;
  t.mode = ToleranceMode::kSigFigs;
  t.digits = 3;
  EXPECT_EQ(match("123", 123.456, t), Match::kRight);
  EXPECT_EQ(match("123.96", 123.456, t), Match::kRight);  // 0.504 off
  EXPECT_EQ(match("123.97", 123.456, t), Match::kWrong);  // 0.514 off
  EXPECT_EQ(match("0.00123", 0.0012345, t), Match::kRight);
  EXPECT_EQ(match("0.00124", 0.0012345, t), Match::kWrong);  // 5.5e-6 > 5.1e-6
}

TEST(Tolerance, InsufficientPrecision) {
  Tolerance t;
  t.mode = ToleranceMode::kDecimals;
  t.digits = 2;
  double ref = 9 - std::sqrt(3.0);
  NumberVerdict v = compare_number(typed("7.3"), ref, ref, t);
  EXPECT_EQ(v.match, Match::kInsufficientPrecision);
  EXPECT_NE(v.message.find("2 decimal places"), std::string::npos);
  EXPECT_EQ(match("7.4", ref, t), Match::kWrong);  // wrong even at one decimal
  // By the default relative 0.1%, 0.71 is 1/√2 to two decimals but not precise enough.
  Tolerance d;
  double h = 1 / std::sqrt(2.0);
  EXPECT_EQ(match("0.71", h, d), Match::kInsufficientPrecision);
  EXPECT_EQ(match("0.7071", h, d), Match::kRight);
  EXPECT_EQ(match("0.72", h, d), Match::kWrong);
  // An exact expression is never "too few digits".
  EXPECT_EQ(match("1/3", 1.0 / 3, t), Match::kRight);
  EXPECT_EQ(match("2/3", 0.7, t), Match::kWrong);
}

TEST(Tolerance, VectorsRelativeToTheirLength) {
  Tolerance t;  // 0.1% of |(0, 0, 7.2679)|: 0.00727
  StudentNumber s[3] = {typed("0.007"), typed("0"), typed("7.2679")};
  EXPECT_EQ(compare_vector(s, {0, 0, 7.2679}, t).match, Match::kRight);
  s[0] = typed("0.008");
  EXPECT_EQ(compare_vector(s, {0, 0, 7.2679}, t).match, Match::kWrong);
}

// A point far from the origin: |(1e300, 1e300, 0)| is about 1.414e300, so 0.1% of it allows
// about 1.4e297 in each component. Squaring a component overflows double (1e600); a length
// computed by squaring would be infinite and allow anything.
TEST(Tolerance, AHugePointKeepsItsTolerance) {
  Tolerance t;
  StudentNumber right[3] = {typed("1.0001e300"), typed("1e300"), typed("0")};
  EXPECT_EQ(compare_vector(right, {1e300, 1e300, 0}, t).match, Match::kRight);
  StudentNumber wrong[3] = {typed("1.1e300"), typed("1e300"), typed("0")};
  EXPECT_EQ(compare_vector(wrong, {1e300, 1e300, 0}, t).match, Match::kWrong);
  StudentNumber top[3] = {typed("1.0000001e308"), typed("0"), typed("0")};
  EXPECT_EQ(compare_vector(top, {1e308, 0, 0}, t).match, Match::kRight);  // within 0.1%
  StudentNumber off[3] = {typed("1.7e308"), typed("0"), typed("0")};
  EXPECT_EQ(compare_vector(off, {1e308, 0, 0}, t).match, Match::kWrong);
  // A direction typed with huge components is still a direction: (1e300, 1e300, 0) is (1, 1, 0).
  StudentNumber big[3] = {typed("1e300"), typed("1e300"), typed("0")};
  DirectionVerdict d = compare_direction(big, {1, 1, 0}, t);
  EXPECT_EQ(d.verdict.match, Match::kRight);
  EXPECT_NEAR(d.length, std::sqrt(2.0) * 1e300, 1e286);
}

TEST(Tolerance, ReadFromProblem) {
  Problem p = testing::problem(R"({"id": "x", "precision": 2,
    "tolerance": {"t": {"sigfigs": 4}, "normal": {"rtol": 0.01}},
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  TolerancePolicy tp = read_tolerance_policy(p);
  EXPECT_EQ(tp.base.mode, ToleranceMode::kDecimals);  // from precision
  EXPECT_EQ(tp.for_field("t").mode, ToleranceMode::kSigFigs);
  EXPECT_EQ(tp.for_field("t").digits, 4);
  EXPECT_EQ(tp.for_field("normal").mode, ToleranceMode::kRelAbs);
  EXPECT_DOUBLE_EQ(tp.for_field("normal").rtol, 0.01);
  EXPECT_EQ(tp.for_field("point").mode, ToleranceMode::kDecimals);
}

TEST(Tolerance, FaultyToleranceNamesItsPath) {
  Problem p = testing::problem(R"({"id": "x", "tolerance": {"t": {"sigfig": 3}},
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  try {
    read_tolerance_policy(p);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().path, "/tolerance/t/sigfig");
    EXPECT_NE(e.diagnostic().message.find("sigfigs"), std::string::npos);
  }
}

// Feedback shows a reference at the precision it is graded to: graded to 5 decimals,
// 0.876771 shows as 0.87677 (not the four significant figures 0.8768, which cannot show why
// 0.8768 typed is wrong); to 6 significant figures, 0.876771; never fewer digits than usual.
TEST(Tolerance, FeedbackShowsTheDigitsItGrades) {
  Tolerance five_decimals{ToleranceMode::kDecimals, 0, 0, 5, 0};
  EXPECT_EQ(format_number(0.876771, shown_at(five_decimals, 0.876771, {})), "0.87677");
  Tolerance six_figures{ToleranceMode::kSigFigs, 0, 1e-9, 6, 0};
  EXPECT_EQ(format_number(0.876771, shown_at(six_figures, 0.876771, {})), "0.876771");
  EXPECT_EQ(format_number(1234.5678, shown_at(six_figures, 1234.5678, {})), "1234.57");
  // The default tolerance (1e-3 relative) needs no more than four significant figures.
  Tolerance usual;
  EXPECT_EQ(format_number(7.26795, shown_at(usual, 7.26795, {})), "7.268");
  // Coarser grading than the usual display keeps the usual display.
  Tolerance two_decimals{ToleranceMode::kDecimals, 0, 0, 2, 0};
  EXPECT_EQ(format_number(7.26795, shown_at(two_decimals, 7.26795, {})), "7.268");
}

}  // namespace
}  // namespace raygrade
