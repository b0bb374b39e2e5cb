// Stress, short version: rays through the edges and vertices of a closed mesh never miss it,
// and rays spawned from hit points never re-hit the triangle they leave (the full million
// runs with `raygrade bench --stress 1000000`).
#include <gtest/gtest.h>

#include <map>

#include "accuracy/mesh.h"

namespace raygrade {
namespace {

// An icosahedron has 12 vertices and 20 faces; each subdivision splits every face in four
// and adds one vertex per edge (30, then 120, 480 edges): 12 + 30 + 120 + 480 = 642 vertices.
TEST(MeshStress, SubdividedSphereIsClosed) {
  TriangleMesh m = subdivided_sphere(3);
  EXPECT_EQ(m.triangles.size(), 1280u);
  EXPECT_EQ(m.vertices.size(), 642u);
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [e, n] : edges) EXPECT_EQ(edges.count({e.second, e.first}), 1u);
}

TEST(MeshStress, EdgeAndVertexRaysNeverMiss) {
  StressResult r = stress_edge_rays(subdivided_sphere(3), 30000, 11);
  EXPECT_EQ(r.rays, 30000);
  EXPECT_EQ(r.failures, 0);
}

TEST(MeshStress, SpawnedRaysNeverReHit) {
  StressResult r = stress_spawned_rays(subdivided_sphere(3), 5000, 12);
  EXPECT_GT(r.rays, 2000);
  EXPECT_EQ(r.failures, 0);
}

}  // namespace
}  // namespace raygrade
