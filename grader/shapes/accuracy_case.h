// AccuracyCase: one ray and one primitive given as exact doubles, the unit of the accuracy
// study (hard-case corpus, random sets, benchmark), and its JSON form.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "json/cursor.h"
#include "math/vec3.h"
#include "shapes/ladder_primitives.h"

namespace raygrade {

// The ray is p(t) = origin + t·direction for t in [0, ∞). `points` and `radius` are the
// primitive's parameters as its Ladder says (shapes/ladder_primitives.h).
struct AccuracyCase {
  std::string id;
  std::string group;  // which kind of hard case: "far-sphere", "grazing", "shared-edge", ...
  Primitive primitive{};
  Vec3d origin, direction;
  std::vector<Vec3d> points;
  double radius = 0;
};

inline AccuracyCase make_case(std::string id, std::string group, Primitive p, Vec3d o, Vec3d d,
                              std::vector<Vec3d> points, double radius = 0) {
  return AccuracyCase{std::move(id), std::move(group), p, o, d, std::move(points), radius};
}

// The case as JSON, every double written so that it reads back exactly.
nlohmann::json case_json(const AccuracyCase& c);

// Reads a case written by case_json; throws raygrade::Error naming the JSON path on a fault.
AccuracyCase read_case(const Cursor& c);

}  // namespace raygrade
