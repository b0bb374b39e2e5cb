// Cone: the circle of `radius` at `base` and the apex at base + height·â, open or with its
// base cap.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "sampling/outcome.h"
#include "shapes/filter_roots.h"
#include "shapes/round.h"
#include "shapes/shape.h"
#include "shapes/sphere.h"
#include "shapes/surface_point.h"

namespace raygrade {

struct AccuracyCase;
class SplitMix;

// The side's quadratic of the cone with apex A and axis vector v = A − B (|v| = h, B the base's
// centre; any number type T), for the ray O + tD. A point P is on the side when, with q = P − B,
// v·v |q × v|² = r² (v·v − q·v)² (that is h²|q⊥|² = r²(h − s)², times h²); with f = O − B,
// α = D·v, β = f·v and w = v·v − β that is a t² + b t + c = 0 with
//   a = (v·v)|D × v|² − r²α²,  b = 2((v·v)(f × v)·(D × v) + r² w α),  c = (v·v)|f × v|² − r² w².
// It is computed from the apex, g = O − A (f × v = g × v, w = −g·v), and its quarter discriminant
// from the identity
//   Δ' = (b/2)² − ac = (v·v)² (r²(v·v)|m|² − (v·v + r²)(m·v)²),  m = D × g,
// which cancels only where the ray is tangent (the plane through the apex and the ray touches
// the cone), not where the ray passes near the apex. No square root other than √Δ': for
// whole-number data along a coordinate axis every term is a whole number. A root t lies on
// the cone (not the other nappe, not below the base) where −v·v ≤ γ + tα ≤ 0, γ = g·v.
template <typename T>
struct ConeSide {
  T a{}, half_b{}, c{}, vv{}, alpha{}, gamma{};
  T disc{};   // Δ' / (v·v)²
  Vec3<T> g;  // O − A
};

template <typename T>
ConeSide<T> cone_side(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& apex, const Vec3<T>& v,
                      const T& r) {
  ConeSide<T> k;
  k.g = o - apex;
  k.vv = dot(v, v);
  T rr = r * r;
  Vec3<T> gv = cross_fused(k.g, v), dv = cross_fused(d, v), m = cross_fused(d, k.g);
  k.alpha = dot_fused(d, v);
  k.gamma = dot_fused(k.g, v);
  T w = -k.gamma, mv = dot_fused(m, v);
  k.a = k.vv * dot(dv, dv) - rr * (k.alpha * k.alpha);
  k.half_b = k.vv * dot(gv, dv) + rr * (w * k.alpha);
  k.c = k.vv * dot(gv, gv) - rr * (w * w);
  k.disc = rr * k.vv * dot(m, m) - (k.vv + rr) * (mv * mv);
  return k;
}

// The real roots of the side's quadratic, ascending, by the stable q = −(b/2 + sign(b)√Δ'),
// t = q/a and c/q: one when a = 0 (a ray parallel to a line of the side), none and `contained`
// when a = b = c = 0 (the ray's line is a line of the side, through the apex).
template <typename T>
Roots<T> cone_side_roots(const ConeSide<T>& k, bool& contained) {
  using std::sqrt;
  Roots<T> out;
  contained = false;
  if (k.a == T(0)) {
    if (k.half_b == T(0)) {
      contained = k.c == T(0);
      return out;
    }
    out.count = 1;
    out.t0 = out.t1 = -k.c / (T(2) * k.half_b);
    return out;
  }
  if (k.disc < T(0)) return out;
  if (k.disc == T(0)) {
    out.count = 1;
    out.t0 = out.t1 = -k.half_b / k.a;
    return out;
  }
  return both_roots(Quadratic<T>{k.a, k.half_b, k.c, k.vv * k.vv * k.disc}, k.vv * sqrt(k.disc));
}

// Whether the side's root t lies on the cone: −v·v ≤ γ + tα ≤ 0 (0 ≤ s ≤ h).
template <typename T>
bool cone_on_side(const ConeSide<T>& k, const T& t) {
  T s = k.gamma + t * k.alpha;
  return s >= -k.vv && s <= T(0);
}

// The cone side's quadratic for the static filter (docs/precision.md, "Static filters"):
// cone_side's own coefficients in double, with the bound γ_n·(the same polynomial on magnitudes)
// on each, n the most roundings on a path from an input to it (cylinder_side_bounded). g = O − A
// and v = A − B, rounded differences, count one rounding each: a has n = 16, b/2 17, c 18 and
// Δ'/(v·v)² 23; the bounds take (n + 1)·u. The root scale is v·v, within 6u of the exact one.
// The side's own test, −v·v ≤ γ + tα ≤ 0 at a root, needs γ and α: their bounds go in
// `gamma_error` and `alpha_error` beside the side and its quadratic. False when a vector's 1-norm
// or the radius lies beyond kFilterInputLimit.
struct BoundedConeSide {
  ConeSide<double> side;
  BoundedQuadratic k;
  double gamma_error = 0, alpha_error = 0;
};
[[gnu::always_inline]] inline bool cone_side_bounded(const Vec3d& o, const Vec3d& d,
                                                     const Vec3d& apex, const Vec3d& v, double r,
                                                     double bound_scale, BoundedConeSide& out) {
  constexpr double u = kUnitRoundoff<double>;
  ConeSide<double>& side = out.side;
  BoundedQuadratic& k = out.k;
  side = cone_side(o, d, apex, v, r);
  const Vec3d& g = side.g;
  // Magnitudes: of D × v and g × v by 1-norms; of m = D × g component by component, since D and
  // g are nearly parallel for a ray aimed at the cone from afar, where the 1-norms would
  // overstate the discriminant's error most.
  Vec3d v_m = magnitudes(v), d_m = magnitudes(d), g_m = magnitudes(g);
  double n_d = norm1(d), n_v = norm1(v), n_g = norm1(g);
  if (!within_filter_limit(n_d, n_v, n_g, r)) return false;
  double dv_m = n_d * n_v, gv_m = n_g * n_v;
  Vec3d m_v{d_m.y * g_m.z + d_m.z * g_m.y, d_m.z * g_m.x + d_m.x * g_m.z,
            d_m.x * g_m.y + d_m.y * g_m.x};
  double mm_m = dot_fused(m_v, m_v), mv_m = dot_fused(m_v, v_m);
  double alpha_m = dv_m, gamma_m = gv_m;  // the magnitudes of D·v and g·v, by 1-norms too
  double vv = side.vv, rr = r * r;
  double slack = kFilterUnderflowSlack;
  k.a = side.a;
  k.b = side.half_b;
  k.c = side.c;
  k.disc = side.disc;
  k.scale = vv;
  k.a_error = (17 * u * (vv * (dv_m * dv_m) + rr * (alpha_m * alpha_m)) + slack) * bound_scale;
  k.b_error = (18 * u * (vv * (gv_m * dv_m) + rr * (gamma_m * alpha_m)) + slack) * bound_scale;
  k.c_error = (19 * u * (vv * (gv_m * gv_m) + rr * (gamma_m * gamma_m)) + slack) * bound_scale;
  k.disc_error = (24 * u * (rr * vv * mm_m + (vv + rr) * (mv_m * mv_m)) + slack) * bound_scale;
  out.gamma_error = (6 * u * gamma_m + slack) * bound_scale;
  out.alpha_error = (5 * u * alpha_m + slack) * bound_scale;
  return true;
}

// Is the enclosed root r on the cone, −v·v ≤ γ + tα ≤ 0 for its exact t and the exact γ, α and
// v·v? 1 or −1 when certain (on it or not), 0 when not. s = γ + tα at r.t is within
// |γ − γ*| + width·|α| + (|t| + width)·|α − α*| of the exact one, and two roundings
// (u·(|tα| + |s|)); s + v·v adds 6u·v·v and one rounding. 1.01 covers the bound's own rounding.
[[gnu::always_inline]] inline int cone_root_on_side(const BoundedConeSide& bounded,
                                                    const FilterAnswer& r, double bound_scale) {
  using std::abs;
  constexpr double u = kUnitRoundoff<double>;
  const ConeSide<double>& side = bounded.side;
  double gamma_error = bounded.gamma_error, alpha_error = bounded.alpha_error;
  double width = enclosure_width(r), ta = r.t * side.alpha, s = side.gamma + ta;
  double s_error = 1.01 * (gamma_error + width * abs(side.alpha) +
                           (abs(r.t) + width) * alpha_error + u * bound_scale * (abs(ta) + abs(s)));
  double low = s + side.vv;
  double low_error = s_error + 1.01 * u * bound_scale * (6 * side.vv + abs(low));
  int top = certain_sign(s, s_error), bottom = certain_sign(low, low_error);
  if (top > 0 || bottom < 0) return -1;
  if (top < 0 && bottom > 0) return 1;
  return 0;
}

class Cone final : public Shape {
 public:
  // What the accuracy study needs of an open cone (shapes/ladder_primitives.h).
  struct Ladder;

