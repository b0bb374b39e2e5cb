// Disk: the closed flat disk of a centre, a normal and a radius.
#pragma once

#include <limits>
#include <optional>

#include "math/robust.h"
#include "sampling/outcome.h"
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
