// The triangle's generator: puts the hit at a lattice point of its plane and builds the ray
// backwards from it.
#include "generate/draft.h"
#include "generate/flats.h"
#include "shapes/triangle.h"

namespace raygrade {

const std::vector<Outcome>& Triangle::outcomes() { return kFlatOutcomes; }

Draft Triangle::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kFlatOutcomes);
  Frame f = random_frame(rng);
  int w = rng.range(3, 6), h = rng.range(3, 6);
  std::vector<Vec3d> v = {f.at(0, 0), f.at(w, 0), f.at(0, h)};
  if (rng.below(2)) std::swap(v[1], v[2]);  // either winding: the normal flips
  std::rotate(v.begin(), v.begin() + rng.below(3), v.end());
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
