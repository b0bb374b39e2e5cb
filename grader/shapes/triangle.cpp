// Triangle: reading, reference intersection and the edge-test derivation of seeds 001 and 004.
#include "shapes/triangle.h"

#include <algorithm>

#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/flats.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"
#include "shapes/flat.h"

namespace raygrade {

// A triangle whose area is below this fraction of its longest edge squared is degenerate:
// its normal would be noise. Far below any triangle an exercise draws.
constexpr double kDegenerateArea = 1e-14;

std::unique_ptr<Shape> Triangle::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.emplace_back("vertices");
  object.allow_only(keys);
  auto items = object.at("vertices").items();
  if (items.size() != 3) {
    object.at("vertices")
        .fail(fmt::format("a triangle has 3 vertices, found {}", items.size()), "type");
  }
  Vec3d a = items[0].vec3(), b = items[1].vec3(), c = items[2].vec3();
  double longest = std::max({length_squared(b - a), length_squared(c - b), length_squared(a - c)});
  if (length(cross_accurate(b - a, c - a)) <= kDegenerateArea * longest) {
    object.at("vertices")
        .fail("degenerate triangle: the vertices are collinear or coincide", "degenerate");
  }
  return std::make_unique<Triangle>(a, b, c);
}

nlohmann::json Triangle::to_json() const {
  nlohmann::json vs = nlohmann::json::array();
  for (const auto& v : v_) vs.push_back({v.x, v.y, v.z});
  return {{"type", "triangle"}, {"vertices", vs}};
}

double Triangle::extent() const {
  Vec3d c = center();
  return std::sqrt(
      std::max({length_squared(v_[0] - c), length_squared(v_[1] - c), length_squared(v_[2] - c)}));
}

Intersection Triangle::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  Vec3d n = cross_accurate(v_[1] - v_[0], v_[2] - v_[0]);
  if (parallel_to_plane(n, ray.direction)) {
    out.contained =
        in_plane(n, v_[0], ray.origin) && ray_in_plane_meets_polygon(ray, {v_[0], v_[1], v_[2]}, n);
    return out;
  }
  auto hit = watertight_triangle(ray.origin, ray.direction, v_[0], v_[1], v_[2]);
  if (!hit.hit || !ray.accepts(hit.t)) return out;
  Hit h;
  h.t = hit.t;
  h.point = ray.at(hit.t);
  // (b − a) × (c − a) from the exact differences in double-double: a needle triangle's
  // edges are nearly parallel, and their cross product cancels in double.
  h.normal = unit_rounded(cross(difference_dd(v_[1], v_[0]), difference_dd(v_[2], v_[0])));
  h.barycentric = hit.barycentric;
  out.hits.push_back(h);
  return out;
}

