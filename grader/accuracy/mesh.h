// Stress tests after pbrt-v4's and Embree's: rays through the edges and vertices of a closed
// triangle mesh must never miss it, and rays spawned from a hit point must never re-hit the
// surface they leave.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "math/vec3.h"

namespace raygrade {

struct TriangleMesh {
  std::vector<Vec3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

// An icosahedron subdivided `levels` times, vertices pushed onto the unit sphere
// (20·4^levels triangles).
TriangleMesh subdivided_sphere(int levels);

struct StressResult {
  long long rays = 0;
  long long failures = 0;  // misses of the closed mesh, or re-hits of the surface left
};

// `rays` rays from outside aimed at points of the mesh's edges (a third of them exactly at
// vertices), each tested against every triangle with the watertight reference; a ray that
// hits no triangle is a failure. `progress` (if set) gets the fraction done now and then.
StressResult stress_edge_rays(const TriangleMesh& mesh, long long rays, std::uint64_t seed,
                              const std::function<void(double)>& progress = {});

// `rays` rays hit the mesh; from each hit a ray is spawned outward and one inward, with the
// origin offset along the normal by the hit point's rounding bound (pbrt-v4's
// OffsetRayOrigin). Outward rays of this convex mesh must hit nothing; inward rays must leave
// through another triangle, never the one they start on. Each violation is a failure.
StressResult stress_spawned_rays(const TriangleMesh& mesh, long long rays, std::uint64_t seed);

}  // namespace raygrade
