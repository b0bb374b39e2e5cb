// The fresnel kind.
#include "kinds/fresnel.h"

#include <cmath>
#include <numbers>

#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/sketch.h"
#include "scenes/optics.h"

namespace raygrade {
std::unique_ptr<Task> FresnelTask::read(const Cursor& problem) {
  std::string model = problem.string_or("model", "exact");
  FresnelModel m = model == "schlick" ? FresnelModel::kSchlick : FresnelModel::kExact;
  if (model != "schlick" && model != "exact") {
    problem.at("model").fail("expected \"exact\" or \"schlick\"", "invalid");
  }
  double n1 = problem.at("n1").positive_number();
  double n2 = problem.at("n2").positive_number();
  bool by_angle = problem.has("angle");
  if (by_angle == (problem.has("direction") || problem.has("normal"))) {
    problem.fail("give the incidence either as an angle (degrees) or as a direction and a normal",
                 "invalid");
  }
  if (by_angle) {
    double a = problem.at("angle").number();
    if (a < 0 || a >= 90) {
      problem.at("angle").fail("the angle of incidence is from 0 up to 90 degrees", "range");
    }
    return std::make_unique<FresnelTask>(m, n1, n2, a, Vec3d{}, Vec3d{});
  }
  Vec3d d = problem.at("direction").nonzero_vec3();
  Vec3d n = problem.at("normal").nonzero_vec3();
  if (dot(d, n) == 0) problem.at("normal").fail("the ray runs along the surface", "degenerate");
  return std::make_unique<FresnelTask>(m, n1, n2, std::nullopt, d, n);
}

double FresnelTask::cos_i() const {
  if (angle_) return std::cos(*angle_ * std::numbers::pi / 180);
  return std::abs(dot(normalized(d_), normalized(n_)));
}

nlohmann::json FresnelTask::answer() const {
  Reflectance r = fresnel_reflectance(model_, cos_i(), n1_, n2_);
  nlohmann::json j = {{"reflectance", r.reflectance},
                      {"transmittance", 1 - r.reflectance},
                      {"total_internal_reflection", r.total_internal_reflection},
                      {"angle_of_incidence", degrees(std::acos(std::min(1.0, r.cos_i)))}};
  if (!r.total_internal_reflection) {
    j["angle_of_refraction"] = degrees(std::acos(std::min(1.0, r.cos_t)));
  }
  if (model_ == FresnelModel::kSchlick) {
    j["r0"] = r.r0;
  } else if (!r.total_internal_reflection) {
    j["r_s"] = r.r_s;
    j["r_p"] = r.r_p;
  }
  return j;
}

std::vector<SolutionPart> FresnelTask::derive(std::string_view /*method*/,
                                              const Overrides* overrides) const {
  Deriver d("fresnel",
            model_ == FresnelModel::kSchlick ? "Fresnel reflectance by Schlick's approximation"
                                             : "Fresnel reflectance by the Fresnel equations",
            overrides);
  E n1 = d.given("n1", "n_1", n1_, "the index on the incoming side");
  E n2 = d.given("n2", "n_2", n2_, "the index on the far side");
  d.step("eta", "eta", n1 / n2);
  if (angle_) {
    E theta = d.given("theta_i", "theta_i", *angle_, "the angle of incidence, in degrees");
    d.step("cos_i", "cos_i", cos(theta * pi() / 180), "cos θi, the angle in radians");
  } else {
    E D = d.given("d", "d", d_, "the incoming direction");
    E N = d.given("n", "n", n_, "the surface normal");
    d.step("cos_i", "cos_i", abs(dot(D, N)) / (norm(D) * norm(N)), "cos θi = |d·n|/(|d||n|)");
    d.step("theta_i", "theta_i", arccos_degrees(d.sym("cos_i")), "the angle of incidence");
  }
  Value k = d.step("k", "k", 1 - square(d.sym("eta")) * (1 - square(d.sym("cos_i"))),
                   "1 − η²·sin²θi = cos²θt (Snell's law)");
  if (auto c = critical_angle_degrees(n1_, n2_)) {
    d.note(fmt::format("Going into a lower index, the critical angle is asin(n₂/n₁) = {}°.",
                       format_number(*c)));
  }
  bool tir = k.scalar < 0;
  fresnel_steps(d, model_, tir);
  // Schlick's step out of the denser medium has worked θt already.
  if (!tir && !d.env().contains("theta_t"))
    d.step("theta_t", "theta_t", arccos_degrees(d.sym("cos_t")), "the angle of refraction");
  Value f = d.value("F");
  d.step("T", "T", 1 - d.sym("F"), "the transmitted share, 1 − F");
  d.conclude(Sentence(tir ? "Total internal reflection: the reflectance is F = "
                          : "The boundary reflects F = ")
                 .value(f)
                 .text(" of the light and transmits T = ")
                 .value(d.value("T"))
                 .text("."));
  return {SolutionPart{"", std::move(d).finish()}};
}

// The surface seen edge-on with the two media, the incoming ray at θi, the reflected ray
// labelled with F and the refracted one with 1 − F (none past the critical angle).
Sketch FresnelTask::sketch() const {
  Sketch f;
  Vec3d at{0, 0, 0}, n{0, 1, 0}, right{1, 0, 0};
  double c = cos_i();
  double s = std::sqrt(std::max(0.0, 1 - c * c));
  Vec3d d = s * right - c * n;
  Reflectance r = fresnel_reflectance(model_, c, n1_, n2_);
  sketch_surface(f, at, n, right, "n̂");
  f.line(at, n, Ink::kGuide);
  f.text(at - right + 0.15 * n, Ink::kObject, "n₁ = " + format_number(n1_));
  f.text(at - right - 0.3 * n, Ink::kObject, "n₂ = " + format_number(n2_));
  f.point(at, Ink::kHit);
  sketch_incoming(f, at, d, "θi = " + format_number(degrees(std::acos(std::min(1.0, c)))) + "°");
  f.arrow(at, at + reflect(d, n), Ink::kRay, "reflected: F = " + format_number(r.reflectance));
  if (r.total_internal_reflection) {
    f.text(at + 0.5 * right - 0.5 * n, Ink::kMiss, "no refracted ray: total internal reflection");
  } else {
    Refraction t = refract(d, n, n1_, n2_);
    f.arrow(at, at + t.direction, Ink::kRay,
            "refracted: 1 − F = " + format_number(1 - r.reflectance));
  }
  return f;
}

// Incidence by an angle θ: the surface y = 0 and a ray at θ from its normal in the xy plane.
std::optional<SceneGivens> FresnelTask::scene_givens() const {
  SceneGivens g;
  GivenSurface& s = g.surface.emplace();
  if (angle_) {
    double theta = *angle_ * std::numbers::pi / 180;
    s.normal = Vec3d{0, 1, 0};
    s.incoming = Vec3d{std::sin(theta), -std::cos(theta), 0};
  } else {
    s.normal = n_;
    s.incoming = d_;
  }
  return g;
}

std::unique_ptr<Task> FresnelKind::read(const Cursor& problem) {
  return FresnelTask::read(problem);
}

std::vector<PartSpec> FresnelKind::parts() {
  using C = Comparison;
  return {
      {"reflectance", "the reflected share F (1 under total internal reflection)", 1, C::kScalar},
      {"transmittance", "the transmitted share 1 − F", 0, C::kScalar},
      {"total_internal_reflection", "whether the light is totally reflected", 0, C::kFlag},
      {"angle_of_incidence", "θi in degrees", 0, C::kScalar},
      {"angle_of_refraction", "θt in degrees (none past the critical angle)", 0, C::kScalar},
      {"r0", "Schlick: the reflectance at normal incidence", 0, C::kScalar},
      {"r_s", "exact: the s-polarized reflectance", 0, C::kScalar},
      {"r_p", "exact: the p-polarized reflectance", 0, C::kScalar}};
}

nlohmann::json FresnelKind::answer_form(const Problem& /*p*/) {
  return form::fields(
      {form::field<field_types::Number>("reflectance", "The reflectance F"),
       form::field<field_types::Number>("transmittance", "The transmitted share 1 − F"),
       form::field<field_types::YesNo>("total_internal_reflection", "Total internal reflection?")});
}

std::string_view FresnelKind::schema() {
  return R"json({
  "required": [
    "n1",
    "n2"
  ],
  "properties": {
    "n1": {
      "$ref": "#/$defs/positive"
    },
    "n2": {
      "$ref": "#/$defs/positive"
    },
    "model": {
      "enum": [
        "exact",
        "schlick"
      ]
    },
    "angle": {
      "type": "number",
      "minimum": 0,
      "exclusiveMaximum": 90
    },
    "direction": {
      "$ref": "#/$defs/nonzero_vec3"
    },
    "normal": {
      "$ref": "#/$defs/nonzero_vec3"
    }
  }
})json";
}

}  // namespace raygrade
