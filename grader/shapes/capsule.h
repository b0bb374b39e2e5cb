// Capsule: the segment ab swept by a sphere of radius r (a cylinder with two hemispherical ends).
#pragma once

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "sampling/outcome.h"
#include "shapes/cylinder.h"
#include "shapes/shape.h"
#include "shapes/sphere.h"
#include "shapes/surface_point.h"

namespace raygrade {

struct AccuracyCase;
class SplitMix;

// Which part of a capsule {a, b} a point P = O + tD of its side's cylinder or of an end sphere
// belongs to, by the sign of the height along u = b − a (any length: only the sign counts):
// the side where (P − a)·u ≥ 0 and (P − b)·u ≤ 0, the end a where (P − a)·u ≤ 0, the end b
// where (P − b)·u ≥ 0. P − a is taken as (O − a) + tD, so that a far origin keeps its digits.
template <typename T>
T capsule_height(const Vec3<T>& o, const Vec3<T>& d, const T& t, const Vec3<T>& end,
                 const Vec3<T>& u) {
  return dot((o - end) + t * d, u);
}

// The nearest hit at t ≥ 0 of a capsule from the roots of its side and of its end spheres
// (side_roots and end_roots(i) give them, ascending): every root kept lies on the capsule's
// surface, so the smallest is the capsule's first hit.
template <typename T, typename SideRoots, typename EndRoots>
bool capsule_nearest(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& a, const Vec3<T>& b,
                     SideRoots&& side_roots, EndRoots&& end_roots, T& t) {
  Vec3<T> u = b - a;
  bool found = false;
  auto consider = [&](const T& x) {
    if (x >= T(0) && (!found || x < t)) {
      t = x;
      found = true;
    }
  };
  Roots<T> side = side_roots();
  T side_t[2] = {side.t0, side.t1};
  for (int i = 0; i < side.count; ++i) {
    if (capsule_height(o, d, side_t[i], a, u) >= T(0) &&
        capsule_height(o, d, side_t[i], b, u) <= T(0))
      consider(side_t[i]);
  }
  for (int end = 0; end < 2; ++end) {
    Roots<T> k = end_roots(end);
    T end_t[2] = {k.t0, k.t1};
    for (int i = 0; i < k.count; ++i) {
      T s = capsule_height(o, d, end_t[i], end == 0 ? a : b, u);
      if (end == 0 ? s <= T(0) : s >= T(0)) consider(end_t[i]);
    }
  }
  return found;
}

// The real roots of a t² + b t + c = 0 as a textbook takes them: (−b ∓ √Δ)/2a.
template <typename T>
Roots<T> naive_quadratic_roots(T a, T b, T c) {
  using std::sqrt;
  Roots<T> out;
  T disc = b * b - T(4) * a * c;
  if (a == T(0) || disc < T(0)) return out;
  T s = sqrt(disc);
  out.count = 2;
  out.t0 = (-b - s) / (T(2) * a);
  out.t1 = (-b + s) / (T(2) * a);
  return out;
}

// The hits are the side's (the cylinder of radius r around ab, where the height s along the
// axis from a lies in [0, h], h = |b − a|) and the end spheres' (around a where s ≤ 0, around b
// where s ≥ h). A hit on the rim between the side and an end is found by both and listed once.
// The sign of the exact height ((o − e) + t·d)·u of an enclosed root r above the end e, for the
// static filter, with u the rounded b − a standing for the exact one: 1 or −1 when certain, 0
// when not. Each component g = (o − e) + t·d, rounded three times, is within
// u·(|o − e| + |t·d| + |g|) + width·|d| of the exact one at the exact t, u's within u·|u|, and the
// products and their sum round within 3u·|g·u| more: the bound sums
// |u|·(u·(|o − e| + |t·d|) + 5u·|g| + width·|d|), 1.01 covering its own rounding.
[[gnu::always_inline]] inline int capsule_height_sign(const Vec3d& o, const Vec3d& d,
                                                      const FilterAnswer& r, const Vec3d& end,
                                                      const Vec3d& axis, double bound_scale) {
  using std::abs;
  constexpr double u = kUnitRoundoff<double>;
  double width = enclosure_width(r), h = 0, error = 0;
  for (int i = 0; i < 3; ++i) {
    double oe = o[i] - end[i], m = r.t * d[i], g = oe + m;
    h += g * axis[i];
    error += abs(axis[i]) * (u * (abs(oe) + abs(m)) + 5 * u * abs(g) + width * abs(d[i]));
  }
  return certain_sign(h, (1.01 * error + kFilterUnderflowSlack) * bound_scale);
}

class Capsule final : public Shape {
 public:
  // What the accuracy study needs of a capsule (shapes/ladder_primitives.h).
  struct Ladder;

