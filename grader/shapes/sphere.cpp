// Sphere: reading, reference intersection, and the geometric and algebraic derivations.
#include "shapes/sphere.h"

#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/solids.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"

namespace raygrade {

// A direction within this of unit length is treated as a unit vector by the geometric method
// (no normalising step): far below the 4 digits a solution shows, above double rounding.
constexpr double kUnitLength = 1e-12;

std::unique_ptr<Shape> Sphere::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.insert(keys.end(), {"center", "radius"});
  object.allow_only(keys);
  return std::make_unique<Sphere>(object.at("center").vec3(),
                                  object.at("radius").positive_number());
}

nlohmann::json Sphere::to_json() const {
  return {{"type", "sphere"}, {"center", {center_.x, center_.y, center_.z}}, {"radius", radius_}};
}

Intersection Sphere::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  // The roots and the normals in double-double, rounded once: t keeps its digits on grazing
  // rays (its condition number grows as the ray nears the tangent), and the normal
  // (O − C + t·D)/r, which cancels when the sphere is small next to its distance (radius 6e-9
  // at 1000), is computed from the exact O − C and the unrounded t.
  Vec3dd o(ray.origin), d(ray.direction), c(center_);
  DoubleDouble r(radius_);
  Roots<DoubleDouble> roots = sphere_roots(o, d, c, r);
  Intersection out;
  DoubleDouble ts[2] = {roots.t0, roots.t1};
  for (int i = 0; i < roots.count; ++i) {
    double t = static_cast<double>(ts[i]);
    if (!ray.accepts(t)) continue;
    Hit h;
    h.t = t;
    h.point = ray.at(t);
    h.normal = unit_rounded((o - c) + ts[i] * d);
    out.hits.push_back(h);
  }
  finish_hits(out.hits);
  return out;
}

Derivation Sphere::derive(const Ray& ray, std::string_view method,
                          const Overrides* overrides) const {
  if (method == "algebraic") return derive_algebraic(ray, overrides);
  return derive_geometric(ray, overrides);
}