  Cone(Vec3d base, Vec3d axis, double radius, double height, bool capped);
  static std::unique_ptr<Shape> read(const Cursor& object);

  static constexpr std::string_view kType = "cone";
  static constexpr std::string_view kSummary = "base, axis, radius, height, optional base cap";
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
  std::vector<std::string> methods() const override { return {"quadratic"}; }
  Derivation derive(const Ray& ray, std::string_view method,
                    const Overrides* overrides) const override;
  nlohmann::json to_json() const override;
  Vec3d center() const override { return base_ + (height_ / 2) * axis_; }
  double extent() const override { return std::max(radius_, height_ / 2); }
  void sketch(Sketch& figure, const std::string& label) const override;
  // Closed with its cap.
  bool solid() const override { return capped_; }
  static constexpr std::string_view kNormalMistake = "inward-normal";
  static constexpr std::string_view kNormalSentence =
      " A cone's side has the outward normal (h·ê + r·â)/√(h² + r²), ê the unit vector across "
      "the axis towards P; at the apex it is â; the base cap's is −â.";
  static constexpr std::string_view kContainedLine =
      "The ray runs along a line of the cone's side through its apex (a = b = c = 0): it "
      "meets the side along a whole segment";
  std::optional<QuadraticSteps> quadratic() const override { return QuadraticSteps{}; }

