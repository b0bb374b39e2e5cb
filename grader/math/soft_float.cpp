// SoftFloat: exact operations on natural numbers, then one rounding.
#include "math/soft_float.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace raygrade {
namespace {

using Nat = std::vector<std::uint32_t>;

void trim(Nat& a) {
  while (!a.empty() && a.back() == 0) a.pop_back();
}

std::int64_t bit_length(const Nat& a) {
  if (a.empty()) return 0;
  std::uint32_t top = a.back();
  int bits = 0;
  while (top) ++bits, top >>= 1;
  return 32 * static_cast<std::int64_t>(a.size() - 1) + bits;
}

bool bit(const Nat& a, std::int64_t i) {
  if (i < 0 || i >= 32 * static_cast<std::int64_t>(a.size())) return false;
  return (a[i / 32] >> (i % 32)) & 1;
}

// Whether any bit below position i is set.
bool any_below(const Nat& a, std::int64_t i) {
  std::int64_t limbs = std::min<std::int64_t>(i / 32, a.size());
  for (std::int64_t k = 0; k < limbs; ++k)
    if (a[k]) return true;
  if (limbs == static_cast<std::int64_t>(a.size())) return false;
  return (a[limbs] & ((std::uint32_t{1} << (i % 32)) - 1)) != 0;
}

Nat shift_left(const Nat& a, std::int64_t n) {
  if (a.empty()) return a;
  std::size_t limbs = n / 32;
  int bits = n % 32;
  Nat r(limbs, 0);
  std::uint32_t carry = 0;
  for (std::uint32_t x : a) {
    r.push_back(bits ? (x << bits) | carry : x);
    carry = bits ? x >> (32 - bits) : 0;
  }
  r.push_back(carry);
  trim(r);
  return r;
}

Nat shift_right(const Nat& a, std::int64_t n) {
  std::size_t limbs = n / 32;
  if (limbs >= a.size()) return {};
  int bits = n % 32;
  Nat r;
  for (std::size_t k = limbs; k < a.size(); ++k) {
    std::uint32_t high = k + 1 < a.size() ? a[k + 1] : 0;
    r.push_back(bits ? (a[k] >> bits) | (high << (32 - bits)) : a[k]);
  }
  trim(r);
  return r;
}

int compare_nat(const Nat& a, const Nat& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t k = a.size(); k-- > 0;)
    if (a[k] != b[k]) return a[k] < b[k] ? -1 : 1;
  return 0;
}

Nat add_nat(const Nat& a, const Nat& b) {
  Nat r;
  std::uint64_t carry = 0;
  for (std::size_t k = 0; k < std::max(a.size(), b.size()); ++k) {
    std::uint64_t s = carry + (k < a.size() ? a[k] : 0) + (k < b.size() ? b[k] : 0);
    r.push_back(static_cast<std::uint32_t>(s));
    carry = s >> 32;
  }
  r.push_back(static_cast<std::uint32_t>(carry));
  trim(r);
  return r;
}

// a − b, for a ≥ b.
Nat sub_nat(const Nat& a, const Nat& b) {
  Nat r;
  std::int64_t borrow = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    std::int64_t d = static_cast<std::int64_t>(a[k]) - (k < b.size() ? b[k] : 0) - borrow;
    borrow = d < 0;
    r.push_back(static_cast<std::uint32_t>(d + (borrow << 32)));
  }
  trim(r);
  return r;
}

