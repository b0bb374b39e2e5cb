// The hard-case corpus (cases built to break naive formulas, with their ground truth) and the
// random sets of ordinary cases, both from a fixed seed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "accuracy/certified.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"

namespace raygrade {

// The hard cases: every kind of input the accuracy study names (far and huge spheres, grazing
// and tangent rays, origins on the surface, rays nearly parallel to a plane, shared edges and
// vertices, needle triangles, huge coordinates, tiny and huge direction scales, box slab
// planes, rays along a cylinder's axis, ...). Each primitive draws its own in its Ladder's
// hard_cases; the families across primitives (huge coordinates, direction scales) are drawn
// here. Triangles or polygons that share an edge (pairs) or a vertex (fans of five) have ids
// ending in "/a", "/b", ...
std::vector<AccuracyCase> hard_cases();

// The families of hard cases across primitives: `count` random cases of the primitives cycled in
// the list's order, shifted by 1e8 (huge coordinates), with directions scaled by 1e±150, or by
// 10^s for s in [−300, 148].
void huge_coordinate_cases(std::vector<AccuracyCase>& out, SplitMix& rng);
void direction_scale_cases(std::vector<AccuracyCase>& out, SplitMix& rng);
void extreme_scale_cases(std::vector<AccuracyCase>& out, SplitMix& rng);

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