 private:
  Vec3d base_;
  Vec3d axis_given_;
  Vec3d axis_;  // unit
  double radius_;
  double height_;
  bool capped_;
  // The apex, when the cone was made from an accuracy case (Ladder::shape_of): it is then
  // intersected with v = apex − B exactly, as the case is, not with h·â rebuilt from the
  // rounded height.
  std::optional<Vec3d> apex_;
};

// The case's points: {base, apex} of an open cone; its radius. A capped cone has no case (as a
// finite cylinder), nor a cone whose apex − base, rounded, is not exactly h·â: the case must be
// the very cone the solver intersects.
struct Cone::Ladder {
  static constexpr std::size_t kPoints = 2;
  static constexpr bool kMorePoints = false, kRadius = true;
  static constexpr int kDirectionPoint = -1;

  // The side's roots (cone_side_roots), the nearest at t ≥ 0 that lies on the cone, as intersect
  // runs them in double-double. A ray along a line of the side (contained) has no answer here:
  // the solver reports it as contained and settles nothing.
  template <typename T>
  [[gnu::always_inline]] static bool reference(const Vec3<T>& o, const Vec3<T>& d,
                                               const std::vector<Vec3<T>>& p, const T& r, T& t) {
    ConeSide<T> k = cone_side(o, d, p[1], Vec3<T>(p[1] - p[0]), r);
    bool contained = false;
    Roots<T> roots = cone_side_roots(k, contained);
    T ts[2] = {roots.t0, roots.t1};
    for (int i = 0; i < roots.count; ++i) {
      if (ts[i] >= T(0) && cone_on_side(k, ts[i])) {
        t = ts[i];
        return true;
      }
    }
    return false;
  }

  // The static filter: cone_side_bounded's quadratic, its roots enclosed (enclose_roots), each
  // certainly on the cone or not (cone_root_on_side), the nearest kept at t > 0. Its t is the
  // reference's own (the same coefficients, root and quotients).
  [[gnu::always_inline]] static bool filter(const Vec3d& o, const Vec3d& d,
                                            const std::vector<Vec3d>& p, double r,
                                            FilterAnswer& out, double bound_scale) {
    BoundedConeSide bounded;
    EnclosedRoots roots;
    if (!cone_side_bounded(o, d, p[1], Vec3d(p[1] - p[0]), r, bound_scale, bounded) ||
        !enclose_roots(bounded.k, roots)) {
      return false;
    }
    // The roots in the order of their t, as the reference takes them: it stops at the first
    // kept, and so does the filter when that one lies certainly before the other.
    NearestKept nearest;
    bool swapped = roots.count == 2 && roots.root[1].t < roots.root[0].t;
    for (int i = 0; i < roots.count; ++i) {
      const FilterAnswer& root = roots.root[swapped ? 1 - i : i];
      if (root.t_hi < 0) continue;
      if (nearest.nearest.hit && nearest.nearest.t_hi < root.t_lo) break;
      int on = cone_root_on_side(bounded, root, bound_scale);
      if (on == 0 || (on > 0 && !nearest.keep(root))) return false;
    }
    out = nearest.nearest;
    return true;
  }

