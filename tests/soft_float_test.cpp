// SoftFloat against values derived by hand, and bit for bit against MPFR on random operands.
#include "math/soft_float.h"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <ctime>
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

// The same double: both NaN (whatever their signs), or equal with the same sign (±0 apart).
bool same(double x, double y) {
  if (std::isnan(x) || std::isnan(y)) return std::isnan(x) && std::isnan(y);
  return x == y && std::signbit(x) == std::signbit(y);
}

// Operands a (the sum of a1 and a2) and b (of b1 and b2), each rounded to `bits`, through every
// operation in every rounding at `bits`, against MPFR: the same value bit for bit (as the exact
// sum of doubles it expands to) and the same conversions to double down and up. Returns the
// number of results compared.
int compare_with_mpfr(double a1, double a2, double b1, double b2, int bits, const char* what) {
  const Rounding roundings[] = {Rounding::kNearest, Rounding::kDown, Rounding::kUp};
  const mpfr_rnd_t modes[] = {MPFR_RNDN, MPFR_RNDD, MPFR_RNDU};
  int compared = 0;
  SoftFloat sa = SoftFloat::add(SoftFloat(a1, 53), SoftFloat(a2, 53), bits, kNear);
  SoftFloat sb = SoftFloat::add(SoftFloat(b1, 53), SoftFloat(b2, 53), bits, kNear);
  mpfr_t ma, mb, mr;
  mpfr_inits2(bits, ma, mb, mr, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(ma, a1, MPFR_RNDN);
  mpfr_add_d(ma, ma, a2, MPFR_RNDN);
  mpfr_set_d(mb, b1, MPFR_RNDN);
  mpfr_add_d(mb, mb, b2, MPFR_RNDN);
  EXPECT_EQ(expansion(sa), expansion(ma)) << what;
  for (int k = 0; k < 3; ++k) {
    Rounding r = roundings[k];
    auto check = [&](const SoftFloat& s, const char* op) {
      EXPECT_EQ(expansion(s), expansion(mr)) << op << " " << bits << " bits, " << what;
      EXPECT_TRUE(same(s.to_double(Rounding::kDown), mpfr_get_d(mr, MPFR_RNDD))) << op << " " << what;
      EXPECT_TRUE(same(s.to_double(Rounding::kUp), mpfr_get_d(mr, MPFR_RNDU))) << op << " " << what;
      EXPECT_TRUE(same(s.to_double(kNear), mpfr_get_d(mr, MPFR_RNDN))) << op << " " << what;
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
  // The comparison, as the ladder's sign tests use it: exactly −1, 0 or 1.
  bool unordered = false;
  int c = SoftFloat::compare(sa, sb, unordered);
  EXPECT_EQ(c, mpfr_cmp(ma, mb) > 0 ? 1 : mpfr_cmp(ma, mb) < 0 ? -1 : 0) << what;
  EXPECT_FALSE(unordered);
  mpfr_clears(ma, mb, mr, static_cast<mpfr_ptr>(nullptr));
  return compared;
}

// Random operands of every magnitude, some sums of two (more bits than a double), some
// cancelling, through every operation and rounding at precisions from 2 to 4096 bits.
TEST(SoftFloat, AgreesWithMpfrBitForBit) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  int compared = 0;
  for (int bits : {2, 24, 53, 64, 113, 256, 4096}) {
    for (int trial = 0; trial < 150; ++trial) {
      double a1 = std::ldexp(mantissa(rng), exponent(rng)), a2 = std::ldexp(mantissa(rng), -400);
      double b1 = std::ldexp(mantissa(rng), exponent(rng) / 4), b2 = 0;
      if (trial % 3 == 0) b2 = b1 * 0x1p-70;
      if (trial % 7 == 0) b1 = a1;  // cancellation
      compared += compare_with_mpfr(a1, a2, b1, b2, bits, "random");
    }
  }
  EXPECT_EQ(compared, 7 * 150 * 3 * 5);
}

// The cases where a rounding is decided by its last bits: exact quotients and square roots (no
// sticky bit), ties at 53 bits (1 + 2^-53 and 1 + 3·2^-53, which go to the even neighbour),
// results just above and below a tie, a sum whose carry makes a new top bit, an addend far below
// the other, zeros of both signs, and results at the ends of the double range (subnormal, the
// largest double, overflow).
TEST(SoftFloat, AgreesWithMpfrOnTiesExactResultsAndTheEndsOfTheRange) {
  struct Case {
    double a1, a2, b1, b2;
    const char* what;
  };
  const Case cases[] = {
      {6.0, 0, 3.0, 0, "exact quotient"},
      {9.0, 0, 1.0, 0, "perfect square"},
      {0x1p-1074, 0, 0x1p-1074, 0, "smallest subnormals"},
      {1.0, 0x1p-53, 1.0, 0, "1 + 2^-53, a tie"},
      {1.0, 3 * 0x1p-53, 1.0, 0, "1 + 3·2^-53, a tie to the even above"},
      {1.0, 0x1p-53, 0x1p-120, 0, "just above a tie"},
      {1.0, 0x1p-53, -0x1p-120, 0, "just below a tie"},
      {1.0, -0x1p-54, 1.0, 0x1p-53, "cancellation near 1"},
      {0x1.fffffffffffffp0, 0, 0x1p-52, 0, "a carry into a new top bit"},
      {1.0, 0, 0x1p-1000, 0, "an addend far below"},
      {-1.0, 0, 0x1p-1000, 0, "a negative value and a far smaller addend"},
      {0.0, 0, -0.0, 0, "zeros of both signs"},
      {0x1.fffffffffffffp1023, 0x1p970, 2.0, 0, "beyond the largest double"},
      {0x1p-1022, -0x1p-1074, 0x1p-1, 0, "a subnormal quotient"},
      {0x1p-1074, 0, 3.0, 0, "a third of the smallest subnormal"},
      {2.0, 0, 0x1p-1070, 0, "an overflowing quotient"},
  };
  for (int bits : {2, 53, 54, 64, 256, 4096}) {
    for (const Case& c : cases) compare_with_mpfr(c.a1, c.a2, c.b1, c.b2, bits, c.what);
  }
}

// The square root of an exact square is exact in every rounding: x = 1/3 to 2048 bits, x² exact
// at 4096, √(x²) at 2048 bits is x itself whichever way it rounds; at 2047 bits, x's last bit
// goes, so up and down differ by one unit of the 2047th bit.
TEST(SoftFloat, SquareRootOfAnExactSquare) {
  SoftFloat x = SoftFloat::div(SoftFloat(1.0, 53), SoftFloat(3.0, 53), 2048, kNear);
  SoftFloat square = SoftFloat::mul(x, x, 4096, kNear);
  for (Rounding r : {Rounding::kNearest, Rounding::kDown, Rounding::kUp}) {
    bool unordered = true;
    EXPECT_EQ(SoftFloat::compare(SoftFloat::sqrt(square, 2048, r), x, unordered), 0);
    EXPECT_FALSE(unordered);
  }
  SoftFloat down = SoftFloat::sqrt(square, 2047, Rounding::kDown);
  SoftFloat up = SoftFloat::sqrt(square, 2047, Rounding::kUp);
  bool unordered = true;
  EXPECT_EQ(SoftFloat::compare(down, x, unordered), -1);
  EXPECT_EQ(SoftFloat::compare(up, x, unordered), 1);
  // 1/3 = 0.0101…₂: its 2048 bits start at 2^-2, so the 2047th is worth 2^-2048.
  SoftFloat gap = SoftFloat::sub(up, down, 4096, kNear);
  EXPECT_EQ(gap.to_double(kNear), 0.0);
  EXPECT_EQ(SoftFloat::mul(gap, SoftFloat(0x1p1000, 53), 64, kNear).to_double(kNear) * 0x1p1000 *
                0x1p48,
            1.0);
}

// The top rung of the ladder divides and takes square roots at 4096 bits. Measured on one core
// (of a loaded machine), 2,000 of each take MPFR about 7 ms, SoftFloat on cpp_int about 0.12 s,
// and took the hand-written bit-by-bit arithmetic before it 15 s: the bound of 1 s of CPU time
// (so a loaded machine does not fail it) tells the two apart.
TEST(SoftFloat, DivisionAndSquareRootAt4096BitsAreFast) {
  std::mt19937_64 rng(52);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  SoftFloat one(1.0, 4096);
  std::vector<SoftFloat> xs;
  xs.reserve(20);
  for (int k = 0; k < 20; ++k) {
    // A full 4096-bit operand: 1 / (a double), which does not terminate in binary.
    xs.push_back(SoftFloat::div(one, SoftFloat(mantissa(rng) * 3, 53), 4096, kNear));
  }
  std::clock_t start = std::clock();
  double sum = 0;
  for (int k = 0; k < 2000; ++k) {
    const SoftFloat& a = xs[k % 20];
    const SoftFloat& b = xs[(k * 7 + 3) % 20];
    sum += SoftFloat::div(a, b, 4096, Rounding::kUp).to_double(kNear);
    sum += SoftFloat::sqrt(a, 4096, Rounding::kDown).to_double(kNear);
  }
  double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  EXPECT_GT(sum, 0);
  EXPECT_LT(seconds, 1.0) << "2,000 divisions and square roots at 4096 bits";
}

}  // namespace
}  // namespace raygrade
