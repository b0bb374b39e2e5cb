// Number formatting for worked solutions and feedback.
#include "derivation/number_format.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace raygrade {
namespace {

// Values within this relative distance of an integer print as that integer: far below any
// precision a derivation is shown at, far above double rounding noise (about 1e-16).
constexpr double kIntegerSnap = 1e-12;

std::string trim_zeros(std::string s) {
  if (s.find('.') == std::string::npos) return s;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

std::string format_number(double v, const NumberFormat& f) {
  if (std::isnan(v)) return "undefined";
  if (std::isinf(v)) return v > 0 ? "∞" : "−∞";
  double r = std::round(v);
  if (std::abs(v - r) <= kIntegerSnap * std::max(1.0, std::abs(v)) && std::abs(r) < 1e15) {
    if (r == 0) return "0";
    return fmt::format("{}", static_cast<long long>(r));
  }
  std::string s;
  if (f.decimals >= 0) {
    s = trim_zeros(fmt::format("{:.{}f}", v, f.decimals));
  } else {
    double mag = std::abs(v);
    if (mag >= 1e15 || mag < 1e-6) {
      s = fmt::format("{:.{}e}", v, std::max(0, f.significant - 1));
      auto e = s.find('e');
      s = trim_zeros(s.substr(0, e)) + s.substr(e);
    } else {
      int exponent = static_cast<int>(std::floor(std::log10(mag)));
      int decimals = std::max(0, f.significant - 1 - exponent);
      s = trim_zeros(fmt::format("{:.{}f}", v, decimals));
    }
  }
  if (s == "-0") s = "0";
  return s;
}

bool prints_negative(double v, const NumberFormat& f) {
  return v < 0 && (std::isinf(v) || format_number(v, f).front() == '-');
}

std::string format_vector(const Vec3d& v, const NumberFormat& f) {
  return fmt::format("({}, {}, {})", format_number(v.x, f), format_number(v.y, f),
                     format_number(v.z, f));
}

std::string format_value(const Value& v, const NumberFormat& f) {
  switch (v.kind) {
    case Value::Kind::kScalar: return format_number(v.scalar, f);
    case Value::Kind::kVector: return format_vector(v.vector, f);
    case Value::Kind::kBool: return v.truth ? "yes" : "no";
    case Value::Kind::kNone: break;
  }
  return "";
}

namespace {

// A candidate exact form matches when q·v − s·√k lies this close to an integer, relative to
// q·v: far above the rounding of a few chained double operations (about 1e-15), far below
// the chance agreement of a random number (about 2e-11 per candidate, some 2,000 candidates).
constexpr double kExactSnap = 1e-11;
// Decimals up to this many places are written as decimals, never as fractions (0.5, 1.25).
constexpr double kShortDecimalScale = 1e6;
constexpr long long kMaxP = 10000;

constexpr long long kSquareFree[] = {2,  3,  5,  6,  7,  10, 11, 13, 14,
                                     15, 17, 19, 21, 22, 23, 26, 29, 30};
constexpr long long kRootDenominators[] = {1, 2, 3, 4, 6};
constexpr long long kMaxRootCoefficient = 12;
constexpr long long kMaxFractionDenominator = 12;

bool near_integer(double x, double scale, long long& out) {
  double r = std::round(x);
  if (std::abs(x - r) > kExactSnap * std::max(1.0, std::abs(scale))) return false;
  if (std::abs(r) > kMaxP) return false;
  out = static_cast<long long>(r);
  return true;
}

long long gcd(long long a, long long b) {
  a = std::llabs(a);
  b = std::llabs(b);
  while (b) {
    long long t = a % b;
    a = b;
    b = t;
  }
  return a;
}

ExactForm reduced(ExactForm e) {
  long long g = gcd(gcd(e.p, e.s), e.q);
  if (g > 1) {
    e.p /= g;
    e.s /= g;
    e.q /= g;
  }
  return e;
}

}  // namespace

std::optional<ExactForm> exact_form(double v) {
  if (!std::isfinite(v) || std::abs(v) > kMaxP) return std::nullopt;
  // Values that print as an integer (rounding noise about one: 1 − 2e-16, or about zero:
  // 125 − √125², which is −1.4e-14) are that integer, written as such; without this a value
  // near zero would match the fraction 0/2 and print as "0 ≈ 0".
  if (std::abs(v - std::round(v)) <= kIntegerSnap * std::max(1.0, std::abs(v))) {
    return std::nullopt;
  }
  double scaled = v * kShortDecimalScale;
  if (std::abs(scaled - std::round(scaled)) <= kExactSnap * std::max(1.0, std::abs(scaled))) {
    return std::nullopt;  // an integer or a short decimal: written as it is
  }
  long long n = 0;
  for (long long q = 2; q <= kMaxFractionDenominator; ++q) {
    if (near_integer(static_cast<double>(q) * v, static_cast<double>(q) * v, n)) {
      if (n == 0) return std::nullopt;  // zero is no fraction; v is rounding noise about it
      return reduced(ExactForm{n, 0, 1, q});
    }
  }
  for (long long q : kRootDenominators) {
    for (long long s = 1; s <= kMaxRootCoefficient; ++s) {
      for (long long k : kSquareFree) {
        for (long long sign : {1, -1}) {
          double rest = static_cast<double>(q) * v -
                        static_cast<double>(sign * s) * std::sqrt(static_cast<double>(k));
          if (near_integer(rest, static_cast<double>(q) * v, n))
            return reduced(ExactForm{n, sign * s, k, q});
        }
      }
    }
  }
  return std::nullopt;
}

std::string exact_text(const ExactForm& e) {
  std::string root;
  if (e.s != 0) {
    long long a = std::llabs(e.s);
    root = (a == 1 ? std::string() : std::to_string(a)) + "√" + std::to_string(e.k);
  }
  std::string top;
  if (e.p != 0 && e.s != 0) {
    top = (e.p < 0 ? "−" : "") + std::to_string(std::llabs(e.p)) + (e.s < 0 ? " − " : " + ") + root;
  } else if (e.s != 0) {
    top = (e.s < 0 ? "−" : "") + root;
  } else {
    top = (e.p < 0 ? "−" : "") + std::to_string(std::llabs(e.p));
  }
  if (e.q == 1) return top;
  bool sum = e.p != 0 && e.s != 0;
  return (sum ? "(" + top + ")" : top) + "/" + std::to_string(e.q);
}

}  // namespace raygrade
