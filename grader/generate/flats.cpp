// Generators for the flat primitives: plane, triangle and polygon. The hit point is a
// lattice point of the object's plane, and the ray is built backwards from it.
#include "generate/draft.h"
#include "generate/solids.h"

namespace raygrade {
namespace {

// Two integer vectors spanning a plane, and a corner: the plane's 2D lattice.
struct Frame {
  Vec3d corner, e1, e2;
  Vec3d at(double x, double y) const { return corner + x * e1 + y * e2; }
  Vec3d normal() const { return cross(e1, e2); }
};

Frame random_frame(Prng& rng) {
  static const std::vector<std::pair<Vec3d, Vec3d>> kBases = {{{1, 0, 0}, {0, 1, 0}},
                                                              {{1, 1, 0}, {0, 0, 1}},
                                                              {{1, 0, -1}, {0, 1, 0}},
                                                              {{2, 1, 0}, {0, 0, 1}}};
  auto [e1, e2] = rng.pick(kBases);
  AxisMap map = random_axis_map(rng);
  return Frame{random_point(rng, 4), map(e1), map(e2)};
}

// A small integer direction that crosses the plane (never parallel to it).
Vec3d crossing_direction(Prng& rng, const Vec3d& normal) {
  while (true) {
    Vec3d d = random_direction(rng);
    if (dot(d, normal) != 0) return d;
  }
}

// The ray for a flat object: through `p` for a hit or an edge, with `p` behind it for
// kBehind; for a miss the caller passes a point of the plane outside the object.
Draft flat_draft(Prng& rng, Outcome o, const Vec3d& p, const Vec3d& normal,
                 nlohmann::ordered_json object, const std::string& text) {
  Vec3d d = crossing_direction(rng, normal);
  int s = rng.range(1, 3);
  if (o == Outcome::kBehind) return intersect_draft(p + double(s) * d, d, object, text, {});
  std::vector<KnownHit> hits;
  if (o != Outcome::kMiss) hits.push_back({double(s), p});
  return intersect_draft(p - double(s) * d, d, object, text, hits);
}

std::string vertices_text(const std::vector<Vec3d>& v) {
  std::vector<std::string> parts;
  for (const auto& p : v) parts.push_back(point_text(p));
  return fmt::format("{}", fmt::join(parts, ", "));
}

nlohmann::ordered_json vertices_json(const std::vector<Vec3d>& v) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& p : v) list.push_back(vector_json(p));
  return list;
}

}  // namespace

Draft make_plane(Prng& rng, std::optional<Outcome> asked) {
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

Draft make_triangle(Prng& rng, std::optional<Outcome> asked) {
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

Draft make_polygon(Prng& rng, std::optional<Outcome> asked) {
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
