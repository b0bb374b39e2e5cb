// The hard-case corpus and the random sets of the accuracy study.
#include "accuracy/corpus.h"

#include <cmath>

#include "core/error.h"
#include "json/source.h"

namespace raygrade {

std::vector<AccuracyCase> random_cases(Primitive primitive, int count, std::uint64_t seed) {
  SplitMix rng(seed);
  std::vector<AccuracyCase> out;
  for (int i = 0; i < count; ++i) {
    Vec3d o = 4.0 * rng.unit_vector();
    Vec3d target = rng.point(1);
    std::vector<Vec3d> p;
    double r = 0;
    visit_primitive(primitive, [&]<typename P>() { P::Ladder::random_case(rng, p, r); });
    out.push_back(make_case(fmt::format("random-{}-{}", primitive_name(primitive), i), "random",
                            primitive, o, target - o, std::move(p), r));
  }
  return out;
}

namespace {

// Every primitive's hard cases of rounds [first, last], round by round, each round in the list's
// order.
void rounds(int first, int last, std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int round = first; round <= last; ++round) {
    for_each_ladder_primitive([&]<typename P>() { P::Ladder::hard_cases(round, rng, out); });
  }
}

}  // namespace

// The cases come from one stream of random numbers, in rounds: the primitives draw theirs in
// rounds 0 to 8 and the families across primitives between them, in the order the stored corpus
// (tests/data/hard_cases.json) was drawn, so that its cases keep their ids and values. A
// primitive that joins the study draws its hard cases in round kOwnStreamRound from a stream of
// its own, so that no earlier case changes.
std::vector<AccuracyCase> hard_cases() {
  SplitMix rng(20240611);
  std::vector<AccuracyCase> out;
  rounds(0, 4, out, rng);
  huge_coordinate_cases(out, rng);
  direction_scale_cases(out, rng);
  rounds(5, 7, out, rng);
  extreme_scale_cases(out, rng);
  rounds(8, kOwnStreamRound, out, rng);
  return out;
}

}  // namespace raygrade
