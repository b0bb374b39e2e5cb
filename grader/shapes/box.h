// Box: axis-aligned, between corners min and max; the slab method.
#pragma once

#include <algorithm>
#include <limits>

#include "sampling/outcome.h"
#include "shapes/filter_answer.h"
#include "shapes/shape.h"
#include "shapes/sphere.h"
#include "shapes/surface_point.h"

namespace raygrade {

// The interval of t inside the closed box, and the axes whose slabs bound it. A direction
// component of exactly zero is handled without dividing (no NaN when the origin lies on a
// slab plane): the slab then holds all t or none.
template <typename T>
struct SlabInterval {
  bool hit = false;
  T t_enter{}, t_exit{};
  int enter_axis = -1, exit_axis = -1;  // -1: unbounded along the ray
};

// Inlined where it is called: returned through memory from a call, the interval costs about as
// much as the slabs' arithmetic.
template <typename T>
[[gnu::always_inline]] inline SlabInterval<T> slab_interval(const Vec3<T>& o, const Vec3<T>& d,
                                                            const Vec3<T>& lo, const Vec3<T>& hi) {
  SlabInterval<T> s;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == T(0)) {
      if (o[i] < lo[i] || o[i] > hi[i]) return s;
      continue;
    }
    // Selections rather than branches: the signs of d and the order of the slabs are as
    // random as the rays, and a mispredicted branch costs more than the arithmetic.
    T t_low = (lo[i] - o[i]) / d[i], t_high = (hi[i] - o[i]) / d[i];
    bool backward = d[i] < T(0);
    T t_near = backward ? t_high : t_low, t_far = backward ? t_low : t_high;
    bool later = s.enter_axis < 0 || t_near > s.t_enter;
    bool sooner = s.exit_axis < 0 || t_far < s.t_exit;
    s.t_enter = later ? t_near : s.t_enter;
    s.enter_axis = later ? i : s.enter_axis;
    s.t_exit = sooner ? t_far : s.t_exit;
    s.exit_axis = sooner ? i : s.exit_axis;
  }
  s.hit = s.t_enter <= s.t_exit;
  return s;
}

// The box's static filter: slab_interval's slab ends, and every comparison the decision rests
// on (the slabs' entries with one another, their exits with one another, entry against exit,
// and the signs of entry and exit) decided only when the two values lie farther apart than their
// bounds (docs/precision.md). True with the exact decision and t (the reference's own) enclosed
// in `out`. `bound_scale` multiplies the bounds (see filtered_double). A slab end
// t = (b − o)/d is exact when b = o (b − o is then exactly zero), and otherwise, when it is
// normal and finite, t*(1 + α)(1 + β) with |α|, |β| ≤ u (the difference is exact where it
// underflows; the quotient does not underflow): |t − t*| ≤ 2.01u|t|, and t has the sign of t*.
// Two exact values x* < y* are certain when the computed y − x exceeds 2.1u(|x| + |y|): the two
// errors take 2.01u(|x| + |y|), and the rounding of y − x and of the bound at most 3u of it. Every
// pair of entries, and of exits, must be certain, so that the maximum and the minimum are the exact
// ones (and the ground truth, which compares them, is decided). A zero direction component makes
// its slab all or nothing, exactly.
[[gnu::always_inline]] inline bool box_filter(const Vec3d& o, const Vec3d& d, const Vec3d& lo,
                                              const Vec3d& hi, FilterAnswer& out,
                                              double bound_scale) {
  constexpr double u = kUnitRoundoff<double>;
  const double k = 2.1 * u * bound_scale;
  auto certain_less = [&](double x, double y) { return y - x > k * (std::abs(x) + std::abs(y)); };
  // x* ≠ y* certain, one way or the other: |y − x| is the same for both (fl(x − y) = −fl(y − x)).
  // The magnitudes come with the values (the range test below takes them anyway).
  auto certain_apart = [&](double x, double y, double x_m, double y_m) {
    return std::abs(y - x) > k * (x_m + y_m);
  };
  auto in_range = [](double difference, double t_m) {
    return difference == 0 || (t_m >= kQuotientFloor && t_m <= 1 / kQuotientFloor);
  };
  double near[3], far[3], near_m[3], far_m[3];
  int count = 0;
  bool outside = false, ends_in_range = true;
  auto slab = [&](int i, int j) {
    // Selections and accumulated tests rather than branches, as in slab_interval.
    double low = lo[i] - o[i], high = hi[i] - o[i];
    double t_low = low / d[i], t_high = high / d[i];
    double low_m = std::abs(t_low), high_m = std::abs(t_high);
    // Named first: clang warns of a bitwise & on calls' results.
    bool low_in_range = in_range(low, low_m), high_in_range = in_range(high, high_m);
    ends_in_range &= low_in_range & high_in_range;
    bool backward = d[i] < 0;
    near[j] = backward ? t_high : t_low;
    far[j] = backward ? t_low : t_high;
    near_m[j] = backward ? high_m : low_m;
    far_m[j] = backward ? low_m : high_m;
  };
  auto pair_apart = [&](int i, int j) {
    bool near_apart = certain_apart(near[i], near[j], near_m[i], near_m[j]);
    bool far_apart = certain_apart(far[i], far[j], far_m[i], far_m[j]);
    return near_apart & far_apart;
  };
  double enter = 0, leave = 0;
  if ((d.x != 0) & (d.y != 0) & (d.z != 0)) {
    // Every slab bounds the ray (nearly every ray): three of each, in registers.
    slab(0, 0);
    slab(1, 1);
    slab(2, 2);
    bool apart = pair_apart(0, 1) & pair_apart(0, 2) & pair_apart(1, 2);
    if (!(ends_in_range & apart)) return false;
    enter = std::max({near[0], near[1], near[2]});
    leave = std::min({far[0], far[1], far[2]});
  } else {
    for (int i = 0; i < 3; ++i) {
      if (d[i] == 0) {
        outside |= o[i] < lo[i] || o[i] > hi[i];
        continue;
      }
      slab(i, count);
      ++count;
    }
    if (!ends_in_range || count == 0) return false;
    enter = near[0];
    leave = far[0];
    bool apart = true;
    for (int i = 1; i < count; ++i) {
      for (int j = 0; j < i; ++j) apart &= pair_apart(i, j);
      enter = std::max(enter, near[i]);
      leave = std::min(leave, far[i]);
    }
    if (!apart) return false;
  }
  out = {};
  if (outside) return true;
  if (certain_less(leave, enter)) return true;  // the slabs do not overlap: a miss
  if (!certain_less(enter, leave)) return false;
  double t = enter >= 0 ? enter : leave;
  if (!(t >= 0)) return true;  // the box lies behind the origin
  out.hit = true;
  if (t == 0) {
    out.t = out.t_lo = out.t_hi = t;  // the origin on a face: exactly 0
    return true;
  }
  return enclose_quotient(t, 2 * u * bound_scale, 1, out);
}