Derivation Triangle::derive(const Ray& ray, std::string_view /*method*/,
                            const Overrides* overrides) const {
  Deriver d("edge-tests", "Triangle: plane hit, then edge tests", overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  E A = d.given("a", "a", v_[0]);
  E B = d.given("b", "b", v_[1]);
  E C = d.given("c", "c", v_[2]);
  d.step("n", "n", cross_written_out(B - A, C - A), "the normal (b − a) × (c − a), by components");
  E n = d.sym("n");
  double den = d.step("denominator", dot(n, D), dot(n, D)).scalar;
  if (den == 0) {
    double s = d.step("numerator", dot(n, A - O), dot(n, A - O)).scalar;
    d.note("n·D = 0: the ray is parallel to the triangle's plane.");
    d.conclude(s == 0 ? "The ray lies in the triangle's plane: it meets the plane along a line, "
                        "not at a point, so there is no single hit point."
                      : "The ray is parallel to the triangle's plane and off it: no hit.");
    return std::move(d).finish();
  }
  d.step("numerator", dot(n, A - O), dot(n, A - O));
  double t = d.step("t", "t", d.sym("numerator") / d.sym("denominator"),
                    "where the ray meets the plane n·(x − a) = 0")
                 .scalar;
  Value q = d.step("q", "q", O + d.sym("t") * D, "the point where the ray meets the plane");
  E Q = d.sym("q");
  double e0 =
      d.step("e_ab", "e_ab", dot(cross(B - A, Q - A), n), "edge ab: ≥ 0 means inside").scalar;
  double e1 =
      d.step("e_bc", "e_bc", dot(cross(C - B, Q - B), n), "edge bc: ≥ 0 means inside").scalar;
  double e2 =
      d.step("e_ca", "e_ca", dot(cross(A - C, Q - C), n), "edge ca: ≥ 0 means inside").scalar;
  bool inside = e0 >= 0 && e1 >= 0 && e2 >= 0;
  Value w_a, w_b, w_c;
  if (inside) {
    w_a = d.step("w_a", "w_a", d.sym("e_bc") / dot(n, n), "barycentric weight of a");
    w_b = d.step("w_b", "w_b", d.sym("e_ca") / dot(n, n), "barycentric weight of b");
    w_c = d.step("w_c", "w_c", d.sym("e_ab") / dot(n, n), "barycentric weight of c");
    d.step("w", "w", tuple(d.sym("w_a"), d.sym("w_b"), d.sym("w_c")),
           "the weights (w_a, w_b, w_c) of a, b and c");
  }
  std::vector<std::string> outside;
  if (e0 < 0) outside.emplace_back("e_ab");
  if (e1 < 0) outside.emplace_back("e_bc");
  if (e2 < 0) outside.emplace_back("e_ca");
  std::string reason = inside ? range_reason(ray, t)
                              : fmt::format("the plane point q lies outside the triangle ({} < 0)",
                                            fmt::join(outside, ", "));
  conclude_candidates(d, "triangle", ray, {{t, q.vector, reason}}, false);
  if (inside) {
    // The weights computed above belong in the answer too: P = w_a·a + w_b·b + w_c·c.
    d.conclude(Sentence("In barycentric weights, P = w_a·a + w_b·b + w_c·c with w_a = ")
                   .value(w_a.scalar)
                   .text(", w_b = ")
                   .value(w_b.scalar)
                   .text(", w_c = ")
                   .value(w_c.scalar)
                   .text("."));
  }
  return std::move(d).finish();
}

void Triangle::sketch(Sketch& figure, const std::string& label) const {
  figure.path({v_[0], v_[1], v_[2]}, true, Ink::kObject, label);
}

nlohmann::ordered_json Triangle::schema() {
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
      "maxItems": 3,
      "description": "[a, b, c]; the normal is (b − a) × (c − a)"
    }
  },
  "examples": [
    {
      "type": "triangle",
      "vertices": [
        [
          -1,
          -1,
          5
        ],
        [
          2,
          -1,
          5
        ],
        [
          -1,
          2,
          5
        ]
      ]
    }
  ]
}
)json");
}

// The accuracy study's cases of triangles.

void Triangle::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& /*radius*/) {
  Vec3d a = rng.point(1), b = rng.point(1);
  points = {a, b, rng.point(1)};
}