  // The textbook cone: from the apex A along ĉ = (B − A)/h, with cos²θ = h²/(h² + r²) and
  // co = O − A, a = (D·ĉ)² − cos²θ D·D, b = 2((D·ĉ)(co·ĉ) − cos²θ D·co),
  // c = (co·ĉ)² − cos²θ co·co; the roots (−b ∓ √Δ)/2a, kept where 0 ≤ (P − A)·ĉ ≤ h.
  template <typename T>
  static std::optional<T> naive(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p,
                                const T& r) {
    using std::sqrt;
    Vec3<T> down = p[0] - p[1];
    T h = sqrt(dot(down, down));
    Vec3<T> c_hat = down / h;
    T cos2 = h * h / (h * h + r * r);
    Vec3<T> co = o - p[1];
    T dc = dot(d, c_hat), cc = dot(co, c_hat);
    T a = dc * dc - cos2 * dot(d, d), b = T(2) * (dc * cc - cos2 * dot(d, co)),
      c = cc * cc - cos2 * dot(co, co);
    T disc = b * b - T(4) * a * c;
    if (a == T(0) || disc < T(0)) return std::nullopt;
    T root = sqrt(disc);
    T ts[2] = {(-b - root) / (T(2) * a), (-b + root) / (T(2) * a)};
    if (ts[1] < ts[0]) std::swap(ts[0], ts[1]);
    for (const T& t : ts) {
      T s = dot(o + t * d - p[1], c_hat);
      if (t >= T(0) && s >= T(0) && s <= h) return t;
    }
    return std::nullopt;
  }

  // Every root on the cone with its outward normal, the gradient of
  // v·v |q × v|² − r²(v·v − q·v)², halved, which from the apex (q = v + g, g = P − A) is
  // (v·v)((v·v) g − (g·v) v) − r²(g·v) v: (h·ê + r·â) times a positive number on the side, and
  // zero at the apex. Within the solver's seam of the apex (64 ulps of r + h), where the solver
  // gives the apex's documented normal â, the normal is ambiguous: zero.
  template <typename T, typename Add>
  static void hits(const Vec3<T>& o, const Vec3<T>& d, const std::vector<Vec3<T>>& p, const T& r,
                   Add&& add) {
    using std::sqrt;
    Vec3<T> v = p[1] - p[0];
    ConeSide<T> k = cone_side(o, d, p[1], v, r);
    bool contained = false;
    Roots<T> roots = cone_side_roots(k, contained);
    T ts[2] = {roots.t0, roots.t1};
    for (int i = 0; i < roots.count; ++i) {
      if (!cone_on_side(k, ts[i])) continue;
      Vec3<T> g = k.g + ts[i] * d;
      T gv = dot(g, v), seam = T(kSeamRelative) * (r + sqrt(k.vv));
      Vec3<T> n = k.vv * (k.vv * g - gv * v) - ((r * r) * gv) * v;
      add(ts[i], dot(g, g) <= seam * seam ? Vec3<T>{} : n);
    }
  }

  // (h·ê + r·â)/√(h² + r²) at P, ê across the axis towards P; â at the apex.
  static std::optional<Vec3d> naive_normal(const std::vector<Vec3d>& p, double r,
                                           const Vec3d& point) {
    Vec3d v = p[1] - p[0];
    double h = length(v);
    Vec3d axis = v / h, q = point - p[0];
    Vec3d across = q - dot(q, axis) * axis;
    if (length(across) == 0) return axis;
    return normalized(h * normalized(across) + r * axis);
  }

  static bool case_of(const Cone& cone, std::vector<Vec3d>& points, double& radius);
  static std::unique_ptr<Shape> shape_of(const std::vector<Vec3d>& p, double r) {
    Vec3d v = p[1] - p[0];
    auto cone = std::make_unique<Cone>(p[0], v, r, length(v), false);
    cone->apex_ = p[1];
    return cone;
  }

  static void random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius);
  // Its own stream, in round kOwnStreamRound: rays through the apex and the rim, tangent to the
  // side, parallel to a line of the side, grazing, far cones, huge coordinates, and rays worked
  // by hand.
  static void hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out);
};

}  // namespace raygrade
