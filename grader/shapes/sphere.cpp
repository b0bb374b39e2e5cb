// Sphere: reading, reference intersection, and the geometric and algebraic derivations.
#include "shapes/sphere.h"

#include "math/unit_vector.h"
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
  auto root = [&](const char* name, const char* display, E value) {
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

}  // namespace raygrade
