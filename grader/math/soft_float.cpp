// SoftFloat: exact operations on natural numbers (Boost.Multiprecision's cpp_int), then one
// rounding.
#include "math/soft_float.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace raygrade {
namespace {

using Natural = SoftFloat::Natural;
namespace mp = boost::multiprecision;

// The number of bits of a (0 for 0).
std::int64_t bit_length(const Natural& a) {
  return a.is_zero() ? 0 : static_cast<std::int64_t>(mp::msb(a)) + 1;
}

Natural shifted_left(const Natural& a, std::int64_t n) { return a << static_cast<unsigned>(n); }

// floor(sqrt(n)) for n > 0, by Newton's iteration on cpp_int (Boost 1.74's own integer square
// root goes one bit at a time). From any x ≥ ⌊√n⌋, x ↦ ⌊(x + ⌊n/x⌋)/2⌋ stays ≥ ⌊√n⌋ and
// decreases strictly while x² > n, so the loop ends at ⌊√n⌋. The start comes from the root of
// n's top half (n = h·4^k + l, ⌊√h⌋ + 1 times 2^k is at least √n) and has half the root's bits
// right, so a step or two finish; under 128 bits, from double with a margin upwards (√(h + 1) ≤
// √h·(1 + 2^-63) for h ≥ 2^62, and double's conversion and root are each within 2^-53).
Natural integer_sqrt(const Natural& n, Natural& square) {
  std::int64_t bits = bit_length(n);
  Natural x;
  if (bits <= 128) {
    std::int64_t shift = std::max<std::int64_t>(0, bits - 64);
    shift += shift % 2;
    auto top = (n >> static_cast<unsigned>(shift)).convert_to<std::uint64_t>();
    double start = std::sqrt(static_cast<double>(top)) * (1 + 0x1p-40) + 1;
    x = Natural(static_cast<std::uint64_t>(start)) << static_cast<unsigned>(shift / 2);
  } else {
    auto k = static_cast<unsigned>(bits / 4);
    Natural ignored;
    x = (integer_sqrt(n >> (2 * k), ignored) + 1) << k;
  }
  for (;;) {
    square = x * x;
    if (square <= n) return x;
    x = (x + n / x) >> 1;
  }
}

// Whether rounding away from zero in magnitude is due, for a value of sign `negative` whose
// kept part ends in `odd`, the first dropped bit is `half` and the rest is `rest`.
bool round_up(bool negative, bool odd, bool half, bool rest, Rounding r) {
  switch (r) {
    case Rounding::kNearest: return half && (rest || odd);
    case Rounding::kUp: return !negative && (half || rest);
    case Rounding::kDown: return negative && (half || rest);
  }
  return false;
}

// ±m·2^e (plus a fraction below m's last bit when `sticky`) rounded in place to a multiple of
// 2^low, with e = low afterwards when e < low. m is nonzero.
void round_at(bool negative, Natural& m, std::int64_t& e, bool sticky, std::int64_t low,
              Rounding r) {
  if (e >= low) return;
  std::int64_t drop = low - e;
  bool half = false, rest = sticky;
  if (drop - 1 > static_cast<std::int64_t>(mp::msb(m))) {
    rest = true;  // all of m is below the first dropped bit
    m = 0;
  } else {
    half = mp::bit_test(m, static_cast<unsigned>(drop - 1));
    rest = rest || static_cast<std::int64_t>(mp::lsb(m)) < drop - 1;
    m >>= static_cast<unsigned>(drop);
  }
  e = low;
  if (round_up(negative, !m.is_zero() && mp::bit_test(m, 0), half, rest, r)) ++m;
}

}  // namespace

SoftFloat SoftFloat::special(Kind kind, bool negative) {
  SoftFloat x;
  x.kind_ = kind;
  x.negative_ = negative;
  return x;
}

SoftFloat SoftFloat::nan() { return special(Kind::kNaN, false); }

