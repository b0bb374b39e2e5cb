// The polygon's generator: puts the hit at a lattice point of its plane and builds the ray
// backwards from it.
#include "generate/draft.h"
#include "generate/flats.h"
#include "shapes/polygon.h"

namespace raygrade {

const std::vector<Outcome>& Polygon::outcomes() { return kFlatOutcomes; }

Draft Polygon::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kFlatOutcomes);
  Frame f = random_frame(rng);
  std::vector<Vec3d> v;
  Vec3d inside, outside, edge;
  if (rng.below(2)) {
    int w = rng.range(2, 5), h = rng.range(2, 5);
    v = {f.at(0, 0), f.at(w, 0), f.at(w, h), f.at(0, h)};
    inside = f.at(rng.range(1, w - 1), rng.range(1, h - 1));
    outside = f.at(w + 1, rng.range(0, h));
    edge = f.at(w, rng.range(1, h - 1));
  } else {
    // An L: not convex; its notch is outside.
    int k = rng.range(1, 2);
    for (auto [x, y] :
         std::vector<std::pair<int, int>>{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}) {
      v.push_back(f.at(k * x, k * y));
    }
    inside = f.at(k, k);
    outside = f.at(3 * k, 3 * k);
    edge = f.at(4 * k, k);
  }
  if (rng.below(2)) std::reverse(v.begin(), v.end());
  Vec3d p = o == Outcome::kMiss ? outside : o == Outcome::kTangent ? edge : inside;
  nlohmann::ordered_json object = {{"type", "polygon"}, {"vertices", vertices_json(v)}};
  return flat_draft(rng, o, p, f.normal(), object,
                    fmt::format("the polygon with vertices {}", vertices_text(v)));
}

}  // namespace raygrade