namespace {

AccuracyCase triangle_case(std::string id, std::string group, Vec3d o, Vec3d d, Vec3d a, Vec3d b,
                           Vec3d c) {
  return make_case(std::move(id), std::move(group), primitive_of<Triangle>(), o, d, {a, b, c});
}

void shared_edges(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    double scale = i % 4 == 3 ? 1e8 : 1;  // some far from the origin
    Vec3d shift = scale == 1 ? Vec3d{} : scale * rng.unit_vector();
    // A quad folded along its diagonal q0 q2, q1 and q3 on either side of it as seen from
    // above, where the rays come from.
    auto jitter = [&](double x, double y) {
      return shift +
             Vec3d{x + rng.uniform(-0.3, 0.3), y + rng.uniform(-0.3, 0.3), rng.uniform(-0.2, 0.2)};
    };
    Vec3d q[4] = {jitter(-1, -1), jitter(1, -1), jitter(1, 1), jitter(-1, 1)};
    Vec3d o = shift + Vec3d{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(2, 4)};
    if (i % 3 == 0) {
      // A fan of five triangles around a vertex, each ray exactly at the vertex.
      Vec3d center = jitter(0, 0), d = center - o;
      std::vector<Vec3d> rim;
      for (int k = 0; k < 5; ++k) {
        double a = 2 * M_PI * k / 5 + rng.uniform(-0.3, 0.3);
        rim.push_back(center + Vec3d{std::cos(a), std::sin(a), rng.uniform(-0.3, 0.3)});
      }
      for (int k = 0; k < 5; ++k) {
        out.push_back(
            triangle_case(fmt::format("shared-vertex-{}/{}", i, static_cast<char>('a' + k)),
                          "shared-edge", o, d, center, rim[k], rim[(k + 1) % 5]));
      }
      continue;
    }
    Vec3d target = q[0] + rng.uniform(0.05, 0.95) * (q[2] - q[0]);
    Vec3d d = target - o;
    std::string id = fmt::format("shared-edge-{}", i);
    out.push_back(triangle_case(id + "/a", "shared-edge", o, d, q[0], q[1], q[2]));
    out.push_back(triangle_case(id + "/b", "shared-edge", o, d, q[0], q[2], q[3]));
  }
}

void needles(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 40; ++i) {
    Vec3d a{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d e1 = rng.unit_vector(), e2 = perpendicular(e1, rng);
    double h = std::pow(10.0, -rng.uniform(6, 12));
    Vec3d b = a + 2.0 * e1, c = a + 1.0 * e1 + h * e2;
    double across = rng.uniform(-0.5, 1.5), along = rng.uniform(0.1, 1.9);
    Vec3d target = a + along * e1 + (h * across / 2) * e2;
    Vec3d o = target + 3.0 * rng.unit_vector();
    out.push_back(triangle_case(fmt::format("needle-{}", i), "needle", o, target - o, a, b, c));
  }
}

}  // namespace

void Triangle::Ladder::hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out) {
  if (round == 3) shared_edges(out, rng);
  if (round == 4) needles(out, rng);
}

// The triangle's normal at a point: e₁ × e₂ by vertex order, the same over the face.

SurfacePoint Triangle::nearest_surface(const Vec3d& p, double /*tie*/) const {
  return nearest_flat({v_.begin(), v_.end()}, p);
}

void Triangle::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                             const NormalNames& n) const {
  derive_flat_normal(d, {v_.begin(), v_.end()}, n);
}

// The triangle's generator: puts the hit at a lattice point of its plane and builds the ray
// backwards from it.

const std::vector<Outcome>& Triangle::outcomes() { return kFlatOutcomes; }

Draft Triangle::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kFlatOutcomes);
  Frame f = random_frame(rng);
  int w = rng.range(3, 6), h = rng.range(3, 6);
  std::vector<Vec3d> v = {f.at(0, 0), f.at(w, 0), f.at(0, h)};
  if (rng.below(2)) std::swap(v[1], v[2]);  // either winding: the normal flips
  std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(rng.below(3)), v.end());
  Vec3d p;
  if (o == Outcome::kMiss) {
    p = rng.below(2) ? f.at(w, h) : f.at(-1, rng.range(1, h - 1));
  } else if (o == Outcome::kTangent) {
    p = rng.below(2) ? f.at(rng.range(1, w - 1), 0) : f.at(0, rng.range(1, h - 1));
  } else {
    // A lattice point strictly inside: x, y >= 1 and x/w + y/h < 1.
    int x, y;
    do {
      x = rng.range(1, w - 2);
      y = rng.range(1, h - 2);
    } while (x * h + y * w >= w * h);
    p = f.at(x, y);
  }
  nlohmann::ordered_json object = {{"type", "triangle"}, {"vertices", vertices_json(v)}};
  return flat_draft(rng, o, p, f.normal(), object,
                    fmt::format("the triangle with vertices {}", vertices_text(v)));
}

}  // namespace raygrade