SoftFloat SoftFloat::round(bool negative, Natural m, std::int64_t e, bool sticky, int precision,
                           Rounding r) {
  if (m.is_zero()) return special(Kind::kZero, negative);
  round_at(negative, m, e, sticky, e + bit_length(m) - precision, r);
  // Canonical form: the lowest bit set (m is not zero: rounding `precision` ≥ 1 leading bits
  // never gives 0).
  unsigned zeros = mp::lsb(m);
  SoftFloat x = special(Kind::kFinite, negative);
  m >>= zeros;
  x.m_ = std::move(m);
  x.e_ = e + zeros;
  return x;
}

SoftFloat::SoftFloat(double x, int precision, Rounding rounding) {
  if (std::isnan(x)) {
    *this = nan();
  } else if (std::isinf(x)) {
    *this = special(Kind::kInf, x < 0);
  } else if (x == 0) {
    *this = special(Kind::kZero, std::signbit(x));
  } else {
    int exponent = 0;
    double f = std::frexp(std::abs(x), &exponent);  // |x| = f·2^exponent, f in [1/2, 1)
    auto m = static_cast<std::uint64_t>(std::ldexp(f, 64));
    *this = round(x < 0, Natural(m), exponent - 64, false, precision, rounding);
  }
}

SoftFloat SoftFloat::add(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r) {
  if (a.kind_ == Kind::kNaN || b.kind_ == Kind::kNaN) return nan();
  if (a.kind_ == Kind::kInf || b.kind_ == Kind::kInf) {
    if (a.kind_ == Kind::kInf && b.kind_ == Kind::kInf && a.negative_ != b.negative_) return nan();
    return a.kind_ == Kind::kInf ? a : b;
  }
  if (a.kind_ == Kind::kZero && b.kind_ == Kind::kZero) {
    // IEEE 754 and MPFR: −0 only when both are, or for x − x rounded down.
    bool negative = a.negative_ == b.negative_ ? a.negative_ : r == Rounding::kDown;
    return special(Kind::kZero, negative);
  }
  if (a.kind_ == Kind::kZero) return round(b.negative_, b.m_, b.e_, false, precision, r);
  if (b.kind_ == Kind::kZero) return round(a.negative_, a.m_, a.e_, false, precision, r);
  const SoftFloat* big = &a;
  const SoftFloat* small = &b;
  std::int64_t top_a = a.e_ + bit_length(a.m_), top_b = b.e_ + bit_length(b.m_);
  if (top_b > top_a) std::swap(big, small), std::swap(top_a, top_b);
  // An addend entirely below both the larger one's last bit and the result's last kept bit
  // (with two bits to spare, and one more for a cancellation of the top bit) only decides
  // the direction of the rounding: any value of its sign below 2^low rounds the same way.
  std::int64_t low = std::min(big->e_, top_a - precision - 1) - 2;
  bool collapsed = top_b <= low;
  std::int64_t small_e = collapsed ? low - 1 : small->e_;
  std::int64_t e = std::min(big->e_, small_e);
  Natural mb = shifted_left(big->m_, big->e_ - e);
  Natural ms =
      collapsed ? shifted_left(Natural(1), small_e - e) : shifted_left(small->m_, small_e - e);
  if (big->negative_ == small->negative_) {
    mb += ms;
    return round(big->negative_, std::move(mb), e, false, precision, r);
  }
  int c = mb.compare(ms);
  if (c == 0) return special(Kind::kZero, r == Rounding::kDown);
  if (c > 0) {
    mb -= ms;
    return round(big->negative_, std::move(mb), e, false, precision, r);
  }
  ms -= mb;
  return round(small->negative_, std::move(ms), e, false, precision, r);
}

SoftFloat SoftFloat::sub(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r) {
  SoftFloat minus_b = b;
  if (!b.is_nan()) minus_b.negative_ = !b.negative_;
  return add(a, minus_b, precision, r);
}

