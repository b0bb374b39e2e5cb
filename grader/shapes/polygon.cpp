// Polygon: reading with planarity checks, reference intersection, edge-test and
// crossing-number derivations.
#include "shapes/polygon.h"

#include <algorithm>
#include <limits>

#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/flats.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"
#include "shapes/flat.h"
#include "shapes/plane.h"
#include "shapes/triangle.h"

namespace raygrade {
namespace {

// Vertices farther than this fraction of the polygon's size from its plane make it
// non-planar. Generous next to rounding (1e-16), tiny next to any drawn polygon.
constexpr double kPlanarityRelative = 1e-9;

bool is_convex(const std::vector<Vec3d>& v, const Vec3d& n) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3d& a = v[i];
    const Vec3d& b = v[(i + 1) % v.size()];
    const Vec3d& c = v[(i + 2) % v.size()];
    if (dot(cross(b - a, c - b), n) < 0) return false;
  }
  return true;
}

// The bound of d_z² times an edge function, in units of u·(d_z·M)² (polygon_filter).
constexpr double kPolygonEdgeUlps = 18;

// The crossing count of watertight_polygon for the frame (KX, KY, KZ) (k_z the largest
// component of D), swapped when flip (d_z < 0), from exact signs: true with the exact count's
// parity in `inside` when every vertex's sheared y and every edge function lie beyond their
// bounds (polygon_filter). Compile-time axes: picking a component by a run-time index costs a
// load through memory for each.
template <int KX, int KY, int KZ>
[[gnu::always_inline]] inline bool polygon_crossings(const Vec3d& o, const Vec3d& d, const Vec3d* v,
                                                     std::size_t k, bool flip, double bound_scale,
                                                     bool& inside) {
  constexpr double u = kUnitRoundoff<double>;
  const double dz = d[KZ], dx = d[KX], dy = d[KY];
  // X = d_z·w_x − d_x·w_z and Y = d_z·w_y − d_y·w_z in the unswapped frame, with w = v − O.
  const Vec3d w0 = v[0] - o;
  const double x0 = dz * w0[KX] - dx * w0[KZ], y0 = dz * w0[KY] - dy * w0[KZ];
  double m = norm1(w0), norms = m;  // norms: NaN or infinite when some w is
  double xa = x0, ya = y0;
  double sheared_y = flip ? xa : ya;
  double least_y = std::abs(sheared_y), least_edge = std::numeric_limits<double>::infinity();
  bool a_up = (sheared_y > 0) != flip;
  bool in = false;
  for (std::size_t i = 1; i <= k; ++i) {
    double xb = x0, yb = y0;
    if (i < k) {
      const Vec3d w = v[i] - o;
      const double norm = norm1(w);
      norms += norm;
      m = std::max(m, norm);
      xb = dz * w[KX] - dx * w[KZ];
      yb = dz * w[KY] - dy * w[KZ];
    }
    sheared_y = flip ? xb : yb;
    least_y = std::min(least_y, std::abs(sheared_y));
    const bool b_up = (sheared_y > 0) != flip;
    const double e = xa * yb - ya * xb;  // d_z² times the edge function, negated when flip
    least_edge = std::min(least_edge, std::abs(e));
    in ^= (a_up != b_up) & (((e > 0) != flip) == b_up);
    xa = xb;
    ya = yb;
    a_up = b_up;
  }
  const double nd = norm1(d), dm = std::abs(dz) * m;
  constexpr double kHuge = kFastPathRange<double>, kTiny = 1 / (kHuge * kHuge * kHuge);
  const double y_bound = 4 * u * nd * m * bound_scale;
  const double edge_bound = kPolygonEdgeUlps * u * dm * dm * bound_scale;
  inside = in;
  return (nd <= kHuge) & (m <= kHuge) & (norms <= kHuge * kHuge) & (y_bound >= kTiny) &
         (edge_bound >= kTiny) & (least_y > y_bound) & (least_edge > edge_bound);
}

}  // namespace