Nat mul_nat(const Nat& a, const Nat& b) {
  if (a.empty() || b.empty()) return {};
  Nat r(a.size() + b.size(), 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.size(); ++j) {
      std::uint64_t t = static_cast<std::uint64_t>(a[i]) * b[j] + r[i + j] + carry;
      r[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    r[i + b.size()] = static_cast<std::uint32_t>(carry);
  }
  trim(r);
  return r;
}

void set_bit(Nat& a, std::int64_t i) {
  if (static_cast<std::int64_t>(a.size()) <= i / 32) a.resize(i / 32 + 1, 0);
  a[i / 32] |= std::uint32_t{1} << (i % 32);
}

// floor(a / b) and whether the remainder is nonzero, one bit at a time (b > 0).
Nat div_nat(const Nat& a, const Nat& b, bool& inexact) {
  Nat q, r;
  for (std::int64_t i = bit_length(a); i-- > 0;) {
    r = shift_left(r, 1);
    if (bit(a, i)) {
      if (r.empty()) r.push_back(0);
      r[0] |= 1;
    }
    if (compare_nat(r, b) >= 0) {
      r = sub_nat(r, b);
      set_bit(q, i);
    }
  }
  trim(q);
  inexact = !r.empty();
  return q;
}

// floor(sqrt(a)) and whether it is inexact, one bit at a time.
Nat sqrt_nat(const Nat& a, bool& inexact) {
  Nat result, rest = a, one;
  std::int64_t top = bit_length(a);
  if (top == 0) {
    inexact = false;
    return {};
  }
  set_bit(one, (top - 1) & ~std::int64_t{1});  // the highest power of four ≤ a
  while (!one.empty()) {
    Nat trial = add_nat(result, one);
    if (compare_nat(rest, trial) >= 0) {
      rest = sub_nat(rest, trial);
      result = add_nat(shift_right(result, 1), one);
    } else {
      result = shift_right(result, 1);
    }
    one = shift_right(one, 2);
  }
  inexact = !rest.empty();
  return result;
}

Nat nat_of(std::uint64_t x) {
  Nat r = {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(x >> 32)};
  trim(r);
  return r;
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

// ±m·2^e (plus a fraction below m's last bit when `sticky`) rounded to a multiple of 2^low:
// the new m, with e = low afterwards when e < low.
Nat round_at(bool negative, const Nat& m, std::int64_t& e, bool sticky, std::int64_t low,
             Rounding r) {
  if (e >= low) return m;
  std::int64_t drop = low - e;
  bool half = bit(m, drop - 1);
  bool rest = sticky || any_below(m, drop - 1);
  Nat kept = shift_right(m, drop);
  e = low;
  if (round_up(negative, bit(kept, 0), half, rest, r)) kept = add_nat(kept, Nat{1});
  return kept;
}

}  // namespace

SoftFloat SoftFloat::special(Kind kind, bool negative) {
  SoftFloat x;
  x.kind_ = kind;
  x.negative_ = negative;
  return x;
}

SoftFloat SoftFloat::nan() { return special(Kind::kNaN, false); }

SoftFloat SoftFloat::round(bool negative, Nat m, std::int64_t e, bool sticky, int precision,
                           Rounding r) {
  trim(m);
  if (m.empty()) return special(Kind::kZero, negative);
  m = round_at(negative, m, e, sticky, e + bit_length(m) - precision, r);
  // Canonical form: the lowest bit set.
  std::int64_t zeros = 0;
  while (!bit(m, zeros)) ++zeros;
  SoftFloat x = special(Kind::kFinite, negative);
  x.m_ = shift_right(m, zeros);
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
    *this = round(x < 0, nat_of(m), exponent - 64, false, precision, rounding);
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
  Nat small_m = small->m_;
  std::int64_t small_e = small->e_;
  std::int64_t low = std::min(big->e_, top_a - precision - 1) - 2;
  if (top_b <= low) small_m = Nat{1}, small_e = low - 1;
  std::int64_t e = std::min(big->e_, small_e);
  Nat mb = shift_left(big->m_, big->e_ - e), ms = shift_left(small_m, small_e - e);
  if (big->negative_ == small->negative_)
    return round(big->negative_, add_nat(mb, ms), e, false, precision, r);
  int c = compare_nat(mb, ms);
  if (c == 0) return special(Kind::kZero, r == Rounding::kDown);
  return c > 0 ? round(big->negative_, sub_nat(mb, ms), e, false, precision, r)
               : round(small->negative_, sub_nat(ms, mb), e, false, precision, r);
}

SoftFloat SoftFloat::sub(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r) {
  SoftFloat minus_b = b;
  if (!b.is_nan()) minus_b.negative_ = !b.negative_;
  return add(a, minus_b, precision, r);
}

SoftFloat SoftFloat::mul(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r) {
  bool negative = a.negative_ != b.negative_;
  if (a.kind_ == Kind::kNaN || b.kind_ == Kind::kNaN) return nan();
  if (a.kind_ == Kind::kInf || b.kind_ == Kind::kInf) {
    if (a.kind_ == Kind::kZero || b.kind_ == Kind::kZero) return nan();
    return special(Kind::kInf, negative);
  }
  if (a.kind_ == Kind::kZero || b.kind_ == Kind::kZero) return special(Kind::kZero, negative);
  return round(negative, mul_nat(a.m_, b.m_), a.e_ + b.e_, false, precision, r);
}

SoftFloat SoftFloat::div(const SoftFloat& a, const SoftFloat& b, int precision, Rounding r) {
  bool negative = a.negative_ != b.negative_;
  if (a.kind_ == Kind::kNaN || b.kind_ == Kind::kNaN) return nan();
  if (a.kind_ == Kind::kInf) return b.kind_ == Kind::kInf ? nan() : special(Kind::kInf, negative);
  if (b.kind_ == Kind::kInf) return special(Kind::kZero, negative);
  if (b.kind_ == Kind::kZero) return a.kind_ == Kind::kZero ? nan() : special(Kind::kInf, negative);
  if (a.kind_ == Kind::kZero) return special(Kind::kZero, negative);
  // Enough quotient bits for the rounding (precision + 2), the rest in the remainder.
  std::int64_t shift =
      std::max<std::int64_t>(0, precision + 3 + bit_length(b.m_) - bit_length(a.m_));
  bool inexact = false;
  Nat q = div_nat(shift_left(a.m_, shift), b.m_, inexact);
  return round(negative, q, a.e_ - b.e_ - shift, inexact, precision, r);
}

SoftFloat SoftFloat::sqrt(const SoftFloat& a, int precision, Rounding r) {
  if (a.kind_ == Kind::kNaN) return nan();
  if (a.kind_ == Kind::kZero) return a;
  if (a.negative_) return nan();
  if (a.kind_ == Kind::kInf) return a;
  Nat m = a.m_;
  std::int64_t e = a.e_;
  if (e % 2 != 0) m = shift_left(m, 1), --e;
  // An even shift that leaves at least precision + 2 bits in the root.
  std::int64_t shift = std::max<std::int64_t>(0, 2 * (precision + 3) - bit_length(m));
  shift += shift % 2;
  bool inexact = false;
  Nat root = sqrt_nat(shift_left(m, shift), inexact);
  return round(false, root, (e - shift) / 2, inexact, precision, r);
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
  Nat m = round_at(negative_, m_, e, false, std::max(e_ + bit_length(m_) - 53, kLowestBit), r);
  double sign = negative_ ? -1 : 1;
  if (m.empty()) return sign * 0.0;
  if (e + bit_length(m) > 1024) {
    // Beyond the largest double: ∞ unless the rounding goes towards zero.
    bool to_infinity = r == Rounding::kNearest || (r == Rounding::kUp) != negative_;
    return sign * (to_infinity ? kInf : kMax);
  }
  std::uint64_t bits = m[0] | (m.size() > 1 ? std::uint64_t{m[1]} << 32 : 0);
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
      magnitude = compare_nat(shift_left(a.m_, a.e_ - e), shift_left(b.m_, b.e_ - e));
    }
  }
  return a.negative_ ? -magnitude : magnitude;
}

}  // namespace raygrade