  Capsule(Vec3d a, Vec3d b, double radius);
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "capsule";
  static constexpr std::string_view kSummary = "segment ends a and b, radius";
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
  std::vector<std::string> methods() const override { return {"side-and-ends"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return 0.5 * (a_ + b_); }
  double extent() const override { return height_ / 2 + radius_; }
  void sketch(Sketch& figure, const std::string& label) const override;
  bool solid() const override { return true; }
  static constexpr std::string_view kNormalMistake = "inward-normal";
  static constexpr std::string_view kNormalSentence =
      " A capsule's outward normal is (P − Q)/r, Q the nearest point of the segment ab: on "
      "the side the foot of P on the axis, on an end that end's centre a or b.";
  std::optional<QuadraticSteps> quadratic() const override { return QuadraticSteps{}; }

 private:
  Vec3d a_, b_;
  double radius_;
  Vec3d axis_;     // unit, from a to b
  double height_;  // |b − a|
};

// The case's points: {a, b}; its radius.
struct Capsule::Ladder {
  static constexpr std::size_t kPoints = 2;
  static constexpr bool kMorePoints = false, kRadius = true;
  static constexpr int kDirectionPoint = -1;

  // The side's roots (the cylinder's stable formulas, around the axis normalized at the
  // precision of the computation) and the end spheres' (the sphere's), each kept on its part.
  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& r, T& t) {
    using std::sqrt;
    Vec3<T> u = p[1] - p[0];
    Vec3<T> axis = u / sqrt(dot(u, u));
    return capsule_nearest(
        o, d, p[0], p[1], [&] { return cylinder_side_roots(o, d, p[0], axis, r); },
        [&](int end) { return sphere_roots(o, d, p[end], r); }, t);
  }

  // The static filter: the side's roots from cylinder_side_bounded with the axis b − a, and each
  // end sphere's from the sphere's fast path (whose quotients are within kFilterError, as its
  // own filter takes them), each root enclosed, certainly on its part or not (capsule_height_sign),
  // the nearest kept at t > 0.
  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double r,
                                            FilterAnswer& out, double bound_scale) {
    Vec3d u = p[1] - p[0];
    BoundedQuadratic k;
    EnclosedRoots side;
    if (!cylinder_side_bounded(o, d, p[0], u, r, bound_scale, k) || !enclose_roots(k, side))
      return false;
    NearestKept nearest;
    for (int i = 0; i < side.count; ++i) {
      const FilterAnswer& root = side.root[i];
      if (root.t_hi < 0) continue;
      int above_a = capsule_height_sign(o, d, root, p[0], u, bound_scale);
      int above_b = capsule_height_sign(o, d, root, p[1], u, bound_scale);
      if (above_a == 0 || above_b == 0) return false;
      if (above_a > 0 && above_b < 0 && !nearest.keep(root)) return false;
    }
    for (int end = 0; end < 2; ++end) {
      Quadratic<double> sphere;
      FastPath fast = sphere_quadratic_fast(o, d, p[end], r, sphere);
      if (fast == FastPath::kUndecided) return false;
      if (fast == FastPath::kMiss) continue;
      double q = stable_q(sphere, std::sqrt(sphere.disc));
      FilterAnswer roots[2];
      if (!enclose_quotient(sphere.c / q, Sphere::Ladder::kFilterError, 1, roots[0]) ||
          !enclose_quotient(q / sphere.a, Sphere::Ladder::kFilterError, 1, roots[1])) {
        return false;
      }
      for (const FilterAnswer& root : roots) {
        if (root.t_hi < 0) continue;
        int above = capsule_height_sign(o, d, root, p[end], u, bound_scale);
        if (above == 0) return false;
        if ((end == 0 ? above < 0 : above > 0) && !nearest.keep(root)) return false;
      }
    }
    out = nearest.nearest;
    return true;
  }

