// Cone: the reference intersection and reading, against values worked by hand.
#include "shapes/cone.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "accuracy/ladder.h"
#include "accuracy/settle.h"
#include "generated.h"
#include "shape_error.h"
#include "test_util.h"

namespace raygrade {
namespace {

using testing::ray;

// Base circle of radius 1 at the origin, apex at (0, 0, 2): at height s the radius is
// 1 − s/2. The side's outward normal at (x, 0, s) with x > 0 is (2, 0, 1)/√5.
Cone open_cone() { return Cone({0, 0, 0}, {0, 0, 1}, 1, 2, false); }
Cone capped_cone() { return Cone({0, 0, 0}, {0, 0, 1}, 1, 2, true); }

const double kR5 = 1 / std::sqrt(5.0);

void expect_cone_hit(const Hit& h, double t, Vec3d point, Vec3d normal) {
  EXPECT_EQ(h.t, t);
  EXPECT_EQ(h.point, point);
  EXPECT_NEAR(h.normal.x, normal.x, 1e-15);
  EXPECT_NEAR(h.normal.y, normal.y, 1e-15);
  EXPECT_NEAR(h.normal.z, normal.z, 1e-15);
}

// Across at height 1 from (−5, 0, 1): a = 4, b = −40, c = 99, Δ = 1600 − 1584 = 16,
// t = (40 ∓ 4)/8 = 4.5 and 5.5, at x = ∓0.5 (the radius at s = 1).
TEST(Cone, RayAcrossTheSide) {
  auto x = open_cone().intersect(ray({-5, 0, 1}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_cone_hit(x.hits[0], 4.5, {-0.5, 0, 1}, {-2 * kR5, 0, kR5});
  expect_cone_hit(x.hits[1], 5.5, {0.5, 0, 1}, {2 * kR5, 0, kR5});
}

// Above the apex, at height 3: the same quadratic's roots lie on the other nappe (s = 3 > h):
// a miss.
TEST(Cone, OtherNappeIsNotTheCone) {
  EXPECT_TRUE(open_cone().intersect(ray({-5, 0, 3}, {1, 0, 0})).hits.empty());
}

// Tangent at height 1, 0.5 from the axis: a = 4, b = −40, c = 100, Δ = 0: t = 5 at (0.5, 0, 1).
TEST(Cone, TangentRayHitsOnce) {
  auto x = open_cone().intersect(ray({0.5, -5, 1}, {0, 1, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_cone_hit(x.hits[0], 5, {0.5, 0, 1}, {2 * kR5, 0, kR5});
}

// Through the apex across the axis, from (−2, 0, 2): a = 4, b = −16, c = 16, Δ = 0: t = 2 at
// the apex, whose normal is the axis.
TEST(Cone, ApexHasTheAxisAsNormal) {
  auto x = open_cone().intersect(ray({-2, 0, 2}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_cone_hit(x.hits[0], 2, {0, 0, 2}, {0, 0, 1});
}

// Along the axis from (0, 0, −5): D⊥ = 0, a = −1, b = 14, c = −49, Δ = 0: the apex at t = 7.
// With the cap, first the base at t = 5 (normal −â).
TEST(Cone, RayAlongTheAxisMeetsCapAndApex) {
  auto open = open_cone().intersect(ray({0, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(open.hits.size(), 1u);
  expect_cone_hit(open.hits[0], 7, {0, 0, 2}, {0, 0, 1});
  auto capped = capped_cone().intersect(ray({0, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(capped.hits.size(), 2u);
  expect_cone_hit(capped.hits[0], 5, {0, 0, 0}, {0, 0, -1});
  expect_cone_hit(capped.hits[1], 7, {0, 0, 2}, {0, 0, 1});
}

// Parallel to the axis 0.5 from it: a = −1, b = 14, c = −48, Δ = 4: t = 6 (s = 1, kept) and
// t = 8 (s = 3, the other nappe). The cap adds t = 5 at (0.5, 0, 0).
TEST(Cone, RayParallelToTheAxis) {
  auto open = open_cone().intersect(ray({0.5, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(open.hits.size(), 1u);
  expect_cone_hit(open.hits[0], 6, {0.5, 0, 1}, {2 * kR5, 0, kR5});
  auto capped = capped_cone().intersect(ray({0.5, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(capped.hits.size(), 2u);
  expect_cone_hit(capped.hits[0], 5, {0.5, 0, 0}, {0, 0, -1});
}

// Through the rim from (−2, 0, −1) along (1, 0, 1): the side and the cap both meet (−1, 0, 0)
// at t = 1, listed once (with the side's normal); then the side again at t = 7/3 (a = 3,
// b = −10, c = 7, Δ = 16).
TEST(Cone, RimBetweenSideAndCapIsListedOnce) {
  auto x = capped_cone().intersect(ray({-2, 0, -1}, {1, 0, 1}));
  ASSERT_EQ(x.hits.size(), 2u);
  expect_cone_hit(x.hits[0], 1, {-1, 0, 0}, {-2 * kR5, 0, kR5});
  EXPECT_NEAR(x.hits[1].t, 7.0 / 3, 1e-15);
}

// From inside at (0, 0, 1) along +x: roots t = ±0.5, only t = 0.5 ahead.
TEST(Cone, RayFromInsideLeavesOnce) {
  auto x = open_cone().intersect(ray({0, 0, 1}, {1, 0, 0}));
  ASSERT_EQ(x.hits.size(), 1u);
  expect_cone_hit(x.hits[0], 0.5, {0.5, 0, 1}, {2 * kR5, 0, kR5});
}

// From (5, 0, 1) along +x the cone lies behind: roots t = −5.5 and −4.5.
TEST(Cone, ConeBehindTheOriginMisses) {
  EXPECT_TRUE(open_cone().intersect(ray({5, 0, 1}, {1, 0, 0})).hits.empty());
}

// Along a line of the side, from (−1, 0, 0) towards the apex: a = b = c = 0, contained.
TEST(Cone, RayAlongALineOfTheSideIsContained) {
  auto x = open_cone().intersect(ray({-1, 0, 0}, {1, 0, 2}));
  EXPECT_TRUE(x.hits.empty());
  EXPECT_TRUE(x.contained);
}

// A far ray just below the apex: a point's part is decided by its height in double-double,
// with a seam relative to the cone's own size. The cone B = (0, 0, 0), r = 3, h = 4 (slant 5);
// the ray along +x at height 4 − δ, δ = 2⁻²⁸, from 10⁶ away, crosses the side where the radius
// is 3δ/4: at x = ∓3·2⁻³⁰, t = 10⁶ ∓ 3·2⁻³⁰ (exact in double), with the side's normals
// (∓4, 0, 3)/5. A seam scaled by the origin's distance (about 1.4e-8 > δ) took both for the
// apex, normal (0, 0, 1), and listed them as one hit.
TEST(Cone, FarRayNearTheApexTakesTheSide) {
  Cone cone({0, 0, 0}, {0, 0, 1}, 3, 4, false);
  const double delta = 0x1p-28, x = 3 * 0x1p-30;
  Intersection hits = cone.intersect(ray({-1e6, 0, 4 - delta}, {1, 0, 0}));
  ASSERT_EQ(hits.hits.size(), 2u);
  expect_cone_hit(hits.hits[0], 1e6 - x, {-x, 0, 4 - delta}, {-0.8, 0, 0.6});
  expect_cone_hit(hits.hits[1], 1e6 + x, {x, 0, 4 - delta}, {0.8, 0, 0.6});
}

// A far ray along +z just beside the rim of the capped cone B = (0, 0, 0), r = 3, h = 4, from
// 10⁶ away, δ = 2⁻²⁸. Outside, at 3 + δ from the axis: it misses the cap (|P − B| > r) and the
// side (whose roots lie below the base, at s = −4δ/3). Inside, at 3 − δ: the cap at t = 10⁶
// with normal (0, 0, −1), then the side where h|q⊥| = r(h − s), s = 4δ/3, normal (4, 0, 3)/5:
// two hits 4δ/3 apart. A seam scaled by the origin's distance (about 1.4e-8 > δ) let the
// outside ray hit, and merged the two inside hits into one.
TEST(Cone, FarRayBesideTheRimTakesTheRightParts) {
  Cone cone({0, 0, 0}, {0, 0, 1}, 3, 4, true);
  const double delta = 0x1p-28;
  EXPECT_TRUE(cone.intersect(ray({3 + delta, 0, -1e6}, {0, 0, 1})).hits.empty());
  Intersection in = cone.intersect(ray({3 - delta, 0, -1e6}, {0, 0, 1}));
  ASSERT_EQ(in.hits.size(), 2u);
  expect_cone_hit(in.hits[0], 1e6, {3 - delta, 0, 0}, {0, 0, -1});
  EXPECT_NEAR(in.hits[1].t, 1e6 + 4 * delta / 3, 2e-10);
  EXPECT_NEAR(in.hits[1].normal.x, 0.8, 1e-15);
  EXPECT_NEAR(in.hits[1].normal.z, 0.6, 1e-15);
}

// Every level of the precision ladder on rays worked by hand, against the cone B = (0, 0, 0),
// apex (0, 0, 1), r = 1 (the radius at height s is 1 − s; v = (0, 0, 1), so the side's
// quadratic is |f × v + t D × v|² = (w − tα)², w = 1 − f_z, α = D_z; the textbook's cos²θ is 1/2):
// - from (−5, 0, 0.5) along +x: a = 1, b/2 = −5, c = 24.75, Δ' = 0.25: t = 4.5 and 5.5, t = 4.5;
// - from (−2, 0, 1) along +x, through the apex: a = 1, b/2 = −2, c = 4, Δ' = 0: t = 2;
// - from (−5, 0, 0) along +x, through the rim: a = 1, b/2 = −5, c = 24: t = 4 (height 0) and 6;
// - from (0.5, −5, 0.5) along +y, tangent: a = 1, b/2 = −5, c = 25, Δ' = 0: t = 5;
// - from (0, 0, −0.5) along (1, 0, 1), parallel to the line of the side from (−1, 0, 0) to the
//   apex: a = 0, b/2 = 1.5, c = −2.25: one root t = 0.75, at (0.75, 0, 0.25). The textbook
//   divides by 2a: the naive levels find no hit;
// - from (2, −5, 0.5) along +y, 2 from the axis: a miss (Δ' = 25 − 28.75 < 0);
// - from (−5, 0, 1.5) along +x: the roots lie on the other nappe (height 1.5 > h): a miss;
// - from (0, 0, 0.5) along +x, inside: roots −0.5 and 0.5: t = 0.5;
// - from (0, 0, 3) along +z, the cone behind: the double root t = −2: a miss;
// - from (0, 0, −5) along +z, through the open base along the axis: a = −1, b/2 = 6, c = −36,
//   Δ' = 0: the apex at t = 6.
// Every value is exact in every number type, so every level answers exactly.
TEST(Cone, EveryLadderLevelOnRaysWorkedByHand) {
  struct Case {
    Vec3d origin, direction;
    std::optional<double> t;
    bool textbook_divides_by_zero = false;
  };
  const Case cases[] = {{{-5, 0, 0.5}, {1, 0, 0}, 4.5},
                        {{-2, 0, 1}, {1, 0, 0}, 2},
                        {{-5, 0, 0}, {1, 0, 0}, 4},
                        {{0.5, -5, 0.5}, {0, 1, 0}, 5},
                        {{0, 0, -0.5}, {1, 0, 1}, 0.75, true},
                        {{2, -5, 0.5}, {0, 1, 0}, std::nullopt},
                        {{-5, 0, 1.5}, {1, 0, 0}, std::nullopt},
                        {{0, 0, 0.5}, {1, 0, 0}, 0.5},
                        {{0, 0, 3}, {0, 0, 1}, std::nullopt},
                        {{0, 0, -5}, {0, 0, 1}, 6}};
  Cone cone({0, 0, 0}, {0, 0, 1}, 1, 1, false);
  for (const Case& k : cases) {
    std::optional<AccuracyCase> c = accuracy_case_of(cone, Ray{k.origin, k.direction});
    ASSERT_TRUE(c);
    EXPECT_EQ(primitive_name(c->primitive), "cone");
    for (const LadderLevel& level : ladder_levels()) {
      bool naive = level.name.starts_with("naive");
      std::optional<double> expected = naive && k.textbook_divides_by_zero ? std::nullopt : k.t;
      EXPECT_EQ(level.nearest(*c), expected)
          << level.name << " from " << fmt::format("{}", k.origin);
    }
  }
}

// A cone is a case of the study only when the case gives back the very cone the solver
// intersects: not with its cap, nor when apex − B is not exactly h·â (the unit axis of (1, 1, 0)
// is irrational).
TEST(Cone, OnlyAnExactOpenConeIsACase) {
  Ray r{{0, 0, -5}, {0, 0, 1}};
  EXPECT_TRUE(accuracy_case_of(Cone({1, 2, 3}, {0, 2, 0}, 1, 3, false), r));
  EXPECT_FALSE(accuracy_case_of(Cone({0, 0, 0}, {0, 0, 1}, 1, 1, true), r));
  EXPECT_FALSE(accuracy_case_of(Cone({0, 0, 0}, {1, 1, 0}, 1, 1, false), r));
  std::optional<AccuracyCase> c = accuracy_case_of(Cone({1, 2, 3}, {0, 2, 0}, 1, 3, false), r);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->points, (std::vector<Vec3d>{{1, 2, 3}, {1, 5, 3}}));
  EXPECT_EQ(c->radius, 1);
}

// The default axis is +z, and the worked derivation carries a, b, c and Δ of the first case.
TEST(Cone, DerivationStepsCarryTheHandValues) {
  auto s = testing::shape(R"({"type": "cone", "base": [0, 0, 0], "radius": 1, "height": 2})");
  Derivation d = s->derive(ray({-5, 0, 1}, {1, 0, 0}), "", nullptr);
  ASSERT_NE(d.find("a"), nullptr);
  EXPECT_EQ(d.find("a")->value.scalar, 4);
  EXPECT_EQ(d.find("b")->value.scalar, -40);
  EXPECT_EQ(d.find("c")->value.scalar, 99);
  EXPECT_EQ(d.find("discriminant")->value.scalar, 16);
  EXPECT_EQ(d.find("t0")->value.scalar, 4.5);
  EXPECT_EQ(d.find("t1")->value.scalar, 5.5);
}

// Reading: a missing height and a zero radius are errors at their paths.
TEST(Cone, BadParametersAreErrorsAtTheirPaths) {
  EXPECT_EQ(
      testing::shape_error_path(R"({"type": "cone", "base": [0, 0, 0], "radius": 0, "height": 1})"),
      "/radius");
  EXPECT_EQ(testing::shape_error_path(
                R"({"type": "cone", "base": [0, 0, 0], "radius": 1, "height": -1})"),
            "/height");
}

// The cone's generator, many problems of each outcome, checked from their numbers alone. With
// q = P − B, s = q·â and q⊥ = q − s·â, a point of the side has 0 ≤ s ≤ h and
// h|q⊥| = r (h − s), a point of the cap s = 0 and |q⊥| ≤ r. Hits are on the surface, at
// O + tD; a tangent is across the axis (D·â = 0) and perpendicular to the side's normal
// h·ê + r·â there; a miss keeps its height, farther from the axis than the side at that
// height; inside starts strictly inside the capped cone; behind has its hits at t < 0 (those of
// the reversed ray). Each problem also solves to as many hits as stated.
TEST(ConeGenerator, EachOutcomeIsWhatItSays) {
  EXPECT_EQ(Cone::outcomes(),
            (std::vector<Outcome>{Outcome::kHit, Outcome::kMiss, Outcome::kTangent,
                                  Outcome::kInside, Outcome::kBehind}));
  for (Outcome o : Cone::outcomes()) {
    for (const auto& g : testing::generated("cone", o)) {
      auto x = testing::intersect_of(g);
      Vec3d b = testing::vec_at(x.object.at("base"));
      Vec3d a = x.object.contains("axis") ? normalized(testing::vec_at(x.object.at("axis")))
                                          : Vec3d{0, 0, 1};
      double r = x.object.at("radius").get<double>(), h = x.object.at("height").get<double>();
      bool capped = x.object.value("capped", false);
      auto height = [&](const Vec3d& p) { return dot(p - b, a); };
      auto across = [&](const Vec3d& p) { return (p - b) - height(p) * a; };
      auto on_surface = [&](const Vec3d& p) {
        double s = height(p), rho = length(across(p));
        bool side = s >= -1e-12 && s <= h + 1e-12 && std::abs(h * rho - r * (h - s)) <= 1e-12;
        bool cap = capped && std::abs(s) <= 1e-12 && rho <= r + 1e-12;
        return side || cap;
      };
      EXPECT_EQ(x.solved_hits, x.hits.size()) << g.id;
      for (const auto& [t, p] : x.hits) {
        EXPECT_GT(t, 0) << g.id;
        EXPECT_NEAR(length(x.origin + t * x.direction - p), 0, 1e-12) << g.id;
        EXPECT_TRUE(on_surface(p)) << g.id;
      }
      switch (o) {
        case Outcome::kHit: EXPECT_EQ(x.hits.size(), 2u) << g.id; break;
        case Outcome::kTangent: {
          ASSERT_EQ(x.hits.size(), 1u) << g.id;
          Vec3d p = x.hits[0].second;
          Vec3d normal = h * normalized(across(p)) + r * a;
          EXPECT_EQ(dot(x.direction, a), 0) << g.id;
          EXPECT_NEAR(dot(normal, x.direction), 0, 1e-12) << g.id;
          break;
        }
        case Outcome::kMiss: {
          EXPECT_TRUE(x.hits.empty()) << g.id;
          EXPECT_EQ(dot(x.direction, a), 0) << g.id;
          double s = height(x.origin);
          EXPECT_GT(s, 0) << g.id;
          // The line's nearest approach to the axis, against the side's radius at its height.
          Vec3d q = across(x.origin);
          Vec3d u = normalized(x.direction);
          double nearest = length(q - dot(q, u) * u);
          EXPECT_GT(nearest, r * (h - s) / h) << g.id;
          break;
        }
        case Outcome::kInside: {
          EXPECT_EQ(x.hits.size(), 1u) << g.id;
          EXPECT_TRUE(capped) << g.id;
          double s = height(x.origin);
          EXPECT_GT(s, 0) << g.id;
          EXPECT_LT(h * length(across(x.origin)), r * (h - s)) << g.id;
          break;
        }
        case Outcome::kBehind: {
          EXPECT_TRUE(x.hits.empty()) << g.id;
          Cone cone(b, a, r, h, capped);
          auto back = cone.intersect(testing::ray(x.origin, -x.direction));
          EXPECT_EQ(back.hits.size(), 2u) << g.id;
          for (const auto& hit : back.hits) EXPECT_TRUE(on_surface(hit.point)) << g.id;
          break;
        }
      }
    }
  }
}

}  // namespace
}  // namespace raygrade
