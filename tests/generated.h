// Helpers for the tests of a primitive's generator: many problems of one kind and outcome
// through the whole generate pipeline (each read back and checked before it is kept), and the
// numbers a test checks them by, read straight from the problem's JSON.
#pragma once

#include <string>
#include <vector>

#include "generate/generate.h"
#include "math/vec3.h"
#include "test_util.h"

namespace raygrade::testing {

// `count` problems of `kind` with `outcome`, from `seed`.
inline std::vector<GeneratedProblem> generated(const std::string& kind, Outcome outcome,
                                               int count = 40, std::uint64_t seed = 11) {
  GenerateOptions o;
  o.seed = seed;
  o.count = count;
  o.kinds = {kind};
  o.outcome = outcome;
  return generate_problems(o);
}

inline Vec3d vec_at(const nlohmann::ordered_json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

// A generated intersect problem as its numbers: the ray, the object's JSON and the expected
// hits (t and point).
// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct GeneratedIntersect {
  Vec3d origin, direction;
  nlohmann::ordered_json object;
  std::vector<std::pair<double, Vec3d>> hits;
  // How many hits the reference solver finds in the problem as written.
  std::size_t solved_hits = 0;
};

inline GeneratedIntersect intersect_of(const GeneratedProblem& g) {
  GeneratedIntersect x;
  x.origin = vec_at(g.json.at("ray").at("origin"));
  x.direction = vec_at(g.json.at("ray").at("direction"));
  x.object = g.json.at("object");
  for (const auto& h : g.json.at("expected").at("hits")) {
    x.hits.emplace_back(h.at("t").get<double>(), vec_at(h.at("point")));
  }
  x.solved_hits = problem(g.json.dump()).task->answer().at("hits").size();
  return x;
}

}  // namespace raygrade::testing