  // The textbook quadratics: the side's on the components across the unit axis, each end's
  // with b = 2 d·(o − c); the roots (−b ± √Δ)/2a, the height of P = O + tD along the axis.
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& r) {
    using std::sqrt;
    Vec3<T> u = p[1] - p[0];
    Vec3<T> axis = u / sqrt(dot(u, u));
    T t;
    auto side = [&] {
      Vec3<T> f = o - p[0];
      Vec3<T> fp = f - dot(f, axis) * axis, dp = d - dot(d, axis) * axis;
      return naive_quadratic_roots(dot(dp, dp), T(2) * dot(fp, dp), dot(fp, fp) - r * r);
    };
    auto end = [&](int i) {
      Vec3<T> f = o - p[i];
      return naive_quadratic_roots(dot(d, d), T(2) * dot(f, d), dot(f, f) - r * r);
    };
    if (!capsule_nearest(o, d, p[0], p[1], side, end, t)) return std::nullopt;
    return t;
  }

  // Every hit with its outward normal, nearest first: on the side the component across the
  // axis, on an end from its centre. A rim point (height 0 at a, or at b) is the side's: the ends
  // keep only the points strictly beyond their end, so that it is listed once.
  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p, const T& r,
                   Add&& add) {
    using std::sqrt;
    Vec3<T> u = p[1] - p[0];
    Vec3<T> axis = u / sqrt(dot(u, u));
    std::vector<std::pair<T, Vec3<T>>> found;
    Roots<T> side = cylinder_side_roots(o, d, p[0], axis, r);
    T side_t[2] = {side.t0, side.t1};
    for (int i = 0; i < side.count; ++i) {
      const T& t = side_t[i];
      if (capsule_height(o, d, t, p[0], u) >= T(0) && capsule_height(o, d, t, p[1], u) <= T(0)) {
        Vec3<T> v = (o - p[0]) + t * d;
        found.emplace_back(t, v - dot(v, axis) * axis);
      }
    }
    for (int end = 0; end < 2; ++end) {
      Roots<T> k = sphere_roots(o, d, p[end], r);
      T end_t[2] = {k.t0, k.t1};
      for (int i = 0; i < k.count; ++i) {
        T s = capsule_height(o, d, end_t[i], p[end], u);
        if (end == 0 ? s < T(0) : s > T(0))
          found.emplace_back(end_t[i], (o - p[end]) + end_t[i] * d);
      }
    }
    std::sort(found.begin(), found.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [t, normal] : found) add(t, normal);
  }

  // (P − Q)/r, Q the point of the segment nearest P.
  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double r,
                                           const Vec3d& point) {
    Vec3d u = p[1] - p[0];
    double s = dot(point - p[0], u) / dot(u, u);
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return (point - (p[0] + s * u)) / r;
  }

  static bool case_of(const Capsule& c, std::vector<Vec3d>& points, double& radius) {
    points = {c.a_, c.b_};
    radius = c.radius_;
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double r) {
    return std::make_unique<Capsule>(p[0], p[1], r);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Its own stream, in round kOwnStreamRound: rays through the rims, tangent to the side and to
  // an end, grazing, far capsules, huge coordinates, and rays worked by hand.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
