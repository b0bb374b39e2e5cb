// The textbook patterns.
#include "scenes/pattern.h"

#include <fmt/format.h>

#include <cmath>

#include "scenes/colour.h"

namespace raygrade {

const char* to_string(PatternType t) {
  switch (t) {
    case PatternType::kStripe: return "stripe";
    case PatternType::kGradient: return "gradient";
    case PatternType::kRing: return "ring";
    case PatternType::kCheckers: return "checkers";
  }
  return "stripe";
}

namespace {

Vec3d colour_of(const Cursor& c, std::string_view what) { return read_intensity(c, what).rgb(); }

}  // namespace

SurfaceColour read_surface_colour(const Cursor& c) {
  SurfaceColour s;
  if (!c.is_object()) {
    s.uniform = colour_of(c, "colour");
    return s;
  }
  c.allow_only({"pattern", "a", "b", "transform"});
  Pattern p;
  std::string type = c.at("pattern").string();
  if (type == "stripe") {
    p.type = PatternType::kStripe;
  } else if (type == "gradient") {
    p.type = PatternType::kGradient;
  } else if (type == "ring") {
    p.type = PatternType::kRing;
  } else if (type == "checkers") {
    p.type = PatternType::kCheckers;
  } else {
    c.at("pattern").fail(
        fmt::format("unknown pattern '{}' (known: stripe, gradient, ring, checkers)", type),
        "invalid");
  }
  p.a = colour_of(c.at("a"), "a");
  p.b = colour_of(c.at("b"), "b");
  if (auto t = c.find("transform")) p.transform = read_transform(*t);
  s.pattern = p;
  return s;
}

PatternValue pattern_at(const Pattern& p, const Vec3d& q) {
  PatternValue v;
  switch (p.type) {
    case PatternType::kStripe: v.floor_sum = std::floor(q.x); break;
    case PatternType::kGradient:
      v.floor_sum = std::floor(q.x);
      v.fraction = q.x - v.floor_sum;
      v.colour = p.a + (p.b - p.a) * v.fraction;
      return v;
    case PatternType::kRing:
      v.radius = std::sqrt(q.x * q.x + q.z * q.z);
      v.floor_sum = std::floor(v.radius);
      break;
    case PatternType::kCheckers:
      v.floor_sum = std::floor(q.x) + std::floor(q.y) + std::floor(q.z);
      break;
  }
  v.even = std::fmod(v.floor_sum, 2.0) == 0;
  v.colour = v.even ? p.a : p.b;
  return v;
}

}  // namespace raygrade
