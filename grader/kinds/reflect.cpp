// The reflect kind.
#include "kinds/reflect.h"

#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/part_names.h"
#include "kinds/sketch.h"
#include "scenes/optics.h"

namespace raygrade {

std::unique_ptr<Task> ReflectTask::read(const Cursor& problem) {
  return std::make_unique<ReflectTask>(problem.at("direction").nonzero_vec3(),
                                       problem.at("normal").nonzero_vec3());
}

nlohmann::json ReflectTask::answer() const {
  Vec3d r = reflect(d_, normalized(n_));
  return {{"direction", vec_json(r)}, {"unit_direction", vec_json(normalized(r))}};
}

std::vector<SolutionPart> ReflectTask::derive(std::string_view /*method*/,
                                              const Overrides* overrides) const {
  Deriver d("vector", "Reflection about the normal", overrides);
  E D = d.given("d", "d", d_, "the incoming direction");
  E N = d.given("n", "n", n_, "the surface normal");
  E Nh = N;
  if (std::abs(length(n_) - 1) > kUnitLengthTolerance) {
    d.step("n_hat", "n_hat", N / norm(N), "the formula needs a unit normal");
    Nh = d.sym("n_hat");
  }
  d.step("d_dot_n", "d·n", dot(D, Nh), "the component of d along the normal");
  Value r = d.step("r", "r", D - 2 * d.sym("d_dot_n") * Nh,
                   "remove that component twice: the tangential part stays, the normal part "
                   "flips");
  d.step("r_hat", "r_hat", d.sym("r") / norm(d.sym("r")), "r as a unit vector");
  d.conclude(Sentence("The reflected direction is r = ")
                 .value(r)
                 .text(" (same length as d; the normal's orientation does not matter)."));
  return {SolutionPart{"", std::move(d).finish()}};
}

// The surface seen edge-on at the point where the ray meets it (the problem gives no place:
// the origin stands for it), the unit normal on the side the ray comes from, the incoming
// direction and the reflected one, each drawn one unit long.
Sketch ReflectTask::sketch() const {
  Sketch f;
  Vec3d at{0, 0, 0};
  Vec3d d = normalized(d_), n = normalized(n_);
  bool unit = std::abs(length(n_) - 1) <= kUnitLengthTolerance;
  std::string name = unit ? "n" : "n̂";
  // The normal as given may point into the surface; the figure turns it to face the ray.
  bool turned = dot(d, n) > 0;
  sketch_surface(f, at, turned ? -n : n, d, turned ? "−" + name + " (turned to face d)" : name);
  f.point(at, Ink::kHit);
  sketch_incoming(f, at, d, "d = " + sketch_vector(d_));
  f.arrow(at, at + normalized(reflect(d, n)), Ink::kRay, "r = " + sketch_vector(reflect(d_, n)));
  return f;
}

std::optional<SceneGivens> ReflectTask::scene_givens() const {
  return SceneGivens::surface_at_origin(n_, d_);
}

std::unique_ptr<Task> ReflectKind::read(const Cursor& problem) {
  return ReflectTask::read(problem);
}

std::vector<PartSpec> ReflectKind::parts() {
  using C = Comparison;
  PartSpec direction{part_names::kDirection, "the reflected direction r (any positive multiple)", 1,
                     C::kDirection, "r = d − 2(d·n̂)n̂ keeps the length of d"};
  direction.aliases = {part_names::kUnitDirection};  // a unit direction is a direction
  return {direction, {part_names::kUnitDirection, "r as a unit vector", 0, C::kUnitDirection}};
}

nlohmann::json ReflectKind::answer_form(const Problem& /*p*/) {
  return form::fields({form::field<field_types::Vector>("direction", "The reflected direction"),
                       form::field<field_types::Vector>(
                           "unit_direction", "The reflected direction as a unit vector")});
}

std::string_view ReflectKind::schema() {
  return R"json({
  "required": [
    "direction",
    "normal"
  ],
  "properties": {
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
