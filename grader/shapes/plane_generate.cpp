// The plane's generator: puts the hit at a lattice point of its plane and builds the ray backwards
// from it.
#include "generate/draft.h"
#include "generate/flats.h"
#include "shapes/plane.h"

namespace raygrade {

const std::vector<Outcome>& Plane::outcomes() { return kFlatOutcomes; }

Draft Plane::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kFlatOutcomes);
  Frame f = random_frame(rng);
  Vec3d n = reduced(f.normal());
  Vec3d p = f.at(rng.range(-2, 2), rng.range(-2, 2));
  nlohmann::ordered_json object = {{"type", "plane"}};
  std::string text;
  if (rng.below(2)) {
    Vec3d a = f.at(rng.range(-2, 2), rng.range(-2, 2));
    object["point"] = vector_json(a);
    object["normal"] = vector_json(n);
    text = fmt::format("the plane through {} with normal {}", point_text(a), point_text(n));
  } else {
    double dd = -dot(n, p);
    object["normal"] = vector_json(n);
    object["d"] = number_json(dd);
    text = fmt::format("the plane n·p + d = 0 with n = {} and d = {}", point_text(n),
                       number_json(dd).dump());
  }
  if (o == Outcome::kHit || o == Outcome::kBehind) return flat_draft(rng, o, p, n, object, text);
  // Parallel rays: in the plane (the tangent case: contained) or one or two normals off it.
  Vec3d d = reduced(double(rng.range(1, 2)) * f.e1 + double(rng.sign()) * f.e2);
  int s = rng.range(1, 3);
  Vec3d origin = p - double(s) * d;
  if (o == Outcome::kMiss)
    return intersect_draft(origin + double(rng.sign()) * n, d, object, text, {});
  return intersect_draft(origin, d, object, text, {}, true);
}

}  // namespace raygrade