Derivation Sphere::derive_geometric(const Ray& ray, const Overrides* overrides) const {
  Deriver d("geometric", "Sphere, geometric method", overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  E C = d.given("C", "C", center_, "the sphere's center");
  E r = d.given("r", "r", radius_, "the sphere's radius");
  // Normalize the direction: the geometric method measures distances along a unit vector.
  double len = length(ray.direction);
  bool unit = std::abs(len - 1) <= kUnitLength;
  E Dhat = D;
  if (!unit) {
    d.step("D_len", norm(D), norm(D), "D is not a unit vector: the method works along D/‖D‖.");
    d.step("D_hat", "D_hat", D / d.sym("D_len"), "the unit direction");
    Dhat = d.sym("D_hat");
  }
  d.step("L", "L", C - O, "from the origin to the center");
  double t_ca = d.step("t_ca", "t_ca", dot(d.sym("L"), Dhat),
                       "the distance along the ray to the point closest to the center")
                    .scalar;
  double LL = d.step("L2", "L^2", dot(d.sym("L"), d.sym("L")),
                     "the squared distance from the origin to the center")
                  .scalar;
  double r2 = d.step("r2", "r^2", square(r)).scalar;
  bool outside = LL > r2;
  std::vector<Candidate> candidates;
  if (t_ca < 0 && outside && ray.t_min >= 0) {
    d.note("t_ca < 0 and the origin is outside (L² > r²): the sphere lies behind the origin.");
    d.conclude("The ray does not hit the sphere: it lies behind the origin.");
    return std::move(d).finish();
  }
  double d2 = d.step("d2", "d^2", d.sym("L2") - square(d.sym("t_ca")),
                     "the squared distance from the center to the ray")
                  .scalar;
  if (d2 > r2) {
    d.note("d² > r²: the ray passes the sphere without touching it.");
    d.conclude("The ray does not hit the sphere: it passes at a distance d > r from the center.");
    return std::move(d).finish();
  }
  d.step("t_hc", "t_hc", sqrt(d.sym("r2") - d.sym("d2")),
         "half the length of the chord inside the sphere");
  E scale = unit ? E() : d.sym("D_len");
  auto root = [&](const char* name, const char* display, const E& value) {
    return d.step(name, display, unit ? value : value / scale).scalar;
  };
  double t0 = root("t0", "t_0", d.sym("t_ca") - d.sym("t_hc"));
  double t1 = root("t1", "t_1", d.sym("t_ca") + d.sym("t_hc"));
  if (!unit) d.note("Dividing by |D| turns distances along D/|D| into t for the given D.");
  std::vector<double> ts = {t0};
  if (t1 != t0) ts.push_back(t1);
  for (std::size_t k = 0; k < ts.size(); ++k) {
    std::string p = k == 0 ? "P0" : "P1", n = k == 0 ? "N0" : "N1";
    Value P = d.step(p, k == 0 ? "P_0" : "P_1", O + d.sym(k == 0 ? "t0" : "t1") * D);
    d.step(n, k == 0 ? "N_0" : "N_1", (d.sym(p) - C) / r, "the outward unit normal");
    candidates.push_back({ts[k], P.vector, range_reason(ray, ts[k])});
  }
  conclude_candidates(d, "sphere", ray, candidates, true);
  return std::move(d).finish();
}

Derivation Sphere::derive_algebraic(const Ray& ray, const Overrides* overrides) const {
  Deriver d("algebraic", "Sphere, algebraic method", overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  E C = d.given("C", "C", center_, "the sphere's center");
  E r = d.given("r", "r", radius_, "the sphere's radius");
  d.step("f", "f", O - C,
         "substituting p(t) = O + tD into |p − C|² = r² gives (D·D)t² + 2(D·f)t + f·f − r² = 0 "
         "with f = O − C");
  double a = d.step("a", "a", dot(D, D)).scalar;
  d.step("b", "b", 2 * dot(D, d.sym("f")));
  d.step("c", "c", dot(d.sym("f"), d.sym("f")) - square(r));
  double disc =
      d.step("discriminant", "Delta", square(d.sym("b")) - 4 * d.sym("a") * d.sym("c")).scalar;
  (void)a;
  if (disc < 0) {
    d.note("Δ < 0: the quadratic has no real roots.");
    d.conclude("The ray does not hit the sphere: the discriminant is negative.");
    return std::move(d).finish();
  }
  if (disc == 0) d.note("Δ = 0: one double root, the ray is tangent to the sphere.");
  double t0 =
      d.step("t0", "t_0", (-d.sym("b") - sqrt(d.sym("discriminant"))) / (2 * d.sym("a"))).scalar;
  double t1 =
      d.step("t1", "t_1", (-d.sym("b") + sqrt(d.sym("discriminant"))) / (2 * d.sym("a"))).scalar;
  std::vector<Candidate> candidates;
  std::vector<std::pair<std::string, double>> ts = {{"t0", t0}};
  if (t1 != t0) ts.emplace_back("t1", t1);
  for (std::size_t k = 0; k < ts.size(); ++k) {
    std::string p = k == 0 ? "P0" : "P1", n = k == 0 ? "N0" : "N1";
    Value P = d.step(p, k == 0 ? "P_0" : "P_1", O + d.sym(ts[k].first) * D);
    d.step(n, k == 0 ? "N_0" : "N_1", (d.sym(p) - C) / r, "the outward unit normal");
    candidates.push_back({ts[k].second, P.vector, range_reason(ray, ts[k].second)});
  }
  conclude_candidates(d, "sphere", ray, candidates, true);
  return std::move(d).finish();
}

void Sphere::sketch(Sketch& figure, const std::string& label) const {
  figure.circle(center_, radius_, Ink::kObject, label);
}

nlohmann::ordered_json Sphere::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "required": [
    "center",
    "radius"
  ],
  "properties": {
    "center": {
      "$ref": "#/$defs/vec3"
    },
    "radius": {
      "$ref": "#/$defs/positive"
    }
  },
  "examples": [
    {
      "type": "sphere",
      "center": [
        0,
        0,
        5
      ],
      "radius": 2
    }
  ]
}
)json");
}

// The accuracy study's cases of spheres.

void Sphere::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius) {
  points = {rng.point(0.5)};
  radius = rng.uniform(0.3, 1.2);
}