class Box final : public Shape {
 public:
  // What the accuracy study needs of a box (shapes/ladder_primitives.h).
  struct Ladder;

  Box(Vec3d lo, Vec3d hi) : lo_(lo), hi_(hi) {}
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "box";
  static constexpr std::string_view kSummary = "axis-aligned, min and max corners";
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
  bool solid() const override { return true; }
  static constexpr std::string_view kNormalMistake = "inward-normal";
  static constexpr std::string_view kNormalSentence =
      " A box's outward normal is the axis of the slab hit, pointing away from the box's centre.";
  Intersection intersect(const Ray& ray) const override;
  std::vector<std::string> methods() const override { return {"slab"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return (lo_ + hi_) / 2.0; }
  double extent() const override { return length(hi_ - lo_) / 2; }
  void sketch(Sketch& figure, const std::string& label) const override;

 private:
  Vec3d lo_, hi_;
};

// The case's points: {min, max}; no radius.
struct Box::Ladder {
  static constexpr std::size_t kPoints = 2;
  static constexpr bool kMorePoints = false, kRadius = false;
  static constexpr int kDirectionPoint = -1;

  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& /*r*/,
                                               T& t) {
    SlabInterval<T> s = slab_interval(o, d, p[0], p[1]);
    return s.hit && nearest_root(Roots<T>{2, s.t_enter, s.t_exit}, t);
  }

  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double /*r*/,
                                            FilterAnswer& out, double bound_scale) {
    return box_filter(o, d, p[0], p[1], out, bound_scale);
  }

  // The slab method with plain divisions (a zero direction component gives ±∞, and NaN when
  // the origin lies on that slab's plane).
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& /*r*/) {
    const Vec3<T>&lo = p[0], &hi = p[1];
    T t_enter = -std::numeric_limits<T>::infinity(), t_exit = std::numeric_limits<T>::infinity();
    for (int i = 0; i < 3; ++i) {
      T t1 = (lo[i] - o[i]) / d[i], t2 = (hi[i] - o[i]) / d[i];
      t_enter = std::max(t_enter, std::min(t1, t2));
      t_exit = std::min(t_exit, std::max(t1, t2));
    }
    if (t_enter > t_exit) return std::nullopt;
    return naive_nearest_root(t_enter, t_exit);
  }

  // The faces' normals are exact (and ambiguous at an edge): zero.
  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                   const T& /*r*/, Add&& add) {
    SlabInterval<T> s = slab_interval(o, d, p[0], p[1]);
    if (s.hit) {
      add(s.t_enter, Vec3<T>{});
      if (!(s.t_exit == s.t_enter)) add(s.t_exit, Vec3<T>{});
    }
  }

  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& /*p*/, double /*r*/,
                                           const Vec3d& /*point*/) {
    return std::nullopt;
  }

  static bool case_of(const Box& box, std::vector<Vec3d>& points, double& /*radius*/) {
    points = {box.lo_, box.hi_};
    return true;
  }
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double /*r*/) {
    return std::make_unique<Box>(p[0], p[1]);
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Round 5: origins on slab planes, rays through corners and edges.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
