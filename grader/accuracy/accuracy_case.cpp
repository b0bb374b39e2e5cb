// Names of the primitives of the accuracy study, and cases to and from JSON.
#include "accuracy/accuracy_case.h"

namespace raygrade {
namespace {

nlohmann::json vec_json(const Vec3d& v) { return {v.x, v.y, v.z}; }

// How many points each primitive takes; polygons take 3 or more.
std::size_t points_needed(Primitive p) {
  switch (p) {
    case Primitive::kSphere: return 1;
    case Primitive::kTriangle:
    case Primitive::kPolygon: return 3;
    default: return 2;
  }
}

}  // namespace

std::string_view primitive_name(Primitive p) {
  switch (p) {
    case Primitive::kSphere: return "sphere";
    case Primitive::kPlane: return "plane";
    case Primitive::kTriangle: return "triangle";
    case Primitive::kPolygon: return "polygon";
    case Primitive::kCylinder: return "cylinder";
    case Primitive::kBox: return "box";
  }
  return "?";
}

nlohmann::json case_json(const AccuracyCase& c) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : c.points) points.push_back(vec_json(p));
  nlohmann::json j = {{"id", c.id},
                      {"group", c.group},
                      {"primitive", primitive_name(c.primitive)},
                      {"origin", vec_json(c.origin)},
                      {"direction", vec_json(c.direction)},
                      {"points", points}};
  if (c.primitive == Primitive::kSphere || c.primitive == Primitive::kCylinder) {
    j["radius"] = c.radius;
  }
  return j;
}

AccuracyCase read_case(const Cursor& c) {
  c.allow_only({"id", "group", "primitive", "origin", "direction", "points", "radius", "truth"});
  AccuracyCase out;
  out.id = c.at("id").string();
  out.group = c.at("group").string();
  std::string name = c.at("primitive").string();
  bool known = false;
  for (Primitive p : kAllPrimitives) {
    if (primitive_name(p) == name) {
      out.primitive = p;
      known = true;
    }
  }
  if (!known) c.at("primitive").fail(fmt::format("unknown primitive '{}'", name), "unknown-type");
  out.origin = c.at("origin").vec3();
  out.direction = c.at("direction").nonzero_vec3();
  for (const auto& p : c.at("points").items()) out.points.push_back(p.vec3());
  std::size_t need = points_needed(out.primitive);
  bool fixed = out.primitive != Primitive::kPolygon;
  if (out.points.size() < need || (fixed && out.points.size() != need)) {
    c.at("points").fail(fmt::format("a {} takes {}{} points, found {}", name,
                                    fixed ? "" : "at least ", need, out.points.size()));
  }
  if (out.primitive == Primitive::kSphere || out.primitive == Primitive::kCylinder) {
    out.radius = c.at("radius").positive_number();
  }
  return out;
}

}  // namespace raygrade
