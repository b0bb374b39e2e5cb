// The solver's answers (each primitive's intersect, then the adaptive settling that solve
// runs) against MPFR truth: every hit present, t within 1e-14 relative and unit normals within
// 1e-14 per component, on the hard corpus and on random cases at direction scales from 1e-300
// to 1e+300.
#include <gtest/gtest.h>

#include <cmath>

#include "accuracy/corpus.h"
#include "accuracy/settle.h"

namespace raygrade {
namespace {

// The accuracy every answer must reach: a few hundred ulps, far below any exercise's precision
// and far above what double-double loses on the worst-conditioned case of the corpus.
constexpr double kRelativeT = 1e-14;
constexpr double kNormalError = 1e-14;

// The solver merges hits whose t agree within 8 ulps (a seam, a tangent: finish_hits), so the
// truth's hits closer than that are one hit in double, the first.
std::vector<TruthHit> as_double_hits(const std::vector<TruthHit>& hits) {
  constexpr double kSeamUlps = 8 * 0x1p-52;
  std::vector<TruthHit> out;
  for (const TruthHit& h : hits) {
    if (!out.empty() && std::abs(h.t - out.back().t) <= kSeamUlps * std::abs(h.t)) continue;
    out.push_back(h);
  }
  return out;
}

// What is wrong with the solver's answer to `c`, against the truth `want`; empty when nothing.
std::string fault(const AccuracyCase& c, const std::vector<TruthHit>& truth) {
  std::vector<TruthHit> want = as_double_hits(truth);
  std::unique_ptr<Shape> shape = shape_of(c);
  Ray ray{c.origin, c.direction};
  Intersection x = shape->intersect(ray);
  settle_nearest(*shape, ray, x);
  if (x.hits.size() != want.size())
    return fmt::format("{} hits, the truth has {}", x.hits.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    const Hit& got = x.hits[i];
    double scale = want[i].t != 0 ? std::abs(want[i].t) : 1 / length(c.direction);
    if (!(std::abs(got.t - want[i].t) <= kRelativeT * scale))
      return fmt::format("hit {}: t = {}, the truth {}", i, got.t, want[i].t);
    if (want[i].normal == Vec3d{}) continue;  // a box's face
    Vec3d e = got.normal - want[i].normal;
    if (!(std::max({std::abs(e.x), std::abs(e.y), std::abs(e.z)}) <= kNormalError))
      return fmt::format("hit {}: normal {}, the truth {}", i, got.normal, want[i].normal);
  }
  return "";
}

TEST(SolverAccuracy, HardCorpusHasEveryHitWithAccurateTAndNormal) {
  std::vector<TruthCase> corpus =
      read_corpus(fmt::format("{}/tests/data/hard_cases.json", RAYGRADE_SOURCE_DIR));
  int judged = 0;
  for (const TruthCase& c : corpus) {
    if (c.truth.boundary) continue;
    ++judged;
    EXPECT_EQ(fault(c.input, c.truth.hits), "") << c.input.id;
  }
  EXPECT_GT(judged, 900);
}

// The stored hits are what MPFR gives now, and a sphere of radius 1 at distance 5 has its two
// hits at every scale (the corpus's extreme-scale spheres).
TEST(SolverAccuracy, StoredHitsAreTheMpfrHits) {
  std::vector<TruthCase> corpus =
      read_corpus(fmt::format("{}/tests/data/hard_cases.json", RAYGRADE_SOURCE_DIR));
  int spheres = 0;
  for (const TruthCase& c : corpus) {
    if (c.truth.boundary || !c.truth.hit) continue;
    std::vector<TruthHit> now = truth_hits(c.input);
    ASSERT_EQ(now.size(), c.truth.hits.size()) << c.input.id;
    for (std::size_t i = 0; i < now.size(); ++i) {
      EXPECT_EQ(now[i].t, c.truth.hits[i].t) << c.input.id;
      EXPECT_TRUE(now[i].normal == c.truth.hits[i].normal)
          << c.input.id << ": " << fmt::format("{} {}", now[i].normal, c.truth.hits[i].normal);
    }
    if (c.input.id.rfind("extreme-scale-sphere-", 0) == 0) {
      ++spheres;
      EXPECT_EQ(now.size(), 2u) << c.input.id;
    }
  }
  EXPECT_EQ(spheres, 24);
}

TEST(SolverAccuracy, RandomCasesAtEveryDirectionScale) {
  SplitMix rng(17);
  std::size_t hits = 0;
  for (Primitive p : kAllPrimitives) {
    for (AccuracyCase& c : random_cases(p, 150, rng.next())) {
      c.direction = std::pow(10.0, rng.uniform(-300, 300)) * c.direction;
      std::vector<TruthHit> truth = truth_hits(c);
      hits += truth.size();
      EXPECT_EQ(fault(c, truth), "")
          << c.id << fmt::format(" direction {} origin {}", c.direction, c.origin);
    }
  }
  EXPECT_GT(hits, 500u);  // about half the rays hit; spheres, cylinders and boxes twice
}

}  // namespace
}  // namespace raygrade
