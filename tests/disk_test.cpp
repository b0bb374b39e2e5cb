// Disk: the reference intersection and reading, against values worked by hand.
#include "shapes/disk.h"

#include <gtest/gtest.h>

#include "accuracy/ladder.h"
#include "accuracy/settle.h"
#include "generated.h"
#include "shape_error.h"
#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// The disk of radius 2 around (0, 0, 5) facing −z.
Disk facing() { return Disk({0, 0, 5}, {0, 0, -1}, 2); }

// Along its axis from the origin: N·D = −1, N·(C − O) = −5, t = 5 at the centre; the normal
// is the given one.
TEST(Disk, RayAlongTheAxisHitsTheCentre) {
  auto x = facing().intersect(ray({0, 0, 0}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 5);
  EXPECT_EQ(x.hits[0].point, Vec3d(0, 0, 5));
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, -1));
  EXPECT_FALSE(x.contained);
}

// From (1, 1, 0) along (0, 0, 2): t = −5/−2 = 2.5, P = (1, 1, 5), |P − C|² = 2 ≤ 4.
TEST(Disk, OffCentreHitInsideTheRadius) {
  auto x = facing().intersect(ray({1, 1, 0}, {0, 0, 2}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 2.5);
  EXPECT_EQ(x.hits[0].point, Vec3d(1, 1, 5));
}

// From (3, 0, 0) along +z: P = (3, 0, 5), |P − C|² = 9 > 4: the plane is hit, the disk not.
TEST(Disk, PlanePointOutsideTheRadiusMisses) {
  auto x = facing().intersect(ray({3, 0, 0}, {0, 0, 1}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_FALSE(x.contained);
}

// The rim is part of the disk: from the origin along (2, 0, 5), N·D = −5, t = 1 and
// P = (2, 0, 5), exactly r from the centre. Just beyond it, at x = 2 + 1e-6, a miss.
TEST(Disk, RimHitsAndJustBeyondMisses) {
  auto x = facing().intersect(ray({0, 0, 0}, {2, 0, 5}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 1);
  EXPECT_EQ(x.hits[0].point, Vec3d(2, 0, 5));
  EXPECT_TRUE(facing().intersect(ray({2 + 1e-6, 0, 0}, {0, 0, 1})).hits.empty());
}

// From (0, 0, 10) along +z the disk lies behind: t = (−1·(5 − 10))/(−1) = −5.
TEST(Disk, DiskBehindTheOriginMisses) {
  EXPECT_TRUE(facing().intersect(ray({0, 0, 10}, {0, 0, 1})).hits.empty());
}

// From the back side along −z: t = 5, and the normal is still the given one, as a plane's.
TEST(Disk, BackSideHitKeepsTheGivenNormal) {
  auto x = Disk({0, 0, 5}, {0, 0, -3}, 2).intersect(ray({0, 0, 10}, {0, 0, -1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 5);
  EXPECT_EQ(x.hits[0].normal, Vec3d(0, 0, -1));
}

// An origin on the disk itself: t = 0, in the closed interval [0, ∞).
TEST(Disk, OriginOnTheDiskHitsAtZero) {
  auto x = facing().intersect(ray({1, 0, 5}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 0);
}

// Parallel to the plane (perpendicular to the axis): in the plane through the centre it meets
// the disk along a segment (contained); in the plane but 3 from the centre, or pointing away
// (roots t = −7 and −3), or grazing the rim at y = 2 (one root, t = 5) as stated; off the
// plane, nothing.
TEST(Disk, RayParallelToThePlane) {
  EXPECT_TRUE(facing().intersect(ray({-5, 0, 5}, {1, 0, 0})).contained);
  EXPECT_FALSE(facing().intersect(ray({-5, 3, 5}, {1, 0, 0})).contained);
  EXPECT_FALSE(facing().intersect(ray({5, 0, 5}, {1, 0, 0})).contained);
  EXPECT_TRUE(facing().intersect(ray({-5, 2, 5}, {1, 0, 0})).contained);
  auto off = facing().intersect(ray({-5, 0, 4}, {1, 0, 0}));
  EXPECT_FALSE(off.contained);
  EXPECT_TRUE(off.hits.empty());
}

// A tilted disk: centre (1, 2, 0), normal (0, 1, 1), radius 0.5. From (1, 2, −4) along +z,
// N·D = 1 and N·(C − O) = 4: t = 4 at the centre, normal (0, 1, 1)/√2. Along (0, 1, 1) from
// (1, 0, −3): t = 5/2, P = (1, 2.5, −0.5), |P − C|² = 0.5 > 0.25: a miss.
TEST(Disk, TiltedDisk) {
  Disk tilted({1, 2, 0}, {0, 1, 1}, 0.5);
  auto x = tilted.intersect(ray({1, 2, -4}, {0, 0, 1}));
  ASSERT_EQ(x.hits.size(), 1u);
  EXPECT_EQ(x.hits[0].t, 4);
  EXPECT_NEAR(x.hits[0].normal.y, 1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(x.hits[0].normal.z, 1 / std::sqrt(2.0), 1e-15);
  EXPECT_TRUE(tilted.intersect(ray({1, 0, -3}, {0, 1, 1})).hits.empty());
}

// The worked derivation names t, P, |P − C|² and r² with the values above (t = 2.5,
// |P − C|² = 2, r² = 4).
TEST(Disk, DerivationStepsCarryTheHandValues) {
  Derivation d = facing().derive(ray({1, 1, 0}, {0, 0, 2}), "", nullptr);
  ASSERT_NE(d.find("t"), nullptr);
  EXPECT_EQ(d.find("t")->value.scalar, 2.5);
  EXPECT_EQ(d.find("dist2")->value.scalar, 2);
  EXPECT_EQ(d.find("r2")->value.scalar, 4);
}

// Reading: a zero radius, a zero normal and an unknown key are errors at their paths.
TEST(Disk, BadParametersAreErrorsAtTheirPaths) {
  EXPECT_EQ(testing::shape_error_path(
                R"({"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 0})"),
            "/radius");
  EXPECT_EQ(testing::shape_error_path(
                R"({"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 0], "radius": 1})"),
            "/normal");
  EXPECT_EQ(testing::shape_error_path(
                R"({"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1,
               "height": 2})"),
            "/height");
}

// Every level of the precision ladder on rays worked by hand, against the disk of radius 5
// around the origin in z = 0: from (3, 4, 7) along −z, P = (3, 4, 0) on the rim (3² + 4² = 25),
// t = 7; from (3, 4.5, 7), |P|² = 29.25 > 25, a miss; from (0, 0, −2) along +z, t = 2 from
// behind; from (1, 1, 2) along +z the plane is behind, a miss. Every value is exact in every
// number type, so every level answers exactly.
TEST(Disk, EveryLadderLevelOnRaysWorkedByHand) {
  struct Case {
    Vec3d origin, direction;
    std::optional<double> t;
  };
  const Case cases[] = {{{3, 4, 7}, {0, 0, -1}, 7},
                        {{3, 4.5, 7}, {0, 0, -1}, std::nullopt},
                        {{0, 0, -2}, {0, 0, 1}, 2},
                        {{1, 1, 2}, {0, 0, 1}, std::nullopt}};
  Disk disk({0, 0, 0}, {0, 0, 1}, 5);
  for (const Case& k : cases) {
    std::optional<AccuracyCase> c = accuracy_case_of(disk, Ray{k.origin, k.direction});
    ASSERT_TRUE(c);
    EXPECT_EQ(primitive_name(c->primitive), "disk");
    for (const LadderLevel& level : ladder_levels()) {
      EXPECT_EQ(level.nearest(*c), k.t) << level.name << " from " << k.origin.y;
    }
  }
}

// The disk's generator, many problems of each outcome, checked from their numbers alone: the
// ray meets the disk's plane at t* = N·(C − O) / N·D, at P* = O + t* D; a hit or a rim has
// t* > 0 and |P* − C| < r or = r, and is the one hit stated; a miss has t* > 0 and |P* − C| > r;
// behind has t* < 0 with P* on the disk. Each problem also solves to as many hits as stated.
TEST(DiskGenerator, EachOutcomeIsWhatItSays) {
  EXPECT_EQ(Disk::outcomes(), (std::vector<Outcome>{Outcome::kHit, Outcome::kMiss,
                                                    Outcome::kTangent, Outcome::kBehind}));
  for (Outcome o : Disk::outcomes()) {
    for (const auto& g : testing::generated("disk", o)) {
      auto x = testing::intersect_of(g);
      Vec3d c = testing::vec_at(x.object.at("center"));
      Vec3d n = testing::vec_at(x.object.at("normal"));
      double r = x.object.at("radius").get<double>();
      double t = dot(c - x.origin, n) / dot(x.direction, n);
      Vec3d p = x.origin + t * x.direction;
      double from_centre = length(p - c);
      EXPECT_EQ(x.solved_hits, x.hits.size()) << g.id;
      if (o == Outcome::kHit || o == Outcome::kTangent) {
        ASSERT_EQ(x.hits.size(), 1u) << g.id;
        EXPECT_EQ(x.hits[0].first, t) << g.id;
        EXPECT_NEAR(length(x.hits[0].second - p), 0, 1e-12) << g.id;
        EXPECT_NEAR(dot(x.hits[0].second - c, n), 0, 1e-12) << g.id;
        EXPECT_GT(t, 0) << g.id;
        if (o == Outcome::kHit) {
          EXPECT_LT(from_centre, r) << g.id;
        } else {
          EXPECT_NEAR(from_centre, r, 1e-12) << g.id;
        }
      } else {
        EXPECT_TRUE(x.hits.empty()) << g.id;
        if (o == Outcome::kMiss) {
          EXPECT_GT(t, 0) << g.id;
          EXPECT_GT(from_centre, r) << g.id;
        } else {
          EXPECT_LT(t, 0) << g.id;
          EXPECT_LE(from_centre, r) << g.id;
        }
      }
    }
  }
}

}  // namespace
}  // namespace raygrade
