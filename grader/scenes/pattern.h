// Patterns: a surface's colour as a function of the point, the textbook ones (The Ray Tracer
// Challenge, ch. 10): stripes by ⌊x⌋ mod 2, a gradient a + (b − a)(x − ⌊x⌋), rings by
// ⌊√(x² + z²)⌋ mod 2 and 3D checkers by (⌊x⌋ + ⌊y⌋ + ⌊z⌋) mod 2, each in pattern space: the
// world point taken to the object's space by the object's transform, then to the pattern's
// by the pattern's own.
#pragma once

#include <optional>
#include <string>

#include "json/cursor.h"
#include "math/vec3.h"
#include "shapes/transform.h"

namespace raygrade {

enum class PatternType { kStripe, kGradient, kRing, kCheckers };
const char* to_string(PatternType t);

struct Pattern {
  PatternType type = PatternType::kStripe;
  Vec3d a{1, 1, 1}, b{0, 0, 0};  // the two colours (a where the count is even)
  Transform transform;           // pattern to object space; identity when absent
};

// A surface colour as a material gives it: one colour, or a pattern.
struct SurfaceColour {
  Vec3d uniform{1, 1, 1};
  std::optional<Pattern> pattern;
};

// Reads a `colour`: a number, [r, g, b], or {"pattern": "stripe" | "gradient" | "ring" |
// "checkers", "a": colour, "b": colour, "transform": [...]}.
SurfaceColour read_surface_colour(const Cursor& c);

// The pattern's colour at a point of pattern space, and the quantities that decide it.
struct PatternValue {
  Vec3d colour{};
  double floor_sum = 0;  // ⌊x⌋, ⌊r⌋ or ⌊x⌋ + ⌊y⌋ + ⌊z⌋ (stripe, ring, checkers)
  double fraction = 0;   // x − ⌊x⌋ (gradient)
  double radius = 0;     // √(x² + z²) (ring)
  bool even = true;      // floor_sum mod 2 = 0: the colour a
};
PatternValue pattern_at(const Pattern& p, const Vec3d& pattern_point);

}  // namespace raygrade
