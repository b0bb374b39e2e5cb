// Box: axis-aligned, between corners min and max; the slab method.
#pragma once

#include <algorithm>
#include <limits>

#include "sampling/outcome.h"
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
