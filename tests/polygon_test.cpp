// Polygon: the reference intersection against values derived by hand, convex and not.
#include "shapes/polygon.h"

#include <gtest/gtest.h>

#include <random>

#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// The square [0,2]² at z = 0, counter-clockwise seen from +z: Newell's normal (0, 0, 8),
// unit (0, 0, 1).
const Polygon kSquare({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}});

// An L: the square [0,4]² without [1,4]×[1,4]; (1, 1) is its reflex vertex.
const Polygon kEll({{0, 0, 0}, {4, 0, 0}, {4, 1, 0}, {1, 1, 0}, {1, 4, 0}, {0, 4, 0}});

bool hits(const Polygon& p, double x, double y) {
  return !p.intersect(ray({x, y, 3}, {0, 0, -1})).hits.empty();
}

TEST(Polygon, SquareHitAndNormal) {
  auto x = kSquare.intersect(ray({1, 1, 3}, {0, 0, -1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 3);
  EXPECT_EQ(x.hits[0].point, Vec3d(1, 1, 0));
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, 1));
  EXPECT_TRUE(kSquare.convex());
}

TEST(Polygon, SquareMissEdgesAndVertices) {
  EXPECT_FALSE(hits(kSquare, 3, 1));
  EXPECT_TRUE(hits(kSquare, 2, 1));  // edge
  EXPECT_TRUE(hits(kSquare, 1, 0));  // edge
  EXPECT_TRUE(hits(kSquare, 2, 2));  // vertex
  EXPECT_TRUE(hits(kSquare, 0, 0));  // vertex
  EXPECT_FALSE(hits(kSquare, 2.000001, 1));
}

// Oblique rays through points of the edge x = 2 whose plane point comes out a rounding away
// from the edge (1.1 + 3·0.3 is not exactly 2 in binary): the closed square is still hit.
TEST(Polygon, ObliqueRaysThroughAnEdgeHit) {
  const double ys[] = {0.1, 0.7, 1.3, 1.9};
  const Vec3d ds[] = {{0.3, 0.1, -1}, {-0.3, 0.7, -1}, {0.7, -0.2, -0.3}, {-0.1, 0.1, -0.7}};
  for (double y : ys) {
    for (const Vec3d& d : ds) {
      Vec3d p{2, y, 0};
      auto x = kSquare.intersect(ray(p - 3.0 * d, d));
      EXPECT_EQ(x.hits.size(), 1u) << fmt::format("through {} along {}", p, d);
    }
  }
}

// A pentagon tilted out of every coordinate plane, with inexact vertices: rays through random
// points of its edges (and its vertices) from random directions all hit the closed polygon,
// and rays through points just outside an edge (1e-9 of its size) all miss.
TEST(Polygon, RandomRaysThroughTiltedEdgesHit) {
  Vec3d c{0.3, -0.2, 0.7}, e1{0.6, 0.48, 0}, e2{-0.272, 0.34, 0.9};  // in-plane axes
  std::vector<Vec3d> v;
  for (int k = 0; k < 5; ++k) {
    double a = 2 * 3.141592653589793 * k / 5;
    v.push_back(c + std::cos(a) * e1 + std::sin(a) * e2);
  }
  Polygon p(v);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1);
  Vec3d n = cross(e1, e2);
  for (int i = 0; i < 3000; ++i) {
    std::size_t k = i % 5;
    double w = i % 50 == 0 ? 0 : u(rng);
    Vec3d q = (1 - w) * v[k] + w * v[(k + 1) % 5];
    Vec3d d = Vec3d{s(rng), s(rng), s(rng)} + (s(rng) > 0 ? 1.0 : -1.0) * n;
    ASSERT_EQ(p.intersect(ray(q - 2.0 * d, d)).hits.size(), 1u)
        << fmt::format("through {} along {}", q, d);
    Vec3d outward = q - c;
    Vec3d off = q + 1e-9 * outward;
    ASSERT_TRUE(p.intersect(ray(off - 2.0 * d, d)).hits.empty());
  }
}

