// Cases to and from JSON; the primitive is named by its `type` key.
#include "shapes/accuracy_case.h"

namespace raygrade {
namespace {

nlohmann::json case_vector(const Vec3d& v) { return {v.x, v.y, v.z}; }

struct Parameters {
  std::size_t points;
  bool more_points, radius;
};

// How many points a primitive takes (at least that many when more_points), and whether a radius.
Parameters parameters_of(Primitive p) {
  return visit_primitive(p, []<typename P>() {
    return Parameters{P::Ladder::kPoints, P::Ladder::kMorePoints, P::Ladder::kRadius};
  });
}

}  // namespace

nlohmann::json case_json(const AccuracyCase& c) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : c.points) points.push_back(case_vector(p));
  nlohmann::json j = {{"id", c.id},
                      {"group", c.group},
                      {"primitive", primitive_name(c.primitive)},
                      {"origin", case_vector(c.origin)},
                      {"direction", case_vector(c.direction)},
                      {"points", points}};
  if (parameters_of(c.primitive).radius) j["radius"] = c.radius;
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
  Parameters shape = parameters_of(out.primitive);
  std::size_t need = shape.points;
  bool fixed = !shape.more_points;
  if (out.points.size() < need || (fixed && out.points.size() != need)) {
    c.at("points").fail(fmt::format("a {} takes {}{} points, found {}", name,
                                    fixed ? "" : "at least ", need, out.points.size()));
  }
  if (shape.radius) out.radius = c.at("radius").positive_number();
  return out;
}

}  // namespace raygrade