// The polygon's static filter (docs/precision.md, "Static filters").
// - Newell's normal: each of its k terms rounds three times and their sum k − 1 times, so each
//   component is within γ_(k+2) of the sum of its terms' magnitudes; (k + 4)u covers that, the
//   rounding of the sum of magnitudes, and k·2^-1074 the terms that underflow.
// - The sheared test's signs, without its divisions: with w = v − O, in the frame (x, y, z) of
//   watertight_polygon (x and y swapped when d_z < 0), a vertex's sheared coordinates are X/d_z
//   and Y/d_z with X = d_z·w_x − d_x·w_z, Y = d_z·w_y − d_y·w_z, and an edge function is
//   (X_a·Y_b − Y_a·X_b)/d_z². X and Y round three times from exact inputs (w, the products, the
//   difference): within γ₃(|d_z||w_y| + |d_y||w_z|) ≤ 3.01u·|d_z|·M of the exact ones (M the
//   largest 1-norm of the rounded w; |d_x|, |d_y| ≤ |d_z|), inside the bound 4u·‖D‖₁·M of y.
//   With |X|, |Y| ≤ (1 + 3.01u)|d_z|·M, each product X_a·Y_b is within 2·3.02u·(d_z·M)² of the
//   exact one, and the two products and their difference round within 2.01u·2(d_z·M)²: the edge
//   function times d_z² is within 16.1u·(d_z·M)², and kPolygonEdgeUlps = 18 covers the rounding
//   of M and of the bound. In the swapped frame the sheared y is X and the edge function is
//   negated, exactly. The range is the triangle's (‖D‖₁, M at most 2^254, both bounds at least
//   2^-762, every w finite).
bool polygon_filter(const Vec3d& o, const Vec3d& d, const std::vector<Vec3d>& vertices,
                    FilterAnswer& out, double bound_scale) {
  constexpr double u = kUnitRoundoff<double>;
  constexpr std::size_t kMaxVertices = std::size_t(1) << 20;  // keeps k·u far below 1
  const std::size_t k = vertices.size();
  if (k < 3 || k > kMaxVertices) return false;
  const Vec3d* v = vertices.data();
  // Newell's normal as newell_normal_of computes it, with the magnitudes of its terms.
  Vec3d n{}, terms{};
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3d& a = v[i];
    const Vec3d& b = i + 1 < k ? v[i + 1] : v[0];
    double x = (a.y - b.y) * (a.z + b.z), y = (a.z - b.z) * (a.x + b.x),
           z = (a.x - b.x) * (a.y + b.y);
    n.x += x;
    n.y += y;
    n.z += z;
    terms.x += std::abs(x);
    terms.y += std::abs(y);
    terms.z += std::abs(z);
  }
  const double n_ulps = (static_cast<double>(k) + 4) * u,
               n_underflow = static_cast<double>(k) * 0x1p-1074;
  const Vec3d n_error{n_ulps * terms.x + n_underflow, n_ulps * terms.y + n_underflow,
                      n_ulps * terms.z + n_underflow};
  FilterAnswer plane;
  if (!plane_filter(o, d, n, v[0], plane, bound_scale, &n_error)) return false;
  if (!plane.hit) {
    out = {};
    return true;  // parallel or behind the origin, certainly: a miss
  }
  const int kz = max_dimension(d);
  const bool flip = d[kz] < 0;
  bool inside = false, certain = false;
  if (kz == 0) {
    certain = polygon_crossings<1, 2, 0>(o, d, v, k, flip, bound_scale, inside);
  } else if (kz == 1) {
    certain = polygon_crossings<2, 0, 1>(o, d, v, k, flip, bound_scale, inside);
  } else {
    certain = polygon_crossings<0, 1, 2>(o, d, v, k, flip, bound_scale, inside);
  }
  if (!certain) return false;
  out = inside ? plane : FilterAnswer{};
  return true;
}

Polygon::Polygon(std::vector<Vec3d> vertices)
    : v_(std::move(vertices)),
      normal_(rounded(newell_normal_of(std::vector<Vec3dd>(v_.begin(), v_.end())))),
      unit_normal_(unit_rounded(Vec3dd(normal_))),
      convex_(is_convex(v_, normal_)) {}

std::unique_ptr<Shape> Polygon::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.emplace_back("vertices");
  object.allow_only(keys);
  Cursor list = object.at("vertices");
  std::vector<Vec3d> v;
  for (const auto& item : list.items()) v.push_back(item.vec3());
  if (v.size() < 3)
    list.fail(fmt::format("a polygon needs at least 3 vertices, found {}", v.size()), "degenerate");
  double size = 0;
  for (const auto& p : v) size = std::max(size, length(p - v[0]));
  Vec3d n = newell_normal(v);
  if (length(n) <= 1e-14 * size * size) {
    list.fail("degenerate polygon: the vertices are collinear or enclose no area", "degenerate");
  }
  // The plane through the vertices' centroid with Newell's normal fits them best; name the
  // vertex farthest from it.
  Vec3d unit = normalized(n);
  Vec3d centroid{};
  for (const auto& p : v) centroid = centroid + p / static_cast<double>(v.size());
  std::size_t worst = 0;
  double worst_off = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    double off = std::abs(dot(unit, v[i] - centroid));
    if (off > worst_off) {
      worst = i;
      worst_off = off;
    }
  }
  if (worst_off > kPlanarityRelative * size) {
    list.items()[worst].fail(
        fmt::format("non-planar polygon: vertex {} lies {:.6g} off the plane that best fits the "
                    "vertices",
                    worst, worst_off),
        "degenerate");
  }
  return std::make_unique<Polygon>(std::move(v));
}

