// The huge-coordinates hard cases of a primitive whose case is two points and a radius.
#pragma once

#include <fmt/format.h>

#include <vector>

#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"

namespace raygrade {

// `count` of P's random cases (its Ladder's random_case) moved 1e8 away in a random direction,
// each with a ray from about 4 away aimed at the middle of its two points, within `spread`
// (ids "huge-coordinates-<type>-<i>"): every coordinate keeps 8 fewer digits below the unit.
template <typename P>
void two_point_huge_coordinate_cases(int count, double spread, SplitMix& rng,
                                     std::vector<AccuracyCase>& out) {
  for (int i = 0; i < count; ++i) {
    Vec3d shift = 1e8 * rng.unit_vector();
    std::vector<Vec3d> p;
    double r = 0;
    P::Ladder::random_case(rng, p, r);
    Vec3d o = 4.0 * rng.unit_vector();
    Vec3d target = 0.5 * (p[0] + p[1]) + rng.point(spread);
    out.push_back(make_case(fmt::format("huge-coordinates-{}-{}", P::kType, i), "huge-coordinates",
                            primitive_of<P>(), o + shift, target - o, {p[0] + shift, p[1] + shift},
                            r));
  }
}

}  // namespace raygrade
