// Disk: the closed flat disk of a centre, a normal and a radius.
#pragma once

#include <limits>
#include <optional>

#include "math/robust.h"
#include "sampling/outcome.h"
#include "shapes/filter_answer.h"
#include "shapes/plane.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"

namespace raygrade {

// Is the point p of the disk's plane inside the closed disk, |p − c|² ≤ r²? In float, double
// and long double a point within 16 epsilon of r² beyond the rim is on it (the rounding of p and
// of the squares, so that a ray worked by hand through the rim hits); in the other types
// (double-double, MPFR, intervals) the comparison is exact, so that the certified levels and the
// ground truth decide the closed disk itself.
template <typename T>
bool disk_inside(const Vec3<T>& p, const Vec3<T>& center, const T& r) {
  Vec3<T> f = p - center;
  T r2 = r * r;
  if constexpr (kErrorFree<T>) r2 = r2 * (T(1) + T(16) * std::numeric_limits<T>::epsilon());
  return dot(f, f) <= r2;
}

// The disk's static filter: plane_filter's decision and enclosure of t, then the rim test
// |P − C|² ≤ r² at P = O + tD as the reference computes it, decided when |P − C|² lies farther
// from r² than a bound that takes in the enclosure's width and every rounding
// (docs/precision.md). True with the exact decision and t (the reference's own) enclosed in
// `out`. `bound_scale` multiplies the bounds (see filtered_double).
// With t̂ the plane's t and δ ≥ |t̂ − t*| (t* the exact t) twice the half-width of t's enclosure
// with e taken from quotient_bound (at least x/size, at most twice it: no division waits), each
// component g_i = (o_i + t̂·d_i) − c_i, rounded three times (m_i = t̂·d_i, s_i = o_i + m_i, g_i),
// is within e_i = u(|g_i| + |s_i| + |m_i|) + δ|d_i| of the exact o_i + t*·d_i − c_i, and
// |s_i| + |m_i| ≤ (1 + u)²(|o_i| + 2|t̂||d_i|). So Σ e_i ≤ E = 2u(‖g‖₁ + (1 + 4u)(‖o‖₁ +
// 2|t̂|‖d‖₁)) + 2δ‖d‖₁ (the doubled constants cover the rounding of E itself), and
// |Σ g_i² − Σ g*_i²| ≤ Σ e_i(2|g_i| + e_i) ≤ E(2‖g‖₁ + E). S = Σ g_i² carries γ₃ of its own
// (4u·S) and r² rounds once (2u·r²): the rim test is decided when |S − r²| exceeds their sum by a
// thousandth (the bound's evaluation rounds fewer than 20 times). r² in [2^-900, 2^900] and
// finite sums keep the products normal or the underflow's absolute errors (2^-1075 each) far
// inside the slack u·r² ≥ 2^-953.
[[gnu::always_inline]] inline bool disk_filter(const Vec3d& o, const Vec3d& d, const Vec3d& center,
                                               const Vec3d& normal, double r, FilterAnswer& out,
                                               double bound_scale) {
  constexpr double u = kUnitRoundoff<double>;
  PlaneQuotient q;
  if (!plane_quotient_filter(o, d, normal, center, bound_scale, q)) return false;
  out = {};
  if ((q.num < 0) != (q.den < 0)) return true;  // behind the origin: a certain miss
  double rr = r * r;
  double t = q.num / q.den;
  double o_norm = norm1(o);
  double d_norm = norm1(d);
  // enclose_quotient's half-width, with e at most twice x/size (e ≤ 2τ ≤ 1/8 still), doubled.
  double width = 2 * std::abs(t) * (1.25 * quotient_bound(q.x, q.size) + 3 * u);
  // What E takes before g: every term but ‖g‖₁.
  double e_rest = 2 * u * (1 + 4 * u) * (o_norm + 2 * std::abs(t) * d_norm) + 2 * width * d_norm;
  Vec3d g = (o + t * d) - center;  // as disk_inside rounds it
  double s = dot(g, g), g_norm = norm1(g);
  double e = 2 * u * g_norm + e_rest;
  double error = 1.001 * (e * (2 * g_norm + e) + 4 * u * s + 2 * u * rr) * bound_scale;
  double gap = s - rr;
  // enclose_quotient's range for t, r²'s, finite sums, and the gap beyond its bound; joined
  // without short circuits (values named first: clang warns of a bitwise & on a call's result).
  constexpr double kMax = std::numeric_limits<double>::max();
  double t_m = std::abs(t), gap_m = std::abs(gap);
  if (!((t_m >= kQuotientFloor) & (t_m <= kMax) & (rr >= kQuotientFloor) &
        (rr <= 1 / kQuotientFloor) & (gap_m > error) & (error <= kMax))) {
    return false;
  }
  if (gap < 0) {
    out.hit = true;
    return enclose_quotient_within_limit(t, q.x / q.size, 1, out);
  }
  return true;
}

struct AccuracyCase;
class SplitMix;

// The plan of the flat primitives: the ray meets the disk's plane at t, then the point P is
// inside when |P − C|² ≤ r², the rim included (the disk is closed).
class Disk final : public Shape {
 public:
  // What the accuracy study needs of a disk (shapes/ladder_primitives.h).
  struct Ladder;