nlohmann::json Polygon::to_json() const {
  nlohmann::json vs = nlohmann::json::array();
  for (const auto& v : v_) vs.push_back({v.x, v.y, v.z});
  return {{"type", "polygon"}, {"vertices", vs}};
}

std::vector<std::string> Polygon::methods() const {
  if (convex_) return {"edge-tests", "crossing-number"};
  return {"crossing-number"};
}

Vec3d Polygon::center() const {
  Vec3d c{};
  for (const auto& p : v_) c = c + p;
  return c / static_cast<double>(v_.size());
}

double Polygon::extent() const {
  Vec3d c = center();
  double r = 0;
  for (const auto& p : v_) r = std::max(r, length(p - c));
  return r;
}

Intersection Polygon::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  if (parallel_to_plane(normal_, ray.direction)) {
    out.contained =
        in_plane(normal_, v_[0], ray.origin) && ray_in_plane_meets_polygon(ray, v_, normal_);
    return out;
  }
  std::optional<double> t = plane_t(ray.origin, ray.direction, normal_, v_[0]);
  if (!t || !ray.accepts(*t)) return out;
  if (!ray_pierces_polygon(ray, v_)) return out;
  Hit h;
  h.t = *t;
  h.point = ray.at(*t);
  h.normal = unit_normal_;
  out.hits.push_back(h);
  return out;
}

Derivation Polygon::derive(const Ray& ray, std::string_view method,
                           const Overrides* overrides) const {
  bool edges = convex_ && method != "crossing-number";
  Deriver d(edges ? "edge-tests" : "crossing-number",
            edges ? "Convex polygon: plane hit, then edge tests"
                  : "Polygon: plane hit, then the crossing-number test",
            overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  std::vector<E> V;
  for (std::size_t i = 0; i < v_.size(); ++i) {
    V.push_back(d.given(fmt::format("v{}", i), fmt::format("v_{}", i), v_[i]));
  }
  E sum = cross(V[0], V[1]);
  for (std::size_t i = 1; i < V.size(); ++i) sum = sum + cross(V[i], V[(i + 1) % V.size()]);
  d.step("n", "n", sum, "Newell's normal: the sum of v_i × v_(i+1), by vertex order");
  E n = d.sym("n");
  double den = d.step("denominator", dot(n, D), dot(n, D)).scalar;
  if (den == 0) {
    d.note("n·D = 0: the ray is parallel to the polygon's plane.");
    d.conclude("The ray is parallel to the polygon's plane: it has no single hit point.");
    return std::move(d).finish();
  }
  d.step("numerator", dot(n, V[0] - O), dot(n, V[0] - O));
  double t = d.step("t", "t", d.sym("numerator") / d.sym("denominator")).scalar;
  Value q = d.step("q", "q", O + d.sym("t") * D, "the point where the ray meets the plane");
  bool inside = true;
  std::vector<std::string> negative;  // the edge tests that fail
  if (edges) {
    for (std::size_t i = 0; i < V.size(); ++i) {
      std::size_t j = (i + 1) % V.size();
      std::string name = fmt::format("e{}", i);
      double e = d.step(name, fmt::format("e_{}", i), dot(cross(V[j] - V[i], d.sym("q") - V[i]), n),
                        fmt::format("edge v{} v{}: ≥ 0 means inside", i, j))
                     .scalar;
      inside = inside && e >= 0;
      if (e < 0) negative.push_back(fmt::format("e_{}", i));
    }
  } else {
    inside = point_in_polygon(q.vector, v_, normal_);
    int drop = max_dimension(normal_);
    const char* axes[] = {"x", "y", "z"};
    d.step("crossings", "crossings", inside ? 1 : 0,
           fmt::format("project onto the plane without {} (the normal's largest component) and "
                       "cast a ray from q along +{}: an odd number of edge crossings means "
                       "inside (1 stands for odd, 0 for even; a point on an edge is inside)",
                       axes[drop], axes[(drop + 1) % 3]));
  }
  std::string reason =
      inside ? range_reason(ray, t)
      : negative.empty()
          ? "the plane point q lies outside the polygon (an even number of crossings)"
          : fmt::format("the plane point q lies outside the polygon ({} < 0)",
                        fmt::join(negative, ", "));
  conclude_candidates(d, "polygon", ray, {{t, q.vector, reason}}, false);
  return std::move(d).finish();
}

void Polygon::sketch(Sketch& figure, const std::string& label) const {
  figure.path(v_, true, Ink::kObject, label);
}

nlohmann::ordered_json Polygon::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "required": [
    "vertices"
  ],
  "properties": {
    "vertices": {
      "type": "array",
      "items": {
        "$ref": "#/$defs/vec3"
      },
      "minItems": 3,
      "description": "a planar simple polygon, convex or not; the normal follows the vertex order"
    }
  },
  "examples": [
    {
      "type": "polygon",
      "vertices": [
        [
          -2,
          -2,
          3
        ],
        [
          2,
          -2,
          3
        ],
        [
          2,
          2,
          3
        ],
        [
          -2,
          2,
          3
        ]
      ]
    }
  ]
}
)json");
}