// A value that needs no rounding (zero, ∞, NaN: `value`), or ±(m + a fraction below its last
// bit, when `sticky`)·2^e, exactly.
struct SoftFloat::Unrounded {
  bool is_special = false;
  SoftFloat value;
  bool negative = false;
  Natural m;
  std::int64_t e = 0;
  bool sticky = false;
};

SoftFloat SoftFloat::rounded(Unrounded x, int precision, Rounding r) {
  if (x.is_special) return std::move(x.value);
  return round(x.negative, std::move(x.m), x.e, x.sticky, precision, r);
}

std::pair<SoftFloat, SoftFloat> SoftFloat::rounded_down_up(Unrounded x, int precision) {
  if (x.is_special) return {x.value, x.value};
  SoftFloat down = round(x.negative, x.m, x.e, x.sticky, precision, Rounding::kDown);
  return {std::move(down),
          round(x.negative, std::move(x.m), x.e, x.sticky, precision, Rounding::kUp)};
}

SoftFloat::Unrounded SoftFloat::exact_product(const SoftFloat& a, const SoftFloat& b) {
  Unrounded x;
  x.negative = a.negative_ != b.negative_;
  x.is_special = true;
  if (a.kind_ == Kind::kNaN || b.kind_ == Kind::kNaN) {
    x.value = nan();
  } else if (a.kind_ == Kind::kInf || b.kind_ == Kind::kInf) {
    bool zero = a.kind_ == Kind::kZero || b.kind_ == Kind::kZero;
    x.value = zero ? nan() : special(Kind::kInf, x.negative);
  } else if (a.kind_ == Kind::kZero || b.kind_ == Kind::kZero) {
    x.value = special(Kind::kZero, x.negative);
  } else {
    x.is_special = false;
    x.m = a.m_ * b.m_;
    x.e = a.e_ + b.e_;
  }
  return x;
}

SoftFloat::Unrounded SoftFloat::exact_quotient(const SoftFloat& a, const SoftFloat& b,
                                               int precision) {
  Unrounded x;
  x.negative = a.negative_ != b.negative_;
  x.is_special = true;
  if (a.kind_ == Kind::kNaN || b.kind_ == Kind::kNaN) {
    x.value = nan();
  } else if (a.kind_ == Kind::kInf) {
    x.value = b.kind_ == Kind::kInf ? nan() : special(Kind::kInf, x.negative);
  } else if (b.kind_ == Kind::kZero) {
    x.value = a.kind_ == Kind::kZero ? nan() : special(Kind::kInf, x.negative);
  } else if (b.kind_ == Kind::kInf || a.kind_ == Kind::kZero) {
    // a finite over infinity, or zero over a finite b: a zero.
    x.value = special(Kind::kZero, x.negative);
  } else {
    x.is_special = false;
    // Enough quotient bits for the rounding (precision + 2), the rest in the remainder.
    std::int64_t shift =
        std::max<std::int64_t>(0, precision + 3 + bit_length(b.m_) - bit_length(a.m_));
    Natural rem;
    mp::divide_qr(shifted_left(a.m_, shift), b.m_, x.m, rem);
    x.e = a.e_ - b.e_ - shift;
    x.sticky = !rem.is_zero();
  }
  return x;
}

SoftFloat SoftFloat::mul(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r) {
  return rounded(exact_product(a, b), precision, r);
}

SoftFloat SoftFloat::div(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r) {
  return rounded(exact_quotient(a, b, precision), precision, r);
}

std::pair<SoftFloat, SoftFloat> SoftFloat::mul_down_up(const SoftFloat& a, const SoftFloat& b,
                                                       int precision) {
  return rounded_down_up(exact_product(a, b), precision);
}

std::pair<SoftFloat, SoftFloat> SoftFloat::div_down_up(const SoftFloat& a, const SoftFloat& b,
                                                       int precision) {
  return rounded_down_up(exact_quotient(a, b, precision), precision);
}