namespace {

AccuracyCase sphere_case(std::string id, std::string group, Vec3d o, Vec3d d, Vec3d center,
                         double r) {
  return make_case(std::move(id), std::move(group), primitive_of<Sphere>(), o, d, {center}, r);
}

// A ray from `origin` that passes the center of a sphere at distance r·(1 + δ).
AccuracyCase sphere_pass(std::string id, std::string group, Vec3d origin, Vec3d center, double r,
                         double delta, SplitMix& rng) {
  Vec3d u = normalized(center - origin);
  Vec3d target = center + (r * (1 + delta)) * perpendicular(u, rng);
  return sphere_case(std::move(id), std::move(group), origin, target - origin, center, r);
}

void far_spheres(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 100; ++i) {
    Vec3d o{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    double dist = std::pow(10.0, rng.uniform(4, 9));
    double delta = offset(rng, 1, 12);
    Vec3d c = o + dist * rng.unit_vector();
    out.push_back(sphere_pass(fmt::format("far-sphere-{}", i), "far-sphere", o, c, 1, delta, rng));
  }
  for (int i = 0; i < 40; ++i) {
    double r = std::pow(10.0, -rng.uniform(3, 6)), dist = std::pow(10.0, rng.uniform(3, 6));
    double delta = offset(rng, 1, 10);
    Vec3d c = dist * rng.unit_vector();
    out.push_back(
        sphere_pass(fmt::format("tiny-far-sphere-{}", i), "far-sphere", Vec3d{}, c, r, delta, rng));
  }
}

void huge_spheres(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    double r = std::pow(10.0, rng.uniform(6, 12));
    Vec3d c{rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
    Vec3d u = rng.unit_vector(), w = perpendicular(u, rng);
    double h = r * std::pow(10.0, -rng.uniform(6, 14));
    Vec3d o = c + (r + h) * u;
    // Just below the horizon (hits), just above it (misses), straight down, or away.
    double horizon = std::sqrt(2 * h / r);
    Vec3d d;
    switch (i % 4) {
      case 0: d = w - (horizon * (1 + offset(rng, 1, 6))) * u; break;
      case 1: d = w - (horizon * (1 - std::abs(offset(rng, 1, 6)))) * u; break;
      case 2: d = -1.0 * u + 0.3 * w; break;
      default: d = u + w;
    }
    out.push_back(sphere_case(fmt::format("huge-sphere-{}", i), "huge-sphere", o, d, c, r));
  }
}

void sphere_grazing(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 80; ++i) {
    Vec3d c{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    double r = rng.uniform(0.5, 2);
    double delta = offset(rng, 4, 15);
    Vec3d o = c + 5.0 * rng.unit_vector();
    out.push_back(sphere_pass(fmt::format("grazing-sphere-{}", i), "grazing", o, c, r, delta, rng));
  }
}

void exact_cases(int round, std::vector<AccuracyCase>& out) {
  if (round == 1) {
    // Exact tangents: integer data, the discriminant is exactly zero.
    out.push_back(sphere_case("tangent-0", "tangent", {-5, 1, 0}, {1, 0, 0}, {0, 0, 0}, 1));
    out.push_back(sphere_case("tangent-1", "tangent", {-4, 6, 5}, {2, 0, 0}, {3, 4, 5}, 2));
    out.push_back(sphere_case("tangent-2", "tangent", {0, 0, 10}, {3, 4, 0}, {0, 0, 15}, 5));
    return;
  }
  // Beyond double-double: the discriminant is about 1e-32 of its terms, below the 2^-100
  // double-double can vouch for: only MPFR decides. With f = (−5, 1 − 2^-53, z):
  // Δ = 1 − (1 − 2^-53)² − z², which is −2^-106 for z = 2^-26 (a miss) and 3·2^-106 − 2^-158
  // for z = 2^-26 − 2^-79 (a hit; 53 bits, so exactly a double).
  out.push_back(sphere_case("beyond-double-double-0", "tangent", {-5, 1 - 0x1p-53, 0x1p-26},
                            {1, 0, 0}, {0, 0, 0}, 1));
  out.push_back(sphere_case("beyond-double-double-1", "tangent",
                            {-5, 1 - 0x1p-53, 0x1p-26 - 0x1p-79}, {1, 0, 0}, {0, 0, 0}, 1));
  // Origins on the surface: exactly (t = 0) and to the nearest double.
  out.push_back(sphere_case("on-surface-0", "on-surface", {1, 0, 0}, {-1, 0.5, 0}, {0, 0, 0}, 1));
  out.push_back(sphere_case("on-surface-1", "on-surface", {1, 0, 0}, {1, 0.3, 0}, {0, 0, 0}, 1));
}

void on_surface(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 30; ++i) {
    Vec3d c{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    double r = rng.uniform(0.5, 2);
    Vec3d u = rng.unit_vector();
    Vec3d d = i % 2 == 0 ? rng.unit_vector() - u : u + 0.5 * perpendicular(u, rng);
    out.push_back(
        sphere_case(fmt::format("on-surface-{}", i + 3), "on-surface", c + r * u, d, c, r));
  }
}

// Directions scaled by 1e-170 to 1e+148: a sphere of radius 1 at distance 5 (two hits, t of
// order 1e-148 to 1e+170). The problem format reads no direction whose squared length
// overflows a double (about 1.8e308), so 1e+148 is as far as a direction of length 5 goes
// there; the solver itself is tested up to 1e+300 (tests/solver_accuracy_test.cpp).
void extreme_direction_scales(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 24; ++i) {
    int j = i / 2;  // 1e+60, 1e+68, ..., 1e+148 and 1e-60, 1e-70, ..., 1e-170
    int exponent = i % 2 == 0 ? 60 + 8 * j : -(60 + 10 * j);
    double scale = std::pow(10.0, exponent);
    Vec3d aim = Vec3d{0, 0, 5} + 0.6 * perpendicular(Vec3d{0, 0, 1}, rng);
    out.push_back(sphere_case(fmt::format("extreme-scale-sphere-{}", i), "extreme-scale", {0, 0, 0},
                              scale * aim, {0, 0, 5}, 1));
  }
}