// The accuracy study's cases of polygons.

void Polygon::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& /*radius*/) {
  Vec3d c = rng.point(0.3), e1 = rng.unit_vector(), e2 = perpendicular(e1, rng);
  points.clear();
  for (int k = 0; k < 5; ++k) {
    double a = 2 * M_PI * k / 5, s = rng.uniform(0.5, 1);
    points.push_back(c + (s * std::cos(a)) * e1 + (s * std::sin(a)) * e2);
  }
}

void Polygon::Ladder::hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out) {
  if (round != 3) return;
  for (int i = 0; i < 20; ++i) {
    // Two planar polygons (a pentagon and a quad) sharing the edge v0 v2 of a plane.
    Vec3d base{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d e1{1, 0, 0}, e2{0, 1, 0};
    if (i % 2 == 1) e2 = Vec3d{0, 0.5, 0.5};  // a tilted plane with exact coordinates
    auto at = [&](double x, double y) { return base + x * e1 + y * e2; };
    std::vector<Vec3d> left = {at(0, 0), at(0, 2), at(-1, 2.5), at(-2, 1), at(-1, -0.5)};
    std::vector<Vec3d> right = {at(0, 2), at(0, 0), at(1.5, 0.5), at(1, 2)};
    Vec3d target = at(0, rng.uniform(0, 2));
    Vec3d o = target + Vec3d{rng.uniform(-1, 1), rng.uniform(-1, 1), 3};
    std::string id = fmt::format("shared-polygon-edge-{}", i);
    out.push_back(
        make_case(id + "/a", "shared-edge", primitive_of<Polygon>(), o, target - o, left));
    out.push_back(
        make_case(id + "/b", "shared-edge", primitive_of<Polygon>(), o, target - o, right));
  }
}

// The polygon's normal at a point: Newell's, by vertex order, the same over the face.

SurfacePoint Polygon::nearest_surface(const Vec3d& p, double /*tie*/) const {
  return nearest_flat(v_, p);
}

void Polygon::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                            const NormalNames& n) const {
  derive_flat_normal(d, v_, n);
}

// The polygon's generator: puts the hit at a lattice point of its plane and builds the ray
// backwards from it.

const std::vector<Outcome>& Polygon::outcomes() { return kFlatOutcomes; }

Draft Polygon::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kFlatOutcomes);
  Frame f = random_frame(rng);
  std::vector<Vec3d> v;
  Vec3d inside, outside, edge;
  if (rng.below(2)) {
    int w = rng.range(2, 5), h = rng.range(2, 5);
    v = {f.at(0, 0), f.at(w, 0), f.at(w, h), f.at(0, h)};
    int y = rng.range(1, h - 1), x = rng.range(1, w - 1);
    inside = f.at(x, y);
    outside = f.at(w + 1, rng.range(0, h));
    edge = f.at(w, rng.range(1, h - 1));
  } else {
    // An L: not convex; its notch is outside.
    int k = rng.range(1, 2);
    for (auto [x, y] :
         std::vector<std::pair<int, int>>{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}) {
      v.push_back(f.at(k * x, k * y));
    }
    inside = f.at(k, k);
    outside = f.at(3 * k, 3 * k);
    edge = f.at(4 * k, k);
  }
  if (rng.below(2)) std::reverse(v.begin(), v.end());
  Vec3d p = o == Outcome::kMiss ? outside : o == Outcome::kTangent ? edge : inside;
  nlohmann::ordered_json object = {{"type", "polygon"}, {"vertices", vertices_json(v)}};
  return flat_draft(rng, o, p, f.normal(), object,
                    fmt::format("the polygon with vertices {}", vertices_text(v)));
}

}  // namespace raygrade
