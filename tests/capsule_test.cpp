// Capsule: the reference intersection and reading, against values worked by hand.
#include "shapes/capsule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "accuracy/ladder.h"
#include "accuracy/settle.h"
#include "generated.h"
#include "shape_error.h"
#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// The capsule of radius 1 around the segment from (0, 0, 0) to (0, 0, 4).
Capsule upright() { return Capsule({0, 0, 0}, {0, 0, 4}, 1); }

void expect_hit(const Hit& h, double t, Vec3d point, Vec3d normal) {
  EXPECT_EQ(h.t, t);
  EXPECT_EQ(h.point, point);
  EXPECT_EQ(h.normal, normal);
}

// Across the side at height 2: (−5 + t)² = 1, t = 4 and 6; s = 2 lies in [0, 4]; the normals
// are (P − Q)/r with Q = (0, 0, 2).
TEST(Capsule, RayAcrossTheSide) {
  auto x = upright().intersect(ray({-5, 0, 2}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_hit(x.hits[0], 4, {-1, 0, 2}, {-1, 0, 0});
  expect_hit(x.hits[1], 6, {1, 0, 2}, {1, 0, 0});
}

// Along the axis from (0, 0, −5): the side is never crossed. The sphere around a gives t = 4
// (z = −1, s = −1 ≤ 0: kept) and t = 6 (z = 1, inside the span: dropped); the sphere around b
// gives t = 8 (z = 3: dropped) and t = 10 (z = 5, s = 5 ≥ 4: kept).
TEST(Capsule, RayAlongTheAxisHitsBothEnds) {
  auto x = upright().intersect(ray({0, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_hit(x.hits[0], 4, {0, 0, -1}, {0, 0, -1});
  expect_hit(x.hits[1], 10, {0, 0, 5}, {0, 0, 1});
}

// Two from the axis: no root on the side, none on the ends.
TEST(Capsule, RayPastTheSideMisses) {
  EXPECT_TRUE(upright().intersect(ray({-5, 2, 2}, {1, 0, 0})).hits.empty());
}

// One from the axis at height 2: the side's double root t = 5 at (0, 1, 2), one hit.
TEST(Capsule, TangentToTheSideHitsOnce) {
  auto x = upright().intersect(ray({-5, 1, 2}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_hit(x.hits[0], 5, {0, 1, 2}, {0, 1, 0});
}

// Across the rim at a (height 0): the side and the sphere around a both give t = 4 at
// (−1, 0, 0) and t = 6 at (1, 0, 0); each point is listed once.
TEST(Capsule, RimBetweenSideAndEndIsListedOnce) {
  auto x = upright().intersect(ray({-5, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_hit(x.hits[0], 4, {-1, 0, 0}, {-1, 0, 0});
  expect_hit(x.hits[1], 6, {1, 0, 0}, {1, 0, 0});
}

// Parallel to the axis at distance r: it runs along the side and touches the two ends' spheres
// where they meet the side, at (1, 0, 0), t = 5, and (1, 0, 4), t = 9.
TEST(Capsule, RayParallelToTheAxisOnTheSideTouchesBothRims) {
  auto x = upright().intersect(ray({1, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_hit(x.hits[0], 5, {1, 0, 0}, {1, 0, 0});
  expect_hit(x.hits[1], 9, {1, 0, 4}, {1, 0, 0});
}

// From inside, at (0, 0, 2) along +x: the side's roots are t = −1 and 1; only t = 1 is ahead.
TEST(Capsule, RayFromInsideLeavesOnce) {
  auto x = upright().intersect(ray({0, 0, 2}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_hit(x.hits[0], 1, {1, 0, 2}, {1, 0, 0});
}

// From (5, 0, 2) along +x the capsule is behind: roots t = −6 and −4.
TEST(Capsule, CapsuleBehindTheOriginMisses) {
  EXPECT_TRUE(upright().intersect(ray({5, 0, 2}, {1, 0, 0})).hits.empty());
}

// A tilted capsule, a = (−1, 2, 3), b = (2, 2, 3), r = 0.5, along −y from (3, 5, 3): the sphere
// around b alone (x = 3 is beyond b): (5 − t − 2)² + 1 = 0.25 has no root, a miss; from
// (0.5, 5, 3) the side at y = 2.5 and 1.5, t = 2.5 and 3.5.
TEST(Capsule, TiltedCapsule) {
  Capsule c({-1, 2, 3}, {2, 2, 3}, 0.5);
  EXPECT_TRUE(c.intersect(ray({3, 5, 3}, {0, -1, 0})).hits.empty());
  auto x = c.intersect(ray({0.5, 5, 3}, {0, -1, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_hit(x.hits[0], 2.5, {0.5, 2.5, 3}, {0, 1, 0});
  expect_hit(x.hits[1], 3.5, {0.5, 1.5, 3}, {0, -1, 0});
}

// The worked derivation: the side's a, b, c for the ray across the side (a = 1, b = −10,
// c = 24) and its hits.
TEST(Capsule, DerivationStepsCarryTheHandValues) {
  Derivation d = upright().derive(ray({-5, 0, 2}, {1, 0, 0}), "", nullptr);
  ASSERT_NE(d.find("a"), nullptr);
  EXPECT_EQ(d.find("a")->value.scalar, 1);
  EXPECT_EQ(d.find("b")->value.scalar, -10);
  EXPECT_EQ(d.find("c")->value.scalar, 24);
  EXPECT_EQ(d.find("t_side0")->value.scalar, 4);
  EXPECT_EQ(d.find("t_side1")->value.scalar, 6);
}

// Reading: b equal to a, and a zero radius, are errors at their paths.
TEST(Capsule, BadParametersAreErrorsAtTheirPaths) {
  EXPECT_EQ(testing::shape_error_path(
                R"({"type": "capsule", "a": [1, 2, 3], "b": [1, 2, 3], "radius": 1})"),
            "/b");
  EXPECT_EQ(testing::shape_error_path(
                R"({"type": "capsule", "a": [0, 0, 0], "b": [0, 0, 1], "radius": 0})"),
            "/radius");
}

// Every level of the precision ladder on rays worked by hand, against the upright capsule
// (a = (0, 0, 0), b = (0, 0, 4), r = 1):
// - from (−5, 0, 2) along +x, the side's quadratic t² − 10t + 24 = 0 (across the axis) has
//   roots 4 and 6, at height 2: t = 4; the ends' have Δ = 100 − 112 < 0;
// - from (0, 0, 10) along −z, parallel to the axis: the sphere around b gives t = 5 and 7, the
//   one at z = 5 beyond b; the sphere around a t = 9 (z = 1, inside the span) and 11: t = 5;
// - from (0, 0, −3) along +z, the sphere around a: t² − 6t + 8 = 0, t = 2 at z = −1;
// - from (−5, 0, 0) along +x, through the rim at a: the side and the sphere around a both give
//   t = 4 at height 0;
// - from (2, −5, 2) along +y, 2 from the axis: a miss (Δ = 100 − 112 < 0 for the side);
// - from (1, −5, 2) along +y, tangent to the side: t² − 10t + 25 = 0, t = 5;
// - from (0, −5, 5) along +y, tangent to the end b at (0, 0, 5): t = 5 (the side's roots 4 and 6
//   lie at height 5, beyond b);
// - from (0, 0, 2) along +x, inside: the side's roots −1 and 1: t = 1;
// - from (0, 0, 10) along +z, the capsule behind: the roots are negative, a miss.
// Every value is exact in every number type, so every level answers exactly.
TEST(Capsule, EveryLadderLevelOnRaysWorkedByHand) {
  struct Case {
    Vec3d origin, direction;
    std::optional<double> t;
  };
  const Case cases[] = {{{-5, 0, 2}, {1, 0, 0}, 4},
                        {{0, 0, 10}, {0, 0, -1}, 5},
                        {{0, 0, -3}, {0, 0, 1}, 2},
                        {{-5, 0, 0}, {1, 0, 0}, 4},
                        {{2, -5, 2}, {0, 1, 0}, std::nullopt},
                        {{1, -5, 2}, {0, 1, 0}, 5},
                        {{0, -5, 5}, {0, 1, 0}, 5},
                        {{0, 0, 2}, {1, 0, 0}, 1},
                        {{0, 0, 10}, {0, 0, 1}, std::nullopt}};
  Capsule capsule = upright();
  for (const Case& k : cases) {
    std::optional<AccuracyCase> c = accuracy_case_of(capsule, Ray{k.origin, k.direction});
    ASSERT_TRUE(c);
    EXPECT_EQ(primitive_name(c->primitive), "capsule");
    for (const LadderLevel& level : ladder_levels()) {
      EXPECT_EQ(level.nearest(*c), k.t) << level.name << " from " << fmt::format("{}", k.origin);
    }
  }
}

// The truth's hits, nearest first, each once: through the rim at a the side's (height 0) and
// not the end's again; along the axis the two ends, outward normals along ∓z.
TEST(Capsule, TruthListsEachHitOnceNearestFirst) {
  std::optional<AccuracyCase> rim = accuracy_case_of(upright(), Ray{{-5, 0, 0}, {1, 0, 0}});
  ASSERT_TRUE(rim);
  std::vector<TruthHit> hits = truth_hits(*rim);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].t, 4);
  EXPECT_EQ(hits[0].normal, (Vec3d{-1, 0, 0}));
  EXPECT_EQ(hits[1].t, 6);
  EXPECT_EQ(hits[1].normal, (Vec3d{1, 0, 0}));
  std::optional<AccuracyCase> axis = accuracy_case_of(upright(), Ray{{0, 0, 10}, {0, 0, -1}});
  ASSERT_TRUE(axis);
  hits = truth_hits(*axis);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].t, 5);
  EXPECT_EQ(hits[0].normal, (Vec3d{0, 0, 1}));
  EXPECT_EQ(hits[1].t, 11);
  EXPECT_EQ(hits[1].normal, (Vec3d{0, 0, -1}));
}

// A far origin near a rim: a point's part is decided by its height in double-double, so the
// first hit's normal is its part's own. From 1.7e7 away, aimed at (−1, 0, −2⁻³⁰) just beyond
// the rim at a (every coordinate exact in double): the end sphere's hit, normal (P − a)/r =
// (−1, 0, −2⁻³⁰) to within 1e-18, not the side's (−1, 0, 0) that a seam tolerance scaled by the
// origin's distance (about 5e-7) let in.
TEST(Capsule, FarRayNearTheRimTakesTheRightPart) {
  Vec3d target{-1, 0, -0x1p-30};
  Vec3d d{0x1p24, 0, 0x1p21};
  Intersection x = upright().intersect(ray(target - d, d));
  ASSERT_FALSE(x.hits.empty());
  EXPECT_NEAR(x.hits[0].t, 1, 1e-15);
  EXPECT_NEAR(x.hits[0].normal.x, -1, 1e-15);
  EXPECT_NEAR(x.hits[0].normal.z, -0x1p-30, 1e-15);
}

// The distance from p to the segment a–b.
double distance_to_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  double u = std::clamp(dot(p - a, b - a) / length_squared(b - a), 0.0, 1.0);
  return length(p - (a + u * (b - a)));
}

// The capsule's generator, many problems of each outcome, checked from their numbers alone: a
// point of the surface is at distance r from the segment ab; hits are there, at O + tD; a
// tangent is perpendicular to P − F (F the nearest point of the segment, the outward normal's
// direction); a miss passes farther than r from every point of the segment (the distance from
// the line to a + u(b − a) is convex in u: found by ternary search); inside starts nearer than
// r; behind has its hits at t < 0 (those of the reversed ray). Each problem also solves to as
// many hits as stated.
TEST(CapsuleGenerator, EachOutcomeIsWhatItSays) {
  EXPECT_EQ(Capsule::outcomes(),
            (std::vector<Outcome>{Outcome::kHit, Outcome::kMiss, Outcome::kTangent,
                                  Outcome::kInside, Outcome::kBehind}));
  for (Outcome o : Capsule::outcomes()) {
    for (const auto& g : testing::generated("capsule", o)) {
      auto x = testing::intersect_of(g);
      Vec3d a = testing::vec_at(x.object.at("a")), b = testing::vec_at(x.object.at("b"));
      double r = x.object.at("radius").get<double>();
      EXPECT_EQ(x.solved_hits, x.hits.size()) << g.id;
      for (const auto& [t, p] : x.hits) {
        EXPECT_GT(t, 0) << g.id;
        EXPECT_NEAR(length(x.origin + t * x.direction - p), 0, 1e-12) << g.id;
        EXPECT_NEAR(distance_to_segment(p, a, b), r, 1e-12) << g.id;
      }
      switch (o) {
        case Outcome::kHit: EXPECT_EQ(x.hits.size(), 2u) << g.id; break;
        case Outcome::kTangent: {
          ASSERT_EQ(x.hits.size(), 1u) << g.id;
          Vec3d p = x.hits[0].second;
          double u = std::clamp(dot(p - a, b - a) / length_squared(b - a), 0.0, 1.0);
          EXPECT_NEAR(dot(p - (a + u * (b - a)), x.direction), 0, 1e-12) << g.id;
          break;
        }
        case Outcome::kMiss: {
          EXPECT_TRUE(x.hits.empty()) << g.id;
          Vec3d w = normalized(x.direction);
          auto off_line = [&](double u) {
            Vec3d q = a + u * (b - a) - x.origin;
            return length(q - dot(q, w) * w);
          };
          double lo = 0, hi = 1;
          for (int k = 0; k < 200; ++k) {
            double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (off_line(m1) < off_line(m2))
              hi = m2;
            else
              lo = m1;
          }
          EXPECT_GT(off_line(lo), r) << g.id;
          break;
        }
        case Outcome::kInside:
          EXPECT_EQ(x.hits.size(), 1u) << g.id;
          EXPECT_LT(distance_to_segment(x.origin, a, b), r) << g.id;
          break;
        case Outcome::kBehind: {
          EXPECT_TRUE(x.hits.empty()) << g.id;
          auto back = Capsule(a, b, r).intersect(testing::ray(x.origin, -x.direction));
          EXPECT_EQ(back.hits.size(), 2u) << g.id;
          for (const auto& hit : back.hits) {
            EXPECT_NEAR(distance_to_segment(hit.point, a, b), r, 1e-12) << g.id;
          }
          break;
        }
      }
    }
  }
}

}  // namespace
}  // namespace raygrade
