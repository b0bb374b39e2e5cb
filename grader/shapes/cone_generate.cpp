// The cone's generator: a cone along an axis whose radius at every whole height is whole, so
// that its side holds lattice points; the answer is built first from those points (and the
// cap's) and the ray backwards from it.
#include "generate/draft.h"
#include "generate/solids.h"
#include "shapes/cone.h"

namespace raygrade {
namespace {

// A point of the cone's surface as the construction knows it: its offset from the base centre
// across the axis, its height above the base, and whether it is on the cap.
struct ConePoint {
  Vec3d across;
  int height = 0;
  bool cap = false;
  Vec3d at(const Vec3d& base) const { return base + across + Vec3d{0, 0, double(height)}; }
};

}  // namespace

// Every outcome; the ray starts inside a capped cone only (the open one encloses nothing).
const std::vector<Outcome>& Cone::outcomes() { return kSolidOutcomes; }

Draft Cone::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kSolidOutcomes);
  AxisMap map = random_axis_map(rng);
  // radius : height is 1 : 1, 2 : 1 or 1 : 2, so the radius at height s, r (h − s) / h, is
  // whole wherever the side's lattice points are taken.
  static const std::vector<std::pair<int, int>> kRatios = {{1, 1}, {2, 1}, {1, 2}};
  auto [rn, hn] = rng.pick(kRatios);
  int k = rng.range(2, 5);
  int r = rn * k, h = hn * k;
  Vec3d base = random_point(rng, 3);
  bool capped = o == Outcome::kInside || rng.below(2);
  // Built around the z axis, then turned by `map`. The side's points strictly between the cap
  // and the apex, and (when capped) the cap's points strictly inside its rim.
  std::vector<ConePoint> side, pool;
  for (int s = 1; s < h; ++s) {
    if ((rn * (h - s)) % hn != 0) continue;
    for (const auto& p : lattice_circle(rn * (h - s) / hn)) side.push_back({p, s, false});
  }
  pool = side;
  if (capped) {
    for (int x = -r + 1; x < r; ++x) {
      for (int y = -r + 1; y < r; ++y) {
        if (x * x + y * y < r * r) pool.push_back({Vec3d{double(x), double(y), 0}, 0, true});
      }
    }
  }
  Vec3d up{0, 0, 1};
  int s = rng.range(1, 3);
  Vec3d origin, d;
  std::vector<KnownHit> hits;
  if (o == Outcome::kTangent || o == Outcome::kMiss) {
    // Across the axis, tangent to the circle of the cone at that height: the line keeps its
    // height and touches the side at one point (a double root).
    ConePoint p = rng.pick(side);
    d = reduced(Vec3d{-p.across.y, p.across.x, 0});
    origin = p.at(base) - s * d;
    if (o == Outcome::kMiss)
      origin = origin + p.across;  // twice as far from the axis as the side at that height
    else
      hits.push_back({double(s), p.at(base)});
  } else {
    // A chord between two points of the surface: the cone with its cap is convex, so the line
    // meets its surface there and nowhere else, unless both lie on one line of the surface (one
    // generator of the side, or both on the cap).
    ConePoint a, b;
    int steps = 1;
    while (true) {
      a = rng.pick(pool);
      b = rng.pick(pool);
      if (a.cap && b.cap) continue;
      bool same_generator = !a.cap && !b.cap && length_squared(cross(a.across, b.across)) == 0 &&
                            dot(a.across, b.across) > 0;
      if (same_generator || (a.across == b.across && a.height == b.height)) continue;
      steps = static_cast<int>(component_gcd(b.at(base) - a.at(base)));
      if (o == Outcome::kInside && steps < 2) continue;
      break;
    }
    d = reduced(b.at(base) - a.at(base));
    Vec3d p0 = a.at(base), p1 = b.at(base);
    chord_ray(rng, o, p0, p1, d, steps, s, origin, hits);
  }
  nlohmann::ordered_json object = {{"type", kType}, {"base", vector_json(map(base))}};
  if (map(up) != Vec3d{0, 0, 1}) object["axis"] = vector_json(map(up));
  object["radius"] = r;
  object["height"] = h;
  if (capped) object["capped"] = true;
  std::string text = fmt::format(
      "the {} cone whose base circle of radius {} is centred at {}, with its apex at {}",
      capped ? "closed (with its base cap)" : "open", r, point_text(map(base)),
      point_text(map(base + double(h) * up)));
  for (auto& hit : hits) hit.point = map(hit.point);
  return intersect_draft(map(origin), map(d), object, text, hits);
}

}  // namespace raygrade
