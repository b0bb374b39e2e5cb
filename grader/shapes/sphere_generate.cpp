// The sphere's generator: builds the answer first (hits at lattice points, at integer t) and the
// ray backwards from it.
#include "generate/draft.h"
#include "generate/solids.h"
#include "shapes/sphere.h"

namespace raygrade {

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