// Spheres small next to their distance, where a normal from the rounded hit point (P − C)/r
// loses digits: radius 6e-9 at 1000 and radius 1 at 1e11, radius 1e-9 to 1e-6 at 1e2 to 1e4;
// rays aimed within the sphere.
void small_far_spheres(std::vector<AccuracyCase>& out, SplitMix& rng) {
  auto sphere = [&](std::string id, double r, double dist) {
    Vec3d o{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d u = rng.unit_vector(), c = o + dist * u;
    Vec3d across = perpendicular(u, rng);
    Vec3d target = c + (r * rng.uniform(-0.9, 0.9)) * across;
    out.push_back(sphere_case(std::move(id), "small-far", o, target - o, c, r));
  };
  for (int i = 0; i < 10; ++i) sphere(fmt::format("small-far-sphere-{}", i), 6e-9, 1000);
  for (int i = 0; i < 10; ++i) sphere(fmt::format("far-sphere-1e11-{}", i), 1, 1e11);
  for (int i = 0; i < 20; ++i) {
    double dist = std::pow(10.0, rng.uniform(2, 4)), r = std::pow(10.0, -rng.uniform(6, 9));
    sphere(fmt::format("small-far-sphere-{}", i + 10), r, dist);
  }
}

}  // namespace

void Sphere::Ladder::hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out) {
  switch (round) {
    case 0:
      far_spheres(out, rng);
      huge_spheres(out, rng);
      sphere_grazing(out, rng);
      break;
    case 1:
    case 2: exact_cases(round, out); break;
    case 3: on_surface(out, rng); break;
    case 7: extreme_direction_scales(out, rng); break;
    case 8: small_far_spheres(out, rng); break;
    default: break;
  }
}

// The sphere's normal at a point: from the centre to the point, the gradient of |X − C|² − r².

SurfacePoint Sphere::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d pc = p - center_;
  Vec3d dir = length(pc) > 0 ? normalized(pc) : Vec3d{0, 0, 1};
  return SurfacePoint{center_ + radius_ * dir, pc, "", ""};
}

void Sphere::derive_normal(Deriver& d, const E& P, const SurfacePoint& /*s*/,
                           const NormalNames& n) const {
  E C = d.given("C", "C", center_, "the sphere's centre");
  d.step("PC", n.point + " − C", P - C,
         "from the centre to the point: the gradient of |X − C|² − r²");
  d.step(n.name, n.display, d.sym("PC") / norm(d.sym("PC")), "the outward unit normal");
}

// The sphere's generator: builds the answer first (hits at lattice points, at integer t) and the
// ray backwards from it.

const std::vector<Outcome>& Sphere::outcomes() { return kSolidOutcomes; }

Draft Sphere::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kSolidOutcomes);
  int r = rng.pick(std::vector<int>{2, 3, 5, 6, 7, 9});
  Vec3d c = random_point(rng, 5);
  const auto& points = lattice_sphere(r);
  int s = rng.range(1, 3);
  Vec3d origin, d;
  std::vector<KnownHit> hits;
  if (o == Outcome::kTangent || o == Outcome::kMiss) {
    Vec3d a = rng.pick(points);
    d = perpendicular(rng, a);
    origin = c + a - s * d;
    if (o == Outcome::kMiss)
      origin = origin + a;  // the line passes 2r from the centre
    else
      hits.push_back({double(s), c + a});
  } else {
    Chord ch = random_chord(rng, points, o == Outcome::kInside ? 2 : 1);
    d = ch.d;
    chord_ray(rng, o, c + ch.a, c + ch.b, d, ch.steps, s, origin, hits);
  }
  nlohmann::ordered_json object = {{"type", "sphere"}, {"center", vector_json(c)}, {"radius", r}};
  return intersect_draft(origin, d, object,
                         fmt::format("the sphere with center {} and radius {}", point_text(c), r),
                         hits);
}

}  // namespace raygrade
