// Words for the conclusion of a derivation: which roots are hits and why others are not.
#pragma once

#include <string>
#include <vector>

#include "derivation/derivation.h"
#include "shapes/ray.h"

namespace raygrade {

struct Candidate {
  double t = 0;
  Vec3d point;
  std::string rejected;  // empty when it is a hit; otherwise the reason in words
};

// The reason a candidate t is not a hit, by the ray's interval, or "".
std::string range_reason(const Ray& ray, double t);

// The candidates in ascending t, each hit once: a point found by two parts of a surface (a rim
// between a side and a cap or an end, within kSeamRelative of the figure) is one hit, the first
// found. Rejected candidates all stay, each with its reason.
std::vector<Candidate> each_hit_once(std::vector<Candidate> candidates);

// Adds sentences like "The ray enters the sphere at t = 1, at P = (1, 0, 0), and leaves at
// t = 3, at P = (3, 0, 0)." and "t = −2 is rejected: it lies behind the origin (t < 0)."
void conclude_candidates(Deriver& d, const std::string& object, const Ray& ray,
                         const std::vector<Candidate>& candidates, bool solid);

}  // namespace raygrade
