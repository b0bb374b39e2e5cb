// Tolerance modes, verdicts and the reading of a problem's `tolerance`.
#include "grading/tolerance.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

namespace raygrade {

double allowed_error(double reference, double scale, const Tolerance& t, double widen) {
  double a = 0;
  switch (t.mode) {
    case ToleranceMode::kRelAbs: a = t.atol + t.rtol * std::abs(scale); break;
    case ToleranceMode::kDecimals: a = kHalfUnit * std::pow(10.0, -t.digits); break;
    case ToleranceMode::kSigFigs:
      if (reference == 0) {
        a = t.atol;
      } else {
        double e = std::floor(std::log10(std::abs(reference)));
        a = kHalfUnit * std::pow(10.0, e - t.digits + 1);
      }
      break;
  }
  return std::max(a, widen);
}

NumberFormat shown_at(const Tolerance& t, double reference, NumberFormat base) {
  double magnitude = std::abs(reference);
  if (!std::isfinite(magnitude)) return base;
  auto decimals_of_significant = [&](int figures) {
    return magnitude == 0 ? figures - 1
                          : figures - 1 - static_cast<int>(std::floor(std::log10(magnitude)));
  };
  int needed = 0;
  switch (t.mode) {
    case ToleranceMode::kDecimals: needed = t.digits; break;
    case ToleranceMode::kSigFigs: needed = decimals_of_significant(t.digits); break;
    case ToleranceMode::kRelAbs: {
      double a = allowed_error(reference, reference, t);
      needed = a > 0 ? static_cast<int>(std::ceil(-std::log10(a))) : 0;
      break;
    }
  }
  int shown = base.decimals >= 0 ? base.decimals : decimals_of_significant(base.significant);
  constexpr int kMostDecimals = 12;
  if (needed <= shown) return base;
  return NumberFormat{base.significant, std::min(needed, kMostDecimals)};
}

namespace {

std::string plural(int n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

// What the student must give for the answer to count, in words.
std::string needed(const Tolerance& t, double allowed) {
  switch (t.mode) {
    case ToleranceMode::kDecimals:
      return fmt::format("give {}", plural(t.digits, "decimal place", "decimal places"));
    case ToleranceMode::kSigFigs:
      return fmt::format("give {}", plural(t.digits, "significant figure", "significant figures"));
    case ToleranceMode::kRelAbs: break;
  }
  int decimals = static_cast<int>(std::ceil(std::log10(kHalfUnit / allowed)));
  return fmt::format("give at least {} (within {:.2g})",
                     plural(std::max(decimals, 0), "decimal place", "decimal places"), allowed);
}

}  // namespace

NumberVerdict compare_number(const StudentNumber& s, double reference, double scale,
                             const Tolerance& t, double widen) {
  NumberVerdict v;
  v.allowed = allowed_error(reference, scale, t, widen);
  double error = std::abs(s.value - reference);
  if (std::isfinite(s.value) && error <= v.allowed) {
    v.match = Match::kRight;
    return v;
  }
  // Right to the digits the student typed, but too few of them?
  if (s.digits.literal && std::isfinite(s.value)) {
    double own = kHalfUnit * std::pow(10.0, -s.digits.decimals);
    if (error <= own && own > v.allowed) {
      v.match = Match::kInsufficientPrecision;
      v.message = fmt::format("{} is right to the digits given, but too imprecise: {}", s.text,
                              needed(t, v.allowed));
      return v;
    }
  }
  v.match = Match::kWrong;
  return v;
}

NumberVerdict compare_vector(const StudentNumber (&s)[3], const Vec3d& reference,
                             const Tolerance& t, double widen) {
  // hypot, not √(x² + y² + z²): the squares overflow from about 1e154 on, and an infinite
  // scale would allow any answer.
  double scale = std::hypot(reference.x, reference.y, reference.z);
  NumberVerdict out;
  out.match = Match::kRight;
  for (int i = 0; i < 3; ++i) {
    NumberVerdict c = compare_number(s[i], reference[i], scale, t, widen);
    out.allowed = std::max(out.allowed, c.allowed);
    if (c.match == Match::kWrong) {
      out.match = Match::kWrong;
      out.message.clear();
    } else if (c.match == Match::kInsufficientPrecision && out.match == Match::kRight) {
      out.match = Match::kInsufficientPrecision;
      out.message = c.message;
    }
  }
  return out;
}

DirectionVerdict compare_direction(const StudentNumber (&s)[3], const Vec3d& reference,
                                   const Tolerance& t) {
  DirectionVerdict out;
  Vec3d v{s[0].value, s[1].value, s[2].value};
  out.length = std::hypot(v.x, v.y, v.z);  // no overflow of the squares (see compare_vector)
  if (!(out.length > 0) || !std::isfinite(out.length)) {
    out.length = 0;
    return out;
  }
  // The digits typed keep their meaning when the student rounded a unit vector: its length
  // is then 1 within the rounding of its three components (√3 half units of the coarsest).
  // A multiple of another length ((−2, 2, −4)) was not rounded, and is judged by value.
  double own = 0;
  bool literal = true;
  for (const auto& c : s) {
    literal = literal && c.digits.literal;
    if (c.digits.literal) own = std::max(own, kHalfUnit * std::pow(10.0, -c.digits.decimals));
  }
  bool rounded_unit = literal && std::abs(out.length - 1) <= std::sqrt(3.0) * own;
  StudentNumber unit[3];
  for (int k = 0; k < 3; ++k) {
    unit[k] = s[k];
    unit[k].value = s[k].value / out.length;
    if (!rounded_unit) unit[k].digits.literal = false;
  }
  Vec3d r = normalized(reference);
  out.verdict = compare_vector(unit, r, t);
  if (out.verdict.match == Match::kWrong) {
    out.opposite = compare_vector(unit, -r, t).match != Match::kWrong;
  }
  return out;
}

PartVerdict compare_part(Comparison /*how*/, const StudentNumber& s, double reference,
                         const Tolerance& t, double widen) {
  // A number of any part: relative to its own size.
  PartVerdict out;
  out.verdict = compare_number(s, reference, reference, t, widen);
  return out;
}

PartVerdict compare_part(Comparison how, const StudentNumber (&s)[3], const Vec3d& reference,
                         const Tolerance& t, double widen) {
  PartVerdict out;
  if (how != Comparison::kDirection && how != Comparison::kUnitDirection) {
    out.verdict = compare_vector(s, reference, t, widen);
    return out;
  }
  // A unit direction whose reference is not of length 1 (a changed derivation's, in the mistake
  // search; the grader's is always a unit vector) is that vector's numbers, or its unit vector.
  if (how == Comparison::kUnitDirection && std::abs(length(reference) - 1) > kUnitAnswerLength) {
    out.verdict = compare_vector(s, reference, t, widen);
    if (out.verdict.match != Match::kWrong) return out;
    PartVerdict unit = compare_part(how, s, normalized(reference), t, widen);
    return unit;
  }
  DirectionVerdict d = compare_direction(s, reference, t);
  out.verdict = d.verdict;
  out.length = d.length;
  out.opposite = d.opposite;
  if (d.length == 0) {
    out.verdict.match = Match::kWrong;
    return out;
  }
  if (how == Comparison::kUnitDirection && d.verdict.match != Match::kWrong &&
      std::abs(d.length - 1) > kUnitAnswerLength) {
    out.verdict.match = Match::kWrong;
    out.not_unit = true;
  }
  return out;
}

std::string describe(const Tolerance& t) {
  switch (t.mode) {
    case ToleranceMode::kDecimals: return plural(t.digits, "decimal place", "decimal places");
    case ToleranceMode::kSigFigs:
      return plural(t.digits, "significant figure", "significant figures");
    case ToleranceMode::kRelAbs: break;
  }
  return fmt::format("relative {:g}%, absolute {:g}", t.rtol * 100, t.atol);
}

const Tolerance& TolerancePolicy::for_field(std::string_view field) const {
  auto it = fields.find(field);
  return it == fields.end() ? base : it->second;
}

const std::vector<std::string>& tolerance_fields() {
  static const std::vector<std::string> f = {"t", "point", "normal", "ray", "steps"};
  return f;
}

namespace {

const std::vector<std::string>& mode_keys() {
  static const std::vector<std::string> k = {"rtol", "atol", "sigfigs", "decimals",
                                             "precision_credit"};
  return k;
}

// Reads the mode keys of one object on top of `t`.
Tolerance read_modes(const Cursor& c, Tolerance t) {
  if (c.has("sigfigs") && c.has("decimals")) {
    c.fail("give either 'sigfigs' or 'decimals', not both", "invalid");
  }
  if (c.has("rtol") || c.has("atol")) {
    t.mode = ToleranceMode::kRelAbs;
    if (c.has("rtol")) {
      t.rtol = c.at("rtol").number();
      if (t.rtol < 0 || t.rtol >= 1) c.at("rtol").fail("rtol must lie in [0, 1)", "range");
    }
    if (c.has("atol")) {
      t.atol = c.at("atol").number();
      if (t.atol < 0) c.at("atol").fail("atol must not be negative", "range");
    }
  }
  for (const char* key : {"sigfigs", "decimals"}) {
    if (!c.has(key)) continue;
    int d = c.at(key).integer();
    bool sig = std::string_view(key) == "sigfigs";
    if (d < (sig ? 1 : 0) || d > 15) {
      c.at(key).fail(fmt::format("{} must be an integer from {} to 15", key, sig ? 1 : 0), "range");
    }
    t.mode = sig ? ToleranceMode::kSigFigs : ToleranceMode::kDecimals;
    t.digits = d;
  }
  if (c.has("precision_credit")) {
    t.precision_credit = c.at("precision_credit").number();
    if (t.precision_credit < 0 || t.precision_credit > 1) {
      c.at("precision_credit").fail("precision_credit is a fraction from 0 to 1", "range");
    }
  }
  return t;
}

}  // namespace

TolerancePolicy read_tolerance_policy(const Problem& p) {
  TolerancePolicy policy;
  if (p.precision >= 0) {
    policy.base.mode = ToleranceMode::kDecimals;
    policy.base.digits = p.precision;
  }
  if (p.tolerance.is_null() || !p.source.contains("tolerance")) return policy;
  Cursor c(p.source_file, &p.source.at("tolerance"), p.path + "/tolerance");
  if (c.json().is_number()) {
    policy.base.mode = ToleranceMode::kRelAbs;
    policy.base.rtol = c.number();
    if (policy.base.rtol < 0 || policy.base.rtol >= 1) {
      c.fail("a relative tolerance must lie in [0, 1)", "range");
    }
    return policy;
  }
  if (!c.is_object()) c.fail("the tolerance is a number (relative) or an object", "type");
  std::vector<std::string> keys = mode_keys();
  keys.insert(keys.end(), tolerance_fields().begin(), tolerance_fields().end());
  c.allow_only(keys);
  policy.base = read_modes(c, policy.base);
  for (const auto& field : tolerance_fields()) {
    if (!c.has(field)) continue;
    Cursor f = c.at(field);
    if (!f.is_object()) f.fail("a field's tolerance is an object", "type");
    f.allow_only(mode_keys());
    policy.fields[field] = read_modes(f, policy.base);
  }
  return policy;
}

std::string name_as_compared(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == ' ' || ch == '_' || ch == '-') continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  }
  return out;
}

bool same_object_name(const std::string& a, const std::string& b) {
  return name_as_compared(a) == name_as_compared(b);
}

}  // namespace raygrade
