// AccuracyCase: one ray and one primitive given as exact doubles, the unit of the accuracy
// study (hard-case corpus, random sets, benchmark), and its JSON form.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "json/cursor.h"
#include "math/vec3.h"

namespace raygrade {

enum class Primitive { kSphere, kPlane, kTriangle, kPolygon, kCylinder, kBox };

inline constexpr Primitive kAllPrimitives[] = {Primitive::kSphere,   Primitive::kPlane,
                                               Primitive::kTriangle, Primitive::kPolygon,
                                               Primitive::kCylinder, Primitive::kBox};

std::string_view primitive_name(Primitive p);

// The ray is p(t) = origin + t·direction for t in [0, ∞). `points` hold, by primitive:
// sphere {center}; plane {normal, point}; triangle {a, b, c}; polygon {vertices...};
// cylinder {base, axis} (an infinite side; the axis need not be unit: it is normalized at the
// precision of the computation); box {min, max}. `radius` serves the sphere and the cylinder.
struct AccuracyCase {
  std::string id;
  std::string group;  // which kind of hard case: "far-sphere", "grazing", "shared-edge", ...
  Primitive primitive = Primitive::kSphere;
  Vec3d origin, direction;
  std::vector<Vec3d> points;
  double radius = 0;
};

// The case as JSON, every double written so that it reads back exactly.
nlohmann::json case_json(const AccuracyCase& c);

// Reads a case written by case_json; throws raygrade::Error naming the JSON path on a fault.
AccuracyCase read_case(const Cursor& c);

}  // namespace raygrade
