// The reflect kind.
#include "kinds/reflect.h"

#include "derivation/number_format.h"
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
  d.conclude(
      fmt::format("The reflected direction is r = {} (same length as d; the normal's "
                  "orientation does not matter).",
                  format_vector(r.vector)));
  return {SolutionPart{"", std::move(d).finish()}};
}

}  // namespace raygrade
