// SoftFloat against values derived by hand, and bit for bit against MPFR on random operands.
#include "math/soft_float.h"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace raygrade {
namespace {

constexpr Rounding kNear = Rounding::kNearest;

// 1/3 = 6004799503160661·2^-54 + 2^-54/3: to nearest and down the first, up the next double.
TEST(SoftFloat, OneThirdRoundsEachWay) {
  SoftFloat one(1.0, 53), three(3.0, 53);
  double third = 6004799503160661.0 * 0x1p-54;
  EXPECT_EQ(SoftFloat::div(one, three, 53, kNear).to_double(kNear), third);
  EXPECT_EQ(SoftFloat::div(one, three, 53, Rounding::kDown).to_double(kNear), third);
  EXPECT_EQ(SoftFloat::div(one, three, 53, Rounding::kUp).to_double(kNear),
            std::nextafter(third, 1.0));
  // At 200 bits the quotient is above the double by 2^-54/3 within 2^-200.
  SoftFloat wide = SoftFloat::div(one, three, 200, kNear);
  SoftFloat tail = SoftFloat::sub(wide, SoftFloat(third, 53), 200, kNear);
  EXPECT_DOUBLE_EQ(tail.to_double(kNear), 0x1p-54 / 3);
}

// sqrt(2) = 1.41421356237309504880...; the nearest double, 6369051672525773·2^-52 =
// 1.41421356237309514547..., is above it: rounding up gives it too, rounding down the one before.
TEST(SoftFloat, SquareRootOfTwo) {
  SoftFloat two(2.0, 53);
  double nearest = 6369051672525773.0 * 0x1p-52;
  EXPECT_EQ(SoftFloat::sqrt(two, 53, kNear).to_double(kNear), nearest);
  EXPECT_EQ(SoftFloat::sqrt(two, 53, Rounding::kUp).to_double(kNear), nearest);
  EXPECT_EQ(SoftFloat::sqrt(two, 53, Rounding::kDown).to_double(kNear),
            std::nextafter(nearest, 1.0));
  EXPECT_TRUE(SoftFloat::sqrt(SoftFloat(-1.0, 53), 53, kNear).is_nan());
}

// 1 + 2^-150 − 1 is 2^-150 at 200 bits, 0 at 53; a tiny addend still steers directed rounding.
TEST(SoftFloat, SmallAddendsAndDirectedRounding) {
  SoftFloat one(1.0, 53), tiny(0x1p-150, 53);
  SoftFloat sum = SoftFloat::add(one, tiny, 200, kNear);
  EXPECT_EQ(SoftFloat::sub(sum, one, 200, kNear).to_double(kNear), 0x1p-150);
  EXPECT_EQ(SoftFloat::add(one, tiny, 53, kNear).to_double(kNear), 1.0);
  EXPECT_EQ(SoftFloat::add(one, tiny, 53, Rounding::kUp).to_double(kNear), 1.0 + 0x1p-52);
  EXPECT_EQ(SoftFloat::sub(one, tiny, 53, Rounding::kDown).to_double(kNear), 1.0 - 0x1p-53);
  EXPECT_EQ(SoftFloat::sub(one, tiny, 53, Rounding::kUp).to_double(kNear), 1.0);
}

// Conversions to double near the ends of its range: 2^-1075 is half the smallest subnormal.
TEST(SoftFloat, ConversionToDoubleAtTheEndsOfTheRange) {
  SoftFloat half_min = SoftFloat::mul(SoftFloat(0x1p-1000, 53), SoftFloat(0x1p-75, 53), 53, kNear);
  EXPECT_EQ(half_min.to_double(kNear), 0.0);  // a tie, to the even zero
  EXPECT_EQ(half_min.to_double(Rounding::kUp), 0x1p-1074);
  SoftFloat huge = SoftFloat::mul(SoftFloat(0x1p1000, 53), SoftFloat(0x1p100, 53), 53, kNear);
  EXPECT_EQ(huge.to_double(kNear), std::numeric_limits<double>::infinity());
  EXPECT_EQ(huge.to_double(Rounding::kDown), std::numeric_limits<double>::max());
}

// The doubles whose sum is x exactly (each the nearest to what is left), at most `n` of them.
std::vector<double> expansion(const SoftFloat& x) {
  std::vector<double> out;
  SoftFloat rest = x;
  for (int k = 0; k < 200 && rest.is_finite(); ++k) {
    double d = rest.to_double(kNear);
    out.push_back(d);
    if (d == 0) break;
    rest = SoftFloat::sub(rest, SoftFloat(d, 53), 20000, kNear);
  }
  return out;
}

std::vector<double> expansion(mpfr_srcptr x) {
  std::vector<double> out;
  mpfr_t rest;
  mpfr_init2(rest, 20000);
  mpfr_set(rest, x, MPFR_RNDN);
  for (int k = 0; k < 200 && mpfr_number_p(rest); ++k) {
    double d = mpfr_get_d(rest, MPFR_RNDN);
    out.push_back(d);
    if (d == 0) break;
    mpfr_sub_d(rest, rest, d, MPFR_RNDN);
  }
  mpfr_clear(rest);
  return out;
}

// Random operands of every magnitude, some sums of two (more bits than a double), through
// every operation and rounding at 64, 256 and 4096 bits: the same value as MPFR's, bit for bit.
TEST(SoftFloat, AgreesWithMpfrBitForBit) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  const Rounding roundings[] = {Rounding::kNearest, Rounding::kDown, Rounding::kUp};
  const mpfr_rnd_t modes[] = {MPFR_RNDN, MPFR_RNDD, MPFR_RNDU};
  int compared = 0;
  for (int bits : {64, 256, 4096}) {
    int trials = bits == 4096 ? 20 : 150;  // a 4096-bit division costs as much as 150 others
    for (int trial = 0; trial < trials; ++trial) {
      double a1 = std::ldexp(mantissa(rng), exponent(rng)), a2 = std::ldexp(mantissa(rng), -400);
      double b1 = std::ldexp(mantissa(rng), exponent(rng) / 4), b2 = 0;
      if (trial % 3 == 0) b2 = b1 * 0x1p-70;
      if (trial % 7 == 0) b1 = a1;  // cancellation
      SoftFloat sa = SoftFloat::add(SoftFloat(a1, 53), SoftFloat(a2, 53), bits, kNear);
      SoftFloat sb = SoftFloat::add(SoftFloat(b1, 53), SoftFloat(b2, 53), bits, kNear);
      mpfr_t ma, mb, mr;
      mpfr_inits2(bits, ma, mb, mr, static_cast<mpfr_ptr>(nullptr));
      mpfr_set_d(ma, a1, MPFR_RNDN);
      mpfr_add_d(ma, ma, a2, MPFR_RNDN);
      mpfr_set_d(mb, b1, MPFR_RNDN);
      mpfr_add_d(mb, mb, b2, MPFR_RNDN);
      ASSERT_EQ(expansion(sa), expansion(ma));
      for (int k = 0; k < 3; ++k) {
        Rounding r = roundings[k];
        auto check = [&](const SoftFloat& s, const char* op) {
          EXPECT_EQ(expansion(s), expansion(mr)) << op << " " << bits << " bits, trial " << trial;
          EXPECT_EQ(s.to_double(Rounding::kDown), mpfr_get_d(mr, MPFR_RNDD)) << op;
          EXPECT_EQ(s.to_double(Rounding::kUp), mpfr_get_d(mr, MPFR_RNDU)) << op;
          ++compared;
        };
        mpfr_add(mr, ma, mb, modes[k]);
        check(SoftFloat::add(sa, sb, bits, r), "add");
        mpfr_sub(mr, ma, mb, modes[k]);
        check(SoftFloat::sub(sa, sb, bits, r), "sub");
        mpfr_mul(mr, ma, mb, modes[k]);
        check(SoftFloat::mul(sa, sb, bits, r), "mul");
        mpfr_div(mr, ma, mb, modes[k]);
        check(SoftFloat::div(sa, sb, bits, r), "div");
        mpfr_abs(mr, ma, MPFR_RNDN);
        mpfr_sqrt(mr, mr, modes[k]);
        check(SoftFloat::sqrt(SoftFloat::abs(sa, bits), bits, r), "sqrt");
      }
      mpfr_clears(ma, mb, mr, static_cast<mpfr_ptr>(nullptr));
    }
  }
  EXPECT_EQ(compared, (150 + 150 + 20) * 3 * 5);
}

}  // namespace
}  // namespace raygrade
