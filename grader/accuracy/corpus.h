// The hard-case corpus (cases built to break naive formulas, with their ground truth) and the
// random sets of ordinary cases, both from a fixed seed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "accuracy/accuracy_case.h"
#include "accuracy/certified.h"

namespace raygrade {

// A small portable random generator (SplitMix64), so that the sets are the same everywhere.
class SplitMix {
 public:
  explicit SplitMix(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform();                      // in [0, 1)
  double uniform(double lo, double hi);  // in [lo, hi)
  Vec3d unit_vector();                   // uniform on the sphere
  int integer(int lo, int hi);           // in [lo, hi]

 private:
  std::uint64_t state_;
};

// A random unit vector perpendicular to u.
Vec3d perpendicular(const Vec3d& u, SplitMix& rng);

// The hard cases: every kind of input the accuracy study names (far and huge spheres, grazing
// and tangent rays, origins on the surface, rays nearly parallel to a plane, shared edges and
// vertices, needle triangles, huge coordinates, tiny and huge direction scales, box slab
// planes, rays along a cylinder's axis). Triangles or polygons that share an edge (pairs) or
// a vertex (fans of five) have ids ending in "/a", "/b", ...
std::vector<AccuracyCase> hard_cases();

// The part of hard_cases() about scales and slab or axis boundaries: huge coordinates, tiny
// and huge direction scales, boxes with the origin on a slab plane, rays along a cylinder's
// axis.
void scale_and_boundary_cases(std::vector<AccuracyCase>& out, SplitMix& rng);

// `count` ordinary cases of one primitive: unit-sized objects near the origin, rays from a few
// units away aimed near them (about half hit).
std::vector<AccuracyCase> random_cases(Primitive primitive, int count, std::uint64_t seed);

// A case with its ground truth, as stored in tests/data/hard_cases.json.
struct TruthCase {
  AccuracyCase input;
  Truth truth;
};

// The corpus file: {"generated_by": ..., "cases": [{...case, "truth": {...}}]}.
nlohmann::json corpus_json(const std::vector<TruthCase>& cases);
std::vector<TruthCase> read_corpus(const std::string& path);

}  // namespace raygrade
