// The hard-case corpus: its MPFR truth, and what the double reference, the naive baselines,
// the certified bounds and the adaptive answer do on it.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "accuracy/corpus.h"
#include "accuracy/formulations.h"
#include "accuracy/ladder.h"

namespace raygrade {
namespace {

const std::vector<TruthCase>& corpus() {
  static const std::vector<TruthCase> cases =
      read_corpus(fmt::format("{}/tests/data/hard_cases.json", RAYGRADE_SOURCE_DIR));
  return cases;
}

const TruthCase& find(const std::string& id) {
  for (const auto& c : corpus()) {
    if (c.input.id == id) return c;
  }
  throw std::runtime_error(fmt::format("no case {}", id));
}

// The t of the double reference may be off by this many ulps times (condition number + 1).
constexpr double kUlpsPerCondition = 4;
constexpr double kUnitRoundoff = 0x1p-53;

TEST(HardCases, CoverEveryKindOfHardInput) {
  std::map<std::string, int> groups;
  for (const auto& c : corpus()) ++groups[c.input.group];
  for (const char* g :
       {"far-sphere", "huge-sphere", "grazing", "tangent", "on-surface", "near-parallel",
        "shared-edge", "needle", "huge-coordinates", "direction-scale", "box-slab", "cylinder-axis",
        "extreme-scale", "small-far"}) {
    EXPECT_GE(groups[g], 5) << g;
  }
}

// Values by hand: tangent-0 touches the unit sphere at (0, 1, 0) from (−5, 1, 0), t = 5;
// tangent-1 runs at y = 6 past the sphere at (3, 4, 5) of radius 2, touching at x = 3, so
// t = (3 − (−4))/2 = 3.5; on-surface-0 starts on the sphere (t = 0); box-slab-4 reaches the
// corner (−1, −1, −1) from (−3, −3, −3) at t = 2; box-slab-3 lies in the plane x = −1 but
// outside the face (y = 3 > 2).
TEST(HardCases, TruthAgreesWithValuesByHand) {
  EXPECT_EQ(find("tangent-0").truth.t, 5.0);
  EXPECT_EQ(find("tangent-1").truth.t, 3.5);
  EXPECT_TRUE(find("on-surface-0").truth.hit);
  EXPECT_EQ(find("on-surface-0").truth.t, 0.0);
  EXPECT_EQ(find("box-slab-4").truth.t, 2.0);
  EXPECT_FALSE(find("box-slab-3").truth.hit);
  EXPECT_FALSE(find("tangent-0").truth.boundary);
  // Δ = −2^-106 and 2^-106 − 2^-160 (see the generator): a miss and a hit.
  EXPECT_FALSE(find("beyond-double-double-0").truth.hit);
  EXPECT_TRUE(find("beyond-double-double-1").truth.hit);
}

// The stored inputs are what the generators draw now, bit for bit: no generator draws two
// random numbers where the language leaves their order open (which a compiler other than the
// one that wrote the file might take the other way), and the file is not stale.
TEST(HardCases, StoredInputsAreWhatTheGeneratorsDraw) {
  std::vector<AccuracyCase> drawn = hard_cases();
  ASSERT_EQ(drawn.size(), corpus().size());
  auto same = [](const Vec3d& a, const Vec3d& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const AccuracyCase &d = drawn[i], &s = corpus()[i].input;
    ASSERT_EQ(d.id, s.id);
    EXPECT_EQ(d.group, s.group) << d.id;
    EXPECT_EQ(d.primitive, s.primitive) << d.id;
    EXPECT_TRUE(same(d.origin, s.origin) && same(d.direction, s.direction)) << d.id;
    EXPECT_EQ(d.radius, s.radius) << d.id;
    ASSERT_EQ(d.points.size(), s.points.size()) << d.id;
    for (std::size_t k = 0; k < d.points.size(); ++k)
      EXPECT_TRUE(same(d.points[k], s.points[k])) << d.id;
  }
}

// The stored truth is what MPFR gives on the exact inputs now (the file is not stale).
TEST(HardCases, StoredTruthIsTheMpfrTruth) {
  for (const auto& c : corpus()) {
    Truth t = compute_truth(c.input, false);
    ASSERT_EQ(t.hit, c.truth.hit) << c.input.id;
    ASSERT_EQ(t.boundary, c.truth.boundary) << c.input.id;
    if (t.hit) {
      EXPECT_EQ(t.t, c.truth.t) << c.input.id;
    }
  }
}

TEST(HardCases, ReferenceDoubleDecidesRightWhereDoubleCan) {
  int decidable = 0;
  for (const auto& c : corpus()) {
    if (c.truth.boundary || !certified_double(c.input).decided) continue;
    ++decidable;
    std::optional<double> t = reference_nearest<double>(c.input);
    EXPECT_EQ(t.has_value(), c.truth.hit) << c.input.id;
  }
  EXPECT_GT(decidable, static_cast<int>(corpus().size()) / 2);
}

TEST(HardCases, ReferenceTIsWithinUlpsTimesCondition) {
  for (const auto& c : corpus()) {
    if (c.truth.boundary || !c.truth.hit || !certified_double(c.input).decided) continue;
    std::optional<double> t = reference_nearest<double>(c.input);
    ASSERT_TRUE(t) << c.input.id;
    double bound =
        kUlpsPerCondition * kUnitRoundoff * (c.truth.condition + 1) * std::abs(c.truth.t);
    EXPECT_LE(std::abs(*t - c.truth.t), bound) << c.input.id << " condition " << c.truth.condition;
  }
}

TEST(HardCases, SharedEdgeRaysNeverMissBoth) {
  std::map<std::string, int> hits, seen;
  for (const auto& c : corpus()) {
    auto slash = c.input.id.rfind('/');
    if (slash == std::string::npos) continue;
    std::string pair = c.input.id.substr(0, slash);
    ++seen[pair];
    if (reference_nearest<double>(c.input)) ++hits[pair];
  }
  EXPECT_GE(seen.size(), 50u);  // pairs sharing an edge, fans of five sharing a vertex
  for (const auto& [pair, n] : seen) {
    EXPECT_GE(n, 2) << pair;
    EXPECT_GE(hits[pair], 1) << pair << " misses both";
  }
}

// The corpus stays hard: the textbook double formulas decide wrongly on more than 1% of the
// grazing and far-sphere cases.
TEST(HardCases, NaiveDoubleFailsOnGrazingAndFarSpheres) {
  int judged = 0, wrong = 0;
  for (const auto& c : corpus()) {
    if (c.truth.boundary || (c.input.group != "grazing" && c.input.group != "far-sphere")) continue;
    ++judged;
    if (naive_nearest<double>(c.input).has_value() != c.truth.hit) ++wrong;
  }
  EXPECT_GT(wrong * 100, judged) << wrong << " of " << judged;
}

TEST(HardCases, CertifiedBoundsContainTheTruth) {
  int decided = 0;
  for (const auto& c : corpus()) {
    if (c.truth.boundary) continue;
    for (const Certified& x : {certified_double(c.input), certified_double_double(c.input)}) {
      if (!x.decided) continue;
      ++decided;
      EXPECT_EQ(x.hit, c.truth.hit) << c.input.id;
      if (x.hit && c.truth.hit) {
        EXPECT_LE(x.t_lo, c.truth.t) << c.input.id;
        EXPECT_GE(x.t_hi, c.truth.t) << c.input.id;
      }
    }
  }
  EXPECT_GT(decided, static_cast<int>(corpus().size()));
}

TEST(HardCases, AdaptiveAnswerIsRightOnEveryCase) {
  std::set<Level> levels;
  for (const auto& c : corpus()) {
    Adaptive a = adaptive_nearest(c.input);
    levels.insert(a.level);
    EXPECT_EQ(a.level == Level::kExactBoundary, c.truth.boundary) << c.input.id;
    if (c.truth.boundary) continue;
    EXPECT_EQ(a.hit, c.truth.hit) << c.input.id;
    if (a.hit && c.truth.hit) {
      EXPECT_LE(a.t_lo, c.truth.t) << c.input.id;
      EXPECT_GE(a.t_hi, c.truth.t) << c.input.id;
      EXPECT_LE(relative_error(a.t, c.truth.t), 1e-15 * (c.truth.condition + 1)) << c.input.id;
    }
  }
  EXPECT_EQ(levels.size(), 4u);  // the corpus needs every level
}

}  // namespace
}  // namespace raygrade
