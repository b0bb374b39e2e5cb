// Generators for the solid primitives: sphere, cylinder and box. Each builds the answer first
// (hits at lattice points, at integer t) and the ray backwards from it.
#include "generate/solids.h"

#include "generate/draft.h"

namespace raygrade {
namespace {

const std::vector<Outcome> kSolidOutcomes = {Outcome::kHit, Outcome::kMiss, Outcome::kTangent,
                                             Outcome::kInside, Outcome::kBehind};

// Two different points of a lattice set, as offsets a and b; the chord from a to b is
// g·d with d the reduced direction. With `min_steps` 2 the chord has an integer point inside.
struct Chord {
  Vec3d a, b, d;
  int steps = 1;  // g
};
Chord random_chord(Prng& rng, const std::vector<Vec3d>& points, int min_steps) {
  while (true) {
    Chord c{rng.pick(points), rng.pick(points), {}, 1};
    if (c.a == c.b) continue;
    c.steps = static_cast<int>(component_gcd(c.b - c.a));
    if (c.steps < min_steps) continue;
    c.d = reduced(c.b - c.a);
    return c;
  }
}

// An integer vector perpendicular to `a`, reduced.
Vec3d perpendicular(Prng& rng, const Vec3d& a) {
  while (true) {
    Vec3d p = cross(a, random_direction(rng, a));
    if (length_squared(p) > 0) return reduced(p);
  }
}

}  // namespace

Draft make_sphere(Prng& rng, std::optional<Outcome> asked) {
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
    if (o == Outcome::kHit) {
      origin = c + ch.a - s * d;
      hits = {{double(s), c + ch.a}, {double(s + ch.steps), c + ch.b}};
    } else if (o == Outcome::kInside) {
      int k = rng.range(1, ch.steps - 1);
      origin = c + ch.a + k * d;
      hits = {{double(ch.steps - k), c + ch.b}};
    } else {
      origin = c + ch.b + s * d;
    }
  }
  nlohmann::ordered_json object = {{"type", "sphere"}, {"center", vector_json(c)}, {"radius", r}};
  return intersect_draft(origin, d, object,
                         fmt::format("the sphere with center {} and radius {}", point_text(c), r),
                         hits);
}

Draft make_cylinder(Prng& rng, std::optional<Outcome> asked) {
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
    if (o == Outcome::kHit) {
      origin = p0 - s * d;
      hits = {{double(s), p0}, {double(s + ch.steps), p1}};
    } else if (o == Outcome::kInside) {
      int k = rng.range(1, ch.steps - 1);
      origin = p0 + k * d;
      hits = {{double(ch.steps - k), p1}};
    } else {
      origin = p1 + s * d;
    }
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

Draft make_box(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kBoxOutcomes);
  AxisMap map = random_axis_map(rng);
  Vec3d lo = random_point(rng, 3);
  Vec3d size{double(rng.range(2, 5)), double(rng.range(2, 5)), double(rng.range(2, 5))};
  Vec3d hi = lo + size;
  // Enter through the face x = lo.x and leave through x = hi.x, away from every edge.
  auto inner = [&](int axis) { return double(rng.range(1, static_cast<int>(size[axis]) - 1)); };
  Vec3d p0, p1, full;
  int steps = 1;
  do {
    p0 = {lo.x, lo.y + inner(1), lo.z + inner(2)};
    p1 = {hi.x, lo.y + inner(1), lo.z + inner(2)};
    full = p1 - p0;
    steps = static_cast<int>(component_gcd(full));
  } while (o == Outcome::kInside && steps < 2);
  Vec3d d = reduced(full);
  int s = rng.range(1, 3);
  Vec3d origin;
  std::vector<KnownHit> hits;
  if (o == Outcome::kHit) {
    origin = p0 - s * d;
    hits = {{double(s), p0}, {double(s + steps), p1}};
  } else if (o == Outcome::kInside) {
    int k = rng.range(1, steps - 1);
    origin = p0 + k * d;
    hits = {{double(steps - k), p1}};
  } else if (o == Outcome::kBehind) {
    origin = p1 + s * d;
  } else {
    // The same line moved past the box's top in y: clear of it by at least one unit.
    origin = p0 - s * d + Vec3d{0, size.y + std::abs(p1.y - p0.y) + 1, 0};
  }
  Vec3d a = map(lo), b = map(hi);
  Vec3d mn{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  Vec3d mx{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  nlohmann::ordered_json object = {
      {"type", "box"}, {"min", vector_json(mn)}, {"max", vector_json(mx)}};
  for (auto& h : hits) h.point = map(h.point);
  return intersect_draft(
      map(origin), map(d), object,
      fmt::format("the axis-aligned box from {} to {}", point_text(mn), point_text(mx)), hits);
}

}  // namespace raygrade
