// Number formatting for worked solutions and feedback.
#include "derivation/number_format.h"

#include <fmt/format.h>

#include <cmath>

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

}  // namespace raygrade
