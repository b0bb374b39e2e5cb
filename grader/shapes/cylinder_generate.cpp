// The cylinder's generator: builds the answer first (hits at lattice points, at integer t) and the
// ray backwards from it.
#include "generate/draft.h"
#include "generate/solids.h"
#include "shapes/cylinder.h"

namespace raygrade {

const std::vector<Outcome>& Cylinder::outcomes() { return kSolidOutcomes; }

Draft Cylinder::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kSolidOutcomes);
  AxisMap map = random_axis_map(rng);
  int r = rng.pick(std::vector<int>{2, 3, 5, 10});
  Vec3d base = random_point(rng, 3);
  const auto& points = lattice_circle(r);
  Vec3d up{0, 0, 1};
  int s = rng.range(1, 3);
  // Built around the z axis, then turned by `map` (a rotation or reflection of the axes).
  Vec3d origin, d;
  std::vector<KnownHit> hits;
  int top = 0;  // the highest hit's height above the base
  if (o == Outcome::kTangent || o == Outcome::kMiss) {
    Vec3d a = rng.pick(points);
    int z = rng.range(1, 3);
    d = reduced(Vec3d{-a.y, a.x, 0}) + double(rng.range(-1, 1)) * up;
    Vec3d p = base + a + double(z) * up;
    origin = p - s * d;
    if (o == Outcome::kMiss)
      origin = origin + a;
    else
      hits.push_back({double(s), p});
    top = z;
  } else {
    Chord ch;
    int z0 = 0, z1 = 0;
    do {
      ch = random_chord(rng, points, 1);
      z0 = rng.range(1, 4);
      z1 = rng.range(1, 4);
      Vec3d full = (ch.b + double(z1) * up) - (ch.a + double(z0) * up);
      ch.steps = static_cast<int>(component_gcd(full));
      ch.d = reduced(full);
    } while (o == Outcome::kInside && ch.steps < 2);
    d = ch.d;
    Vec3d p0 = base + ch.a + double(z0) * up, p1 = base + ch.b + double(z1) * up;
    top = std::max(z0, z1);
    chord_ray(rng, o, p0, p1, d, ch.steps, s, origin, hits);
  }
  nlohmann::ordered_json object = {{"type", "cylinder"},
                                   {"base", vector_json(map(base))},
                                   {"axis", vector_json(map(up))},
                                   {"radius", r}};
  std::string text =
      fmt::format("the infinite cylinder of radius {} around the axis through {} along {}", r,
                  point_text(map(base)), direction_text(map(up)));
  if (rng.below(2) && o != Outcome::kInside) {
    int height = top + rng.range(1, 2);
    bool capped = rng.below(2);
    object["height"] = height;
    if (capped) object["capped"] = true;
    text = fmt::format(
        "the {} cylinder of radius {} and height {} whose axis starts at {} along {}",
        capped ? "closed" : "open", r, height, point_text(map(base)), direction_text(map(up)));
  }
  for (auto& h : hits) h.point = map(h.point);
  return intersect_draft(map(origin), map(d), object, text, hits);
}

}  // namespace raygrade