  Disk(Vec3d center, Vec3d normal, double radius)
      : center_(center), normal_(normal), radius_(radius) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "disk";
  static constexpr std::string_view kSummary = "center, normal, radius; the rim included";
  // Its fragment of the problem schema: its own keys, and examples.
  static nlohmann::ordered_json schema();
  // Its generator: the outcomes it can build, and a problem for one of them (a random one when none
  // is asked) with nice numbers.
  static const std::vector<Outcome>& outcomes();
  static Draft generate(Prng& rng, std::optional<Outcome> outcome);
  // The normal kind: the part of its surface nearest to the object-space point p, with the outward
  // normal there (`tie`: how near two parts must both be for p to lie where they meet), and the
  // steps that derive that normal at P.
  SurfacePoint nearest_surface(const Vec3d& p, double tie) const;
  void derive_normal(Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) const;

  std::string_view type() const override { return kType; }
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"plane-then-distance"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return center_; }
  double extent() const override { return radius_; }
  void sketch(Sketch& figure, const std::string& label) const override;

 private:
  // Is the point P of the disk's plane inside the closed disk?
  bool inside(const Vec3d& point) const;

  Vec3d center_;
  Vec3d normal_;  // as given, not normalized
  double radius_;
};

// The case's points: {center, normal}; its radius.
struct Disk::Ladder {
  static constexpr std::size_t kPoints = 2;
  static constexpr bool kMorePoints = false, kRadius = true;
  static constexpr int kDirectionPoint = 1;

  // The plane's t, then the distance test at P = O + tD, as intersect runs them.
  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& r, T& t) {
    std::optional<T> x = plane_t(o, d, p[1], p[0]);
    if (!x || !(*x >= T(0)) || !disk_inside(o + *x * d, p[0], r)) return false;
    t = *x;
    return true;
  }

  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double r,
                                            FilterAnswer& out, double bound_scale) {
    return disk_filter(o, d, p[0], p[1], r, out, bound_scale);
  }

  // t = n·(c − o) / n·d, then |P − C| ≤ r with a square root.
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& r) {
    using std::sqrt;
    std::optional<T> t = naive_plane_t(o, d, p[1], p[0]);
    if (!t) return std::nullopt;
    Vec3<T> q = o + *t * d - p[0];
    if (sqrt(dot(q, q)) > r) return std::nullopt;
    return t;
  }

  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p, const T& r,
                   Add&& add) {
    std::optional<T> t = plane_t(o, d, p[1], p[0]);
    if (t && disk_inside(o + *t * d, p[0], r)) add(*t, p[1]);
  }

  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double /*r*/,
                                           const Vec3d& /*point*/) {
    return normalized(p[1]);
  }

  static bool case_of(const Disk& disk, std::vector<Vec3d>& points, double& radius) {
    points = {disk.center_, disk.normal_};
    radius = disk.radius_;
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double r) {
    return std::make_unique<Disk>(p[0], p[1], r);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Its own stream, in round kOwnStreamRound: rays through the rim, far disks, rays grazing the
  // plane across the rim, huge coordinates, and rim rays worked by hand.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