SoftFloat SoftFloat::sqrt(const SoftFloat& a, int precision, Rounding r) {
  if (a.kind_ == Kind::kNaN) return nan();
  if (a.kind_ == Kind::kZero) return a;
  if (a.negative_) return nan();
  if (a.kind_ == Kind::kInf) return a;
  Natural m = a.m_;
  std::int64_t e = a.e_;
  if (e % 2 != 0) m <<= 1, --e;
  // An even shift that leaves at least precision + 2 bits in the root.
  std::int64_t shift = std::max<std::int64_t>(0, 2 * (std::int64_t{precision} + 3) - bit_length(m));
  shift += shift % 2;
  Natural n = shifted_left(m, shift), square;
  Natural root = integer_sqrt(n, square);  // and its square, ≤ n
  return round(false, std::move(root), (e - shift) / 2, square != n, precision, r);
}

SoftFloat SoftFloat::neg(const SoftFloat& a, int precision) {
  if (a.kind_ != Kind::kFinite) {
    SoftFloat x = a;
    if (!a.is_nan()) x.negative_ = !a.negative_;
    return x;
  }
  return round(!a.negative_, a.m_, a.e_, false, precision, Rounding::kNearest);
}

SoftFloat SoftFloat::abs(const SoftFloat& a, int precision) {
  if (a.kind_ != Kind::kFinite) {
    SoftFloat x = a;
    if (!a.is_nan()) x.negative_ = false;
    return x;
  }
  return round(false, a.m_, a.e_, false, precision, Rounding::kNearest);
}

double SoftFloat::to_double(Rounding r) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kMax = std::numeric_limits<double>::max();
  switch (kind_) {
    case Kind::kNaN: return std::numeric_limits<double>::quiet_NaN();
    case Kind::kInf: return negative_ ? -kInf : kInf;
    case Kind::kZero: return negative_ ? -0.0 : 0.0;
    case Kind::kFinite: break;
  }
  // 53 bits, or fewer among the subnormals, whose last bit is 2^-1074.
  constexpr std::int64_t kLowestBit = -1074;
  std::int64_t e = e_;
  Natural m = m_;
  round_at(negative_, m, e, false, std::max(e_ + bit_length(m_) - 53, kLowestBit), r);
  double sign = negative_ ? -1 : 1;
  if (m.is_zero()) return sign * 0.0;
  if (e + bit_length(m) > 1024) {
    // Beyond the largest double: ∞ unless the rounding goes towards zero.
    bool to_infinity = r == Rounding::kNearest || (r == Rounding::kUp) != negative_;
    return sign * (to_infinity ? kInf : kMax);
  }
  auto bits = m.convert_to<std::uint64_t>();  // at most 53 bits
  return sign * std::ldexp(static_cast<double>(bits), static_cast<int>(e));
}

int SoftFloat::compare(const SoftFloat& a, const SoftFloat& b, bool& unordered) {
  unordered = a.is_nan() || b.is_nan();
  if (unordered) return 0;
  auto sign = [](const SoftFloat& x) { return x.kind_ == Kind::kZero ? 0 : x.negative_ ? -1 : 1; };
  if (sign(a) != sign(b)) return sign(a) < sign(b) ? -1 : 1;
  if (sign(a) == 0) return 0;
  int magnitude = 0;  // |a| against |b|
  if (a.kind_ == Kind::kInf || b.kind_ == Kind::kInf) {
    magnitude = (a.kind_ == Kind::kInf) - (b.kind_ == Kind::kInf);
  } else {
    std::int64_t top_a = a.e_ + bit_length(a.m_), top_b = b.e_ + bit_length(b.m_);
    if (top_a != top_b) {
      magnitude = top_a < top_b ? -1 : 1;
    } else {
      std::int64_t e = std::min(a.e_, b.e_);
      int c = shifted_left(a.m_, a.e_ - e).compare(shifted_left(b.m_, b.e_ - e));
      magnitude = (c > 0) - (c < 0);
    }
  }
  return a.negative_ ? -magnitude : magnitude;
}

}  // namespace raygrade
