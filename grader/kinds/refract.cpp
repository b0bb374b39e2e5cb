// The refract kind.
#include "kinds/refract.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/part_names.h"
#include "kinds/sketch.h"
#include "scenes/optics.h"

namespace raygrade {
std::unique_ptr<Task> RefractTask::read(const Cursor& problem) {
  Vec3d d = problem.at("direction").nonzero_vec3();
  Vec3d n = problem.at("normal").nonzero_vec3();
  if (dot(d, n) == 0) problem.at("normal").fail("the ray runs along the surface", "degenerate");
  return std::make_unique<RefractTask>(d, n, problem.at("n1").positive_number(),
                                       problem.at("n2").positive_number());
}

Vec3d RefractTask::facing_normal() const {
  Vec3d n = normalized(n_);
  return dot(d_, n) > 0 ? -n : n;
}

nlohmann::json RefractTask::answer() const {
  Refraction r = refract(normalized(d_), facing_normal(), n1_, n2_);
  nlohmann::json j = {{"total_internal_reflection", r.total_internal_reflection},
                      {"angle_of_incidence", degrees(std::acos(std::clamp(r.cos_i, -1.0, 1.0)))}};
  if (r.total_internal_reflection) {
    j["direction"] = nullptr;
    j["reflected_direction"] = vec_json(reflect(normalized(d_), facing_normal()));
  } else {
    j["direction"] = vec_json(r.direction);
    j["angle_of_refraction"] = degrees(std::acos(std::clamp(std::sqrt(r.k), -1.0, 1.0)));
  }
  if (auto c = critical_angle_degrees(n1_, n2_)) j["critical_angle"] = *c;
  return j;
}

namespace {

// What both methods work first: the givens, the unit direction, the unit normal facing the
// incoming ray, η and cos θi.
void incidence_steps(Deriver& d, const Vec3d& dv, const Vec3d& nv, double n1v, double n2v) {
  E D = d.given("d", "d", dv, "the incoming direction");
  E N = d.given("n", "n", nv, "the surface normal");
  E n1 = d.given("n1", "n_1", n1v, "the index on the incoming side");
  E n2 = d.given("n2", "n_2", n2v, "the index on the far side");
  d.step("d_hat", "d_hat", D / norm(D));
  bool flip = dot(dv, nv) > 0;
  d.step("n_hat", "n_hat", flip ? -N / norm(N) : N / norm(N),
         flip ? "the unit normal, turned to face the incoming ray (d·n > 0 as given)"
              : "the unit normal; it faces the incoming ray");
  d.step("eta", "eta", n1 / n2);
  d.step("cos_i", "cos_i", -dot(d.sym("d_hat"), d.sym("n_hat")), "cos θi");
}

}  // namespace

std::vector<SolutionPart> RefractTask::derive_angles(const Overrides* overrides) const {
  auto not_here = [](const std::string& why) {
    return Error(Diagnostic{"", "", 0, 0, Severity::kError, why, "method-not-applicable"});
  };
  Deriver d("angles", "Refraction by Snell's law on the angles", overrides);
  incidence_steps(d, d_, n_, n1_, n2_);
  double theta_i = d.step("theta_i", "theta_i", arccos_degrees(d.sym("cos_i")),
                          "θi = arccos(cos θi), in degrees, from the normal")
                       .scalar;
  // Snell's law, sin θt = η·sin θi, in one step: the student's θt follows from θi.
  if (!(std::abs(d.scalar("eta") * std::sin(theta_i * std::numbers::pi / 180)) <= 1))
    throw not_here("sin θt > 1: no refracted ray");
  double theta_t =
      d.step("theta_t", "theta_t", arcsin_degrees(d.sym("eta") * sin(radians(d.sym("theta_i")))),
             "Snell's law: θt = arcsin(η·sin θi), in degrees")
          .scalar;
  // Along the surface, the way the ray travels: d̂ with its part along n̂ taken out.
  E along = d.sym("d_hat") + d.sym("cos_i") * d.sym("n_hat");
  Value s = d.step("s", "s", along / norm(along), "along the surface, the side the ray travels");
  if (!std::isfinite(length(s.vector))) throw not_here("the ray runs along the normal");
  E theta = radians(d.sym("theta_t"));
  Value t = d.step("t", "t", sin(theta) * d.sym("s") - cos(theta) * d.sym("n_hat"),
                   "t = sin θt·s − cos θt·n̂");
  d.conclude(Sentence("The refracted direction is t = ")
                 .value(t)
                 .text(" (θi = ")
                 .value(theta_i)
                 .text("°, θt = ")
                 .value(theta_t)
                 .text("°)."));
  return {SolutionPart{"", std::move(d).finish()}};
}

std::vector<std::string> RefractTask::methods() const {
  try {
    derive_angles(nullptr);
  } catch (const Error&) {
    return {"vector"};
  }
  return {"vector", "angles"};
}

std::vector<SolutionPart> RefractTask::derive(std::string_view method,
                                              const Overrides* overrides) const {
  if (method == "angles") return derive_angles(overrides);
  Deriver d("vector", "Refraction by Snell's law", overrides);
  incidence_steps(d, d_, n_, n1_, n2_);
  Value k = d.step("k", "k", 1 - square(d.sym("eta")) * (1 - square(d.sym("cos_i"))),
                   "1 − η²·sin²θi = cos²θt");
  // The angle of incidence, stated in the conclusion, is computed as a step of its own.
  double theta_i = d.step("theta_i", "theta_i", arccos_degrees(d.sym("cos_i")),
                          "θi = arccos(cos θi), in degrees")
                       .scalar;
  if (n1_ > n2_) {
    d.step("theta_c", "theta_c", arcsin_degrees(d.sym("n2") / d.sym("n1")),
           "going into a lower index, the critical angle: arcsin(n₂/n₁)");
  }
  if (k.scalar < 0) {
    d.note("k < 0: sin θt would exceed 1.");
    d.step("r", "r", d.sym("d_hat") + 2 * d.sym("cos_i") * d.sym("n_hat"),
           "all the light is reflected: r = d̂ − 2(d̂·n̂)n̂");
    d.conclude(Sentence("Total internal reflection: at θi = ")
                   .value(theta_i)
                   .text("° there is no refracted ray."));
  } else {
    double theta_t = d.step("theta_t", "theta_t", arccos_degrees(sqrt(d.sym("k"))),
                            "θt = arccos(√k), since k = cos²θt; in degrees")
                         .scalar;
    Value t = d.step("t", "t",
                     d.sym("eta") * d.sym("d_hat") +
                         (d.sym("eta") * d.sym("cos_i") - sqrt(d.sym("k"))) * d.sym("n_hat"),
                     "t = η·d̂ + (η·cos θi − √k)·n̂, a unit vector");
    d.conclude(Sentence("The refracted direction is t = ")
                   .value(t)
                   .text(" (θi = ")
                   .value(theta_i)
                   .text("°, θt = ")
                   .value(theta_t)
                   .text("°)."));
  }
  return {SolutionPart{"", std::move(d).finish()}};
}

// The surface seen edge-on where the ray meets it (the origin stands for the place), the
// unit normal facing the incoming ray and its dashed line through the surface (the angles
// are measured from it), the two media, the incoming direction and the refracted one; past
// the critical angle, the totally reflected direction instead.
Sketch RefractTask::sketch() const {
  Sketch f;
  Vec3d at{0, 0, 0};
  Vec3d d = normalized(d_), n = facing_normal();
  Refraction r = refract(d, n, n1_, n2_);
  Vec3d right = sketch_surface(f, at, n, d, "n̂");
  f.line(at, n, Ink::kGuide);
  f.text(at - right + 0.15 * n, Ink::kObject, "n₁ = " + format_number(n1_));
  f.text(at - right - 0.3 * n, Ink::kObject, "n₂ = " + format_number(n2_));
  double theta_i = degrees(std::acos(std::clamp(r.cos_i, -1.0, 1.0)));
  f.point(at, Ink::kHit);
  sketch_incoming(f, at, d, "d, θi = " + format_number(theta_i) + "°");
  if (r.total_internal_reflection) {
    f.arrow(at, at + reflect(d, n), Ink::kRay, "r: total internal reflection");
    f.text(at + 0.5 * right - 0.5 * n, Ink::kMiss, "no refracted ray (k < 0)");
  } else {
    double theta_t = degrees(std::acos(std::clamp(std::sqrt(r.k), -1.0, 1.0)));
    f.arrow(at, at + r.direction, Ink::kRay, "t, θt = " + format_number(theta_t) + "°");
  }
  return f;
}

std::optional<SceneGivens> RefractTask::scene_givens() const {
  return SceneGivens::surface_at_origin(n_, d_);
}

std::unique_ptr<Task> RefractKind::read(const Cursor& problem) {
  return RefractTask::read(problem);
}

namespace {

using Number = std::function<std::string(double)>;

// Past the critical angle there is no refracted ray, so neither its direction nor its angle.
std::function<std::string(const nlohmann::json&, const Number&)> past_critical(
    std::string_view what) {
  return [what](const nlohmann::json& ref, const Number& number) {
    return fmt::format(
        "Past the critical angle (θi = {}° > θc = {}°) there is no refracted ray: all the "
        "light is reflected, so there is no {}.",
        number(ref.value("angle_of_incidence", 0.0)), number(ref.value("critical_angle", 0.0)),
        what);
  };
}

std::string why_total(const nlohmann::json& ref, bool total, const Number& number) {
  double theta = ref.value("angle_of_incidence", 0.0);
  if (total) {
    return fmt::format("The light is totally reflected: θi = {}° exceeds the critical angle {}°.",
                       number(theta), number(ref.value("critical_angle", 0.0)));
  }
  if (!ref.contains("critical_angle")) {
    return "The ray is refracted: going into an equal or higher index, light is never totally "
           "reflected.";
  }
  return fmt::format("The ray is refracted: θi = {}° is below the critical angle {}°.",
                     number(theta), number(ref.at("critical_angle").get<double>()));
}

}  // namespace

std::vector<PartSpec> RefractKind::parts() {
  using C = Comparison;
  PartSpec direction{part_names::kDirection,
                     "the refracted direction (null past the critical angle)", 1, C::kDirection};
  direction.absent_by_flag = "total_internal_reflection";  // true: there is no refracted ray
  direction.why_absent = past_critical("refracted direction");
  PartSpec total{"total_internal_reflection", "whether the light is totally reflected", 0,
                 C::kFlag};
  total.why_flag = why_total;
  PartSpec theta_t{"angle_of_refraction", "θt in degrees (none past the critical angle)", 0,
                   C::kScalar};
  theta_t.why_absent = past_critical("angle of refraction");
  PartSpec critical{"critical_angle", "asin(n2/n1) in degrees (only when n1 > n2)", 0, C::kScalar};
  critical.why_absent = [](const nlohmann::json&, const Number&) -> std::string {
    return "Going into an equal or higher index (n2 ≥ n1) there is no critical angle: the ray "
           "is always refracted.";
  };
  PartSpec reflected{"reflected_direction",
                     "the totally reflected direction (any positive multiple)", 0, C::kDirection};
  reflected.why_absent = [](const nlohmann::json&, const Number&) -> std::string {
    return "The ray is refracted, not totally reflected: there is no reflected direction to "
           "give.";
  };
  return {direction, total,    {"angle_of_incidence", "θi in degrees", 0, C::kScalar},
          theta_t,   critical, reflected};
}

nlohmann::json RefractKind::answer_form(const Problem& /*p*/) {
  // "Yes" to total internal reflection also answers the direction: there is none.
  nlohmann::json tir =
      form::field<field_types::YesNo>("total_internal_reflection", "Total internal reflection?");
  tir["parts"] = nlohmann::json::array({"total_internal_reflection", "direction"});
  return form::fields(
      {tir,
       form::field<field_types::Vector>(
           "direction", "The refracted direction (blank under total internal reflection)"),
       form::field<field_types::Vector>(
           "reflected_direction", "The reflected direction (under total internal reflection)"),
       form::field<field_types::Number>("angle_of_incidence", "The angle of incidence, in degrees"),
       form::field<field_types::Number>("angle_of_refraction",
                                        "The angle of refraction, in degrees"),
       form::field<field_types::Number>("critical_angle",
                                        "The critical angle, in degrees (when there is one)")});
}

std::string_view RefractKind::schema() {
  return R"json({
  "required": [
    "direction",
    "normal",
    "n1",
    "n2"
  ],
  "properties": {
    "direction": {
      "$ref": "#/$defs/nonzero_vec3"
    },
    "normal": {
      "$ref": "#/$defs/nonzero_vec3"
    },
    "n1": {
      "$ref": "#/$defs/positive"
    },
    "n2": {
      "$ref": "#/$defs/positive"
    }
  }
})json";
}

}  // namespace raygrade