TEST(Polygon, NonConvexInsideNotchAndBoundary) {
  EXPECT_FALSE(kEll.convex());
  EXPECT_TRUE(hits(kEll, 0.5, 3));   // the upright arm
  EXPECT_TRUE(hits(kEll, 3, 0.5));   // the flat arm
  EXPECT_FALSE(hits(kEll, 2, 2));    // the notch
  EXPECT_TRUE(hits(kEll, 1, 1));     // the reflex vertex
  EXPECT_TRUE(hits(kEll, 2, 1));     // an edge of the notch
  EXPECT_TRUE(hits(kEll, 1, 2.5));   // the other edge of the notch
  EXPECT_TRUE(hits(kEll, 0.5, 1));   // level with a horizontal edge, inside
  EXPECT_FALSE(hits(kEll, 4.5, 1));  // level with it, outside
  EXPECT_FALSE(hits(kEll, -0.5, 1));
}

TEST(Polygon, BehindAndParallelMiss) {
  EXPECT_TRUE(kSquare.intersect(ray({1, 1, -3}, {0, 0, -1})).hits.empty());
  auto x = kSquare.intersect(ray({1, 1, 3}, {1, 0, 0}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_FALSE(x.contained);
}

// In the plane z = 0: contained only when the ray meets the polygon within its interval.
TEST(Polygon, RayInThePlaneIsContainedOnlyWhenItMeetsThePolygon) {
  EXPECT_TRUE(kSquare.intersect(ray({-1, 1, 0}, {1, 0, 0})).contained);
  EXPECT_TRUE(kSquare.intersect(ray({1, 1, 0}, {0, 1, 0})).contained);
  EXPECT_TRUE(kSquare.intersect(ray({-1, 0, 0}, {1, 0, 0})).contained);  // along an edge
  EXPECT_FALSE(kSquare.intersect(ray({-1, 3, 0}, {1, 0, 0})).contained);
  EXPECT_FALSE(kSquare.intersect(ray({3, 1, 0}, {1, 0, 0})).contained);
  // From the notch of the L, away from it and towards the reflex vertex and beyond.
  EXPECT_FALSE(kEll.intersect(ray({2, 2, 0}, {1, 1, 0})).contained);
  EXPECT_TRUE(kEll.intersect(ray({2, 2, 0}, {-1, -1, 0})).contained);
  EXPECT_FALSE(kEll.intersect(ray({2, 2, 0}, {-1, -1, 0}, 0, 0.5)).contained);
}

// Newell's normal follows the vertex order: clockwise from +z gives (0, 0, −1).
TEST(Polygon, NormalFollowsVertexOrder) {
  Polygon cw({{0, 0, 0}, {0, 2, 0}, {2, 2, 0}, {2, 0, 0}});
  auto x = cw.intersect(ray({1, 1, 3}, {0, 0, -1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, -1));
}

// A tilted square in the plane x + z = 2: vertices (2,0,0), (2,2,0), (0,2,2), (0,0,2). From the
// origin along (1, 1, 1): 2t = 2, t = 1, at (1, 1, 1), inside; Newell's normal is along
// (1, 0, 1), unit (1, 0, 1)/√2.
TEST(Polygon, TiltedSquareAndUnnormalizedDirection) {
  Polygon p({{2, 0, 0}, {2, 2, 0}, {0, 2, 2}, {0, 0, 2}});
  auto x = p.intersect(ray({0, 0, 0}, {1, 1, 1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_NEAR(x.hits[0].normal.x, std::sqrt(0.5), 2e-16);
  EXPECT_NEAR(x.hits[0].normal.z, std::sqrt(0.5), 2e-16);
  auto half = p.intersect(ray({0, 0, 0}, {0.5, 0.5, 0.5}));
  ASSERT_EQ(half.hits.size(), 1u);
  EXPECT_EQ(half.hits[0].t, 2);
}

TEST(Polygon, IntervalIsClosed) {
  EXPECT_EQ(kSquare.intersect(ray({1, 1, 3}, {0, 0, -1}, 3, 4)).hits.size(), 1u);
  EXPECT_TRUE(kSquare.intersect(ray({1, 1, 3}, {0, 0, -1}, 0, 2.9)).hits.empty());
}

TEST(Polygon, DegenerateAndNonPlanarAreRejected) {
  EXPECT_THROW(testing::shape(R"({"type":"polygon","vertices":[[0,0,0],[1,0,0],[2,0,0]]})"), Error);
  EXPECT_THROW(testing::shape(R"({"type":"polygon","vertices":[[0,0,0],[1,0,0]]})"), Error);
  try {
    testing::shape(R"({"type":"polygon","vertices":[[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]]})");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.diagnostic().message.find("non-planar"), std::string::npos);
    EXPECT_EQ(e.diagnostic().path.rfind("/vertices/", 0), 0u);
  }
}

}  // namespace
}  // namespace raygrade
