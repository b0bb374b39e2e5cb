// The static filters (filtered_double): every decision they make is the MPFR truth's, and t's
// enclosure holds the true t, on the whole hard corpus, on random rays and on rays near a
// tangent, an edge, a vertex or the plane; a bound made too small is caught by the same checks.
// RAYGRADE_FILTER_RAYS sets the random and near-boundary rays per primitive (2000 each by
// default; the long run takes 1000000); RAYGRADE_FILTER_BOUND_SCALE scales the bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "accuracy/corpus.h"
#include "sampling/split_mix.h"
#include "shapes/box.h"
#include "shapes/capsule.h"
#include "shapes/cone.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/plane.h"
#include "shapes/polygon.h"
#include "shapes/sphere.h"
#include "shapes/triangle.h"

namespace raygrade {
namespace {

const std::vector<TruthCase>& filter_corpus() {
  static const std::vector<TruthCase> cases =
      read_corpus(fmt::format("{}/tests/data/hard_cases.json", RAYGRADE_SOURCE_DIR));
  return cases;
}

int rays_per_primitive() {
  const char* n = std::getenv("RAYGRADE_FILTER_RAYS");
  return n ? std::stoi(n) : 2000;
}

// RAYGRADE_FILTER_BOUND_SCALE multiplies the filters' bounds in the checks below (1 unless set),
// to see them fail with a bound smaller than the one derived.
double bound_scale() {
  const char* s = std::getenv("RAYGRADE_FILTER_BOUND_SCALE");
  return s ? std::stod(s) : 1.0;
}

// The part of x across y (a unit vector when x is not along y).
Vec3d across(const Vec3d& x, const Vec3d& y) { return normalized(x - (dot(x, y) / dot(y, y)) * y); }

// A point at r(1 + off) from the line base + s·axis, s uniform in [s_low, 1], and a direction
// across the radial one there: a ray tangent to the cylinder of radius r about that line, or
// nearly.
std::pair<Vec3d, Vec3d> near_side(SplitMix& rng, const Vec3d& base, const Vec3d& axis, double r,
                                  double off, double s_low) {
  Vec3d e = across(rng.unit_vector(), axis);
  Vec3d at = base + rng.uniform(s_low, 1) * axis + (r * (1 + off)) * e;
  return {at, across(rng.unit_vector(), e)};
}

// Rays near a boundary, at distances from a few ulps to 1e-2 (10^-uniform(2, 17) of the
// object's size), where a bound that is too small shows: spheres with a ray that passes the
// centre at about the radius, triangles and polygons with the ray aimed near a point of an edge
// or near a vertex, disks with the ray aimed near the rim, boxes with the ray aimed near an edge
// or a corner from afar, planes with the origin near the plane or the direction nearly in it.
// Each expression draws one random number at most, or its draws are in a braced list: the
// operands of one expression are evaluated in an order the language leaves open, and the rays
// (which the bounds' calibration above was measured on) must be the same whatever the compiler.
std::vector<AccuracyCase> near_boundary_cases(Primitive p, int count, std::uint64_t seed) {
  SplitMix rng(seed);
  std::vector<AccuracyCase> out;
  for (int i = 0; i < count; ++i) {
    Vec3d o = 4.0 * rng.unit_vector();
    double off = std::pow(10.0, -rng.uniform(2, 17)) * (rng.uniform() < 0.5 ? -1 : 1);
    if (p == primitive_of<Disk>()) {
      Vec3d c = rng.point(1), n = rng.unit_vector();
      Vec3d e = rng.unit_vector();
      e = normalized(e - dot(e, n) * n);
      double r = rng.uniform(0.1, 1);
      Vec3d target = c + (r * (1 + off)) * e;
      out.push_back(
          make_case(fmt::format("rim-{}", i), "near-boundary", p, o, target - o, {c, n}, r));
    } else if (p == primitive_of<Polygon>()) {
      std::vector<Vec3d> v;
      double r = 0;
      Polygon::Ladder::random_case(rng, v, r);
      std::size_t j = static_cast<std::size_t>(rng.uniform() * 5) % v.size();
      const Vec3d& a = v[j];
      const Vec3d& b = v[(j + 1) % v.size()];
      Vec3d aside = off * rng.unit_vector();
      Vec3d target = (i % 4 == 0 ? a : a + rng.uniform() * (b - a)) + aside;
      out.push_back(make_case(fmt::format("edge-{}", i), "near-boundary", p, o, target - o, v));
    } else if (p == primitive_of<Box>()) {
      Vec3d lo = rng.point(1),
            size{rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5)};
      Vec3d hi = lo + size;
      // A corner, or a point of an edge along a random axis, seen from afar: the slab ends'
      // differences b − o then round, and the order of two nearly equal ends can come out
      // reversed.
      o = 1000.0 * o;
      Vec3d target{rng.uniform() < 0.5 ? lo.x : hi.x, rng.uniform() < 0.5 ? lo.y : hi.y,
                   rng.uniform() < 0.5 ? lo.z : hi.z};
      if (i % 4 != 0) {
        int axis = static_cast<int>(rng.uniform() * 3) % 3;
        target[axis] = lo[axis] + rng.uniform() * size[axis];
      }
      target = target + off * rng.unit_vector();
      out.push_back(
          make_case(fmt::format("box-edge-{}", i), "near-boundary", p, o, target - o, {lo, hi}));
    } else if (p == primitive_of<Sphere>()) {
      Vec3d c = rng.point(1), d = rng.unit_vector();
      Vec3d n = rng.unit_vector();
      n = normalized(n - dot(n, d) * d);
      double r = rng.uniform(0.1, 1);
      out.push_back(make_case(fmt::format("tangent-{}", i), "near-boundary", p,
                              c + (r * (1 + off)) * n - 4.0 * d, d, {c}, r));
    } else if (p == primitive_of<Cylinder>()) {
      // A ray tangent to the side, or nearly. The axis is not a unit vector.
      Vec3d base = rng.point(1), toward = rng.unit_vector(), axis = rng.uniform(0.3, 3) * toward;
      double r = rng.uniform(0.1, 1);
      auto [at, d] = near_side(rng, base, axis, r, off, -1);
      out.push_back(make_case(fmt::format("tangent-{}", i), "near-boundary", p, at - 4.0 * d, d,
                              {base, axis}, r));
    } else if (p == primitive_of<Cone>()) {
      // Rays near the rim circle, near the apex, and nearly tangent to the side (in the plane
      // that touches it along a line, moved off by `off`).
      Vec3d base = rng.point(1), toward = rng.unit_vector(), v = rng.uniform(0.5, 2) * toward,
            apex = base + v;
      Vec3d e = across(rng.unit_vector(), v);
      double r = rng.uniform(0.2, 1);
      Vec3d target, d;
      if (i % 3 == 0) {
        target = base + (r * (1 + off)) * e;
        d = target - o;
      } else if (i % 3 == 1) {
        target = apex + off * rng.unit_vector();
        d = target - o;
      } else {
        double lambda = rng.uniform(0.1, 0.9);
        Vec3d at = base + lambda * v + (r * (1 - lambda)) * e;
        Vec3d line = apex - at, around = cross(v, e);
        Vec3d outward = normalized(across(e, line));
        d = around + rng.uniform(-1, 1) * line;
        target = at + (off * r) * outward;
      }
      out.push_back(make_case(fmt::format("cone-{}", i), "near-boundary", p, target - 4.0 * d, d,
                              {base, apex}, r));
    } else if (p == primitive_of<Capsule>()) {
      // Rays nearly tangent to the side or to an end, and rays aimed near the circle where the
      // side meets an end.
      Vec3d a = rng.point(1), toward = rng.unit_vector(), axis = rng.uniform(0.3, 2) * toward,
            b = a + axis;
      Vec3d e = across(rng.unit_vector(), axis);
      double r = rng.uniform(0.1, 1);
      Vec3d at, d;
      if (i % 3 == 0) {
        std::tie(at, d) = near_side(rng, a, axis, r, off, 0);
      } else if (i % 3 == 1) {
        Vec3d end = rng.uniform() < 0.5 ? a : b, n = rng.unit_vector();
        at = end + (r * (1 + off)) * n;
        d = across(rng.unit_vector(), n);
      } else {
        Vec3d aside = off * rng.unit_vector();
        at = (rng.uniform() < 0.5 ? a : b) + r * e + aside;
        d = at - o;
      }
      out.push_back(
          make_case(fmt::format("capsule-{}", i), "near-boundary", p, at - 4.0 * d, d, {a, b}, r));
    } else if (p == primitive_of<Triangle>()) {
      Vec3d a = rng.point(1), b = rng.point(1), c = rng.point(1);
      Vec3d aside = off * rng.unit_vector();
      Vec3d target = (i % 4 == 0 ? a : a + rng.uniform() * (b - a)) + aside;
      out.push_back(
          make_case(fmt::format("edge-{}", i), "near-boundary", p, o, target - o, {a, b, c}));
    } else {
      Vec3d n = rng.unit_vector(), q = rng.point(1);
      Vec3d along = rng.unit_vector();
      along = along - dot(along, n) * n;  // in the plane, up to rounding
      if (i % 2 == 0) {
        out.push_back(make_case(fmt::format("on-plane-{}", i), "near-boundary", p,
                                q + rng.uniform(-2, 2) * along + off * n, rng.unit_vector(),
                                {n, q}));
      } else {
        out.push_back(make_case(fmt::format("parallel-{}", i), "near-boundary", p, o,
                                along + off * n, {n, q}));
      }
    }
  }
  return out;
}

struct Tally {
  int decided = 0, wrong = 0;
  std::string first_wrong;
};

// Checks the filter against the MPFR truth on each case; `bound_scale` multiplies its bounds.
Tally check(const std::vector<AccuracyCase>& cases, double bound_scale) {
  Tally tally;
  for (const AccuracyCase& c : cases) {
    std::optional<FilterAnswer> f = filtered_double(c, bound_scale);
    if (!f) continue;
    ++tally.decided;
    Truth truth = compute_truth(c, false);
    bool right = !truth.boundary && f->hit == truth.hit &&
                 (!f->hit || (f->t_lo <= truth.t && truth.t <= f->t_hi));
    if (!right && tally.wrong++ == 0) tally.first_wrong = c.id;
  }
  return tally;
}

const Primitive kFiltered[] = {
    primitive_of<Sphere>(),   primitive_of<Plane>(),   primitive_of<Triangle>(),
    primitive_of<Disk>(),     primitive_of<Polygon>(), primitive_of<Box>(),
    primitive_of<Cylinder>(), primitive_of<Cone>(),    primitive_of<Capsule>()};
// The filters whose bounds `bound_scale` scales (the sphere's are its fast path's constants).
const Primitive kScaled[] = {
    primitive_of<Plane>(), primitive_of<Triangle>(), primitive_of<Disk>(), primitive_of<Polygon>(),
    primitive_of<Box>(),   primitive_of<Cylinder>(), primitive_of<Cone>(), primitive_of<Capsule>()};

TEST(StaticFilter, EveryPrimitiveHasOne) {
  for (Primitive p : kFiltered) EXPECT_TRUE(has_filter(p)) << primitive_name(p);
  EXPECT_EQ(std::size(kFiltered), kPrimitiveCount);
}

TEST(StaticFilter, NeverWrongOnTheHardCorpus) {
  std::map<Primitive, int> decided;
  for (const TruthCase& c : filter_corpus()) {
    std::optional<FilterAnswer> f = filtered_double(c.input, bound_scale());
    if (!f) continue;
    ++decided[c.input.primitive];
    // A case on the boundary itself has no exact decision the filter could know.
    ASSERT_FALSE(c.truth.boundary) << c.input.id;
    EXPECT_EQ(f->hit, c.truth.hit) << c.input.id;
    if (f->hit && c.truth.hit) {
      EXPECT_LE(f->t_lo, c.truth.t) << c.input.id;
      EXPECT_GE(f->t_hi, c.truth.t) << c.input.id;
    }
  }
  // The polygon's hard cases are rays through an edge two polygons share, within rounding: the
  // filter leaves nearly all of them to the ladder.
  for (Primitive p : kFiltered) {
    EXPECT_GT(decided[p], p == primitive_of<Polygon>() ? 2 : 10) << primitive_name(p);
  }
}

TEST(StaticFilter, NeverWrongOnRandomRays) {
  int n = rays_per_primitive();
  for (Primitive p : kFiltered) {
    Tally t = check(random_cases(p, n, 31), bound_scale());
    EXPECT_EQ(t.wrong, 0) << primitive_name(p) << ": " << t.first_wrong;
    // Ordinary rays lie far from every boundary: the filter decides nearly all of them.
    EXPECT_GT(t.decided, n * 9 / 10) << primitive_name(p);
  }
}

TEST(StaticFilter, NeverWrongNearTheBoundary) {
  int n = rays_per_primitive();
  for (Primitive p : kFiltered) {
    Tally t = check(near_boundary_cases(p, n, 32), bound_scale());
    EXPECT_EQ(t.wrong, 0) << primitive_name(p) << ": " << t.first_wrong;
    EXPECT_GT(t.decided, 0) << primitive_name(p);
  }
}

// The checks above can fail: with every bound divided by 2^8 (the cone's by 2^12), the filter
// decides wrongly on some of the same near-boundary rays. (Halved, the bounds of all but the
// box still hold on every ray here: they carry slack, the running bounds of the quadrics most.
// The plane's and the disk's are caught from 1/16 on, the triangle's from 1/32, the polygon's
// and the cylinder's from 1/64, the capsule's from 1/256, the cone's from 1/4096; the box's
// halved is caught below.)
TEST(StaticFilter, ABoundTooSmallIsCaught) {
  for (Primitive p : kScaled) {
    double shrink = p == primitive_of<Cone>() ? 0x1p-12 : 0x1p-8;
    Tally t = check(near_boundary_cases(p, 2000, 32), shrink);
    EXPECT_GT(t.wrong, 0) << primitive_name(p);
  }
}

// A bound halved is caught where the bound is tight: the box's 2.1u(|x| + |y|) is within 5% of
// the most two slab ends can be off. This ray enters the x slab at t*ₓ = (lo_x − o_x)/d_x just
// after it leaves the y slab at t*ᵧ = (hi_y − o_y)/d_y, both near 1.5: an exact miss. Its
// inputs were found by a search for ends whose two roundings (the difference, then the
// division) each come near their most, the x end's downwards and the y end's upwards, so that
// the computed ends lie two ulps apart the wrong way round (a gap of 4u against 2.1u·3 ≈ 6.3u
// at the full bound, 3.15u at half of it). At the full bound the filter leaves the ray to the
// ladder; at half it certifies a hit, which the MPFR truth refutes.
TEST(StaticFilter, AHalvedBoundIsCaught) {
  AccuracyCase c;
  c.id = "box-ends-two-ulps-the-wrong-way";
  c.primitive = primitive_of<Box>();
  c.origin = {-0x1.cf0f9e336e2a8p-2, -0x1.44de32d374468p-2, 0};
  c.direction = {0x1.55f0650b9bfe9p-1, 0x1.5553b7c790ff9p-1, 1};
  c.points = {{0x1.1968ec30a8fb1p-1, -0x1.51378cb4dd11ap+0, -10},
              {0x1.e30f061cc91d6p+2, 0x1.5d969a3fd1e6fp-1, 10}};
  Truth truth = compute_truth(c, false);
  ASSERT_FALSE(truth.boundary);
  EXPECT_FALSE(truth.hit);
  EXPECT_EQ(check({c}, 1).wrong, 0);
  EXPECT_FALSE(filtered_double(c, 1).has_value());
  Tally halved = check({c}, 0.5);
  EXPECT_EQ(halved.decided, 1);
  EXPECT_EQ(halved.wrong, 1);
}

// The triangle's first bound cannot be caught halved: where det, U or V is exactly zero their
// rounding errors add up, to first order, to at most 19u·X·Y·Z (V's to 15u; W's to 57u against
// its 4B), below the halved 25u (docs/precision.md). This ray comes near that most:
// U = s·(D × e₂), exactly −5·10⁻⁵u·X·Y·Z (the ray passes just outside the edge from c to a),
// comes out 16.1u·X·Y·Z above zero, while det, V, W and t's numerator lie far from zero (about
// 4, 3.75, 0.25 and 0.25 times X·Y·Z; X, Y and Z within 10⁻⁶ of 1). Its inputs were found by a
// hill climb over their low bits, from the signs that give the most error. At the full bound and
// at half of it the filter leaves the ray (so a constant below 2·16.1u fails here); at 0.3 of
// it (15u·X·Y·Z) it certifies a hit, which the MPFR truth refutes.
TEST(StaticFilter, ATriangleBoundCutToThreeTenthsIsCaught) {
  AccuracyCase c = make_case("triangle-u-16u-the-wrong-way", "scale", primitive_of<Triangle>(),
                             {0x1.2383985ca7916p+0, -0x1.6f7e1939f39e5p+0, 0x1.1eece6cfab23dp+0},
                             {-0x1.000002913aca6p+0, -0x1.0000015ff0128p+0, -0x1.00000a880263ap+0},
                             {{0x1.1c1c7d1c58074p-3, -0x1.1efc2fc6d6bccp-1, 0x1.eecdfb14e0968p-4},
                              {0x1.238369d8d13bp+0, -0x1.8f7287828fef8p+0, -0x1.c22511e78a54dp-1},
                              {0x1.23839ed898405p+0, -0x1.8f7e23b00f1e4p+0, 0x1.1eececa84e6a6p+0}});
  Truth truth = compute_truth(c, false);
  ASSERT_FALSE(truth.boundary);
  EXPECT_FALSE(truth.hit);
  EXPECT_FALSE(filtered_double(c, 1).has_value());
  EXPECT_FALSE(filtered_double(c, 0.5).has_value());
  Tally cut = check({c}, 0.3);
  EXPECT_EQ(cut.decided, 1);
  EXPECT_EQ(cut.wrong, 1);
}

// The triangle's first bound takes D's scale cubed; the second takes it once, so a direction
// far longer than the triangle is still decided. The triangle (0,0,0), (1,0,0), (0,1,0) and
// O = (−0.75, −0.75, 1), D = 2^30·(1, 1, −1): O + t·D meets z = 0 at t = 2^-30, at
// (0.25, 0.25, 0), inside; from O = (1, 1, 1) the same D meets it at (2, 2, 0), outside. There
// det = 2^30 against a first bound of 50u·2^90 ≈ 2^42, and a second of 12u·3·2^30·2.5² ≈ 2^-15.
TEST(StaticFilter, TheTriangleDecidesAFarLongerDirection) {
  const std::vector<Vec3d> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Vec3d d = 0x1p30 * Vec3d{1, 1, -1};
  AccuracyCase hit =
      make_case("long-hit", "scale", primitive_of<Triangle>(), {-0.75, -0.75, 1}, d, tri);
  AccuracyCase miss = make_case("long-miss", "scale", primitive_of<Triangle>(), {1, 1, 1}, d, tri);
  for (const AccuracyCase& c : {hit, miss}) {
    TriangleHit<double> first;
    EXPECT_FALSE(filtered_triangle<TriangleBound::kAxes>(c.origin, c.direction, tri[0], tri[1],
                                                         tri[2], first))
        << c.id;
  }
  std::optional<FilterAnswer> h = filtered_double(hit, 1), m = filtered_double(miss, 1);
  ASSERT_TRUE(h.has_value());
  EXPECT_TRUE(h->hit);
  EXPECT_LE(h->t_lo, 0x1p-30);
  EXPECT_GE(h->t_hi, 0x1p-30);
  ASSERT_TRUE(m.has_value());
  EXPECT_FALSE(m->hit);
}

}  // namespace
}  // namespace raygrade
