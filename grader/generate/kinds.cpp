// Generators for the first-hit and camera-ray kinds.
#include "generate/kinds.h"

#include <algorithm>
#include <cmath>

#include "kinds/part_names.h"
#include "sampling/draft.h"
#include "shapes/sphere.h"

namespace raygrade {

Draft make_first_hit(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, {Outcome::kHit, Outcome::kMiss});
  Vec3d origin = random_point(rng, 3);
  Vec3d d = random_direction(rng);
  int count = rng.range(2, 3);
  std::vector<int> entries = {1, 2, 3, 4, 5};
  for (std::size_t i = entries.size() - 1; i > 0; --i)
    std::swap(entries[i], entries[rng.below(i + 1)]);
  nlohmann::ordered_json objects = nlohmann::ordered_json::array();
  std::vector<std::string> parts;
  int first = -1;
  for (int k = 0; k < count; ++k) {
    int r = rng.pick(std::vector<int>{1, 2, 3, 5});
    int s = entries[k];
    Vec3d center;
    if (o == Outcome::kHit) {
      // The ray enters this sphere at t = s: its centre is a lattice offset a from the entry
      // point with d·a > 0 (the other root, s + 2 d·a / d·d, comes later).
      std::vector<Vec3d> ahead;
      for (const auto& a : lattice_sphere(r)) {
        if (dot(a, d) > 0) ahead.push_back(a);
      }
      center = origin + double(s) * d + rng.pick(ahead);
      if (first < 0 || s < entries[first]) first = k;
    } else {
      // Off the ray sideways by more than the radius.
      Vec3d w = reduced(cross(d, random_direction(rng, d)));
      center = origin + double(s) * d + std::ceil((r + 1) / length(w)) * w;
    }
    std::string name = fmt::format("sphere {}", k + 1);
    objects.push_back(
        {{"name", name}, {"type", Sphere::kType}, {"center", vector_json(center)}, {"radius", r}});
    parts.push_back(fmt::format("{} with center {} and radius {}", name, point_text(center), r));
  }
  Draft draft;
  draft.fields["statement"] = fmt::format(
      "The ray {} is traced through a scene of {} spheres: {}. Which sphere does it hit first, "
      "at which t and point?",
      ray_text(origin, d), count, fmt::join(parts, "; "));
  draft.fields["ray"] = {{"origin", vector_json(origin)}, {"direction", vector_json(d)}};
  draft.fields["objects"] = objects;
  if (first >= 0) {
    double t = entries[first];
    draft.fields["expected"][part_names::kObject] = objects[first]["name"];
    draft.fields["expected"]["hits"] = {known_hit_json({t, origin + t * d})};
  } else {
    draft.fields["expected"][part_names::kObject] = nullptr;
    draft.fields["expected"]["hits"] = nlohmann::ordered_json::array();
  }
  return draft;
}

Draft make_camera_ray(Prng& rng, std::optional<Outcome> /*outcome*/) {
  AxisMap map = random_axis_map(rng);
  Vec3d eye = random_point(rng, 3);
  Vec3d dir = map(Vec3d{0, 0, -1}), up = map(Vec3d{0, 1, 0});
  int f = rng.range(1, 5);
  int rx = 2 * rng.range(2, 8), ry = 2 * rng.range(2, 6);
  int x = rng.range(0, rx - 1), y = rng.range(0, ry - 1);
  bool corner = rng.below(2);
  double shift = corner ? 0 : 0.5;
  // Seed 004's formula: d_r = f·d + x_diff·(d × u) + y_diff·u.
  Vec3d ray =
      double(f) * dir + (x + shift - rx / 2.0) * cross(dir, up) + (y + shift - ry / 2.0) * up;
  Draft draft;
  draft.fields["statement"] = fmt::format(
      "A camera at {} looks along d = {} with up vector u = {}, focal length f = {} and "
      "resolution {} × {}. Which ray does it shoot through pixel ({}, {}), with pixel (0, 0) at "
      "the lower left and the ray through the pixel's {}?",
      point_text(eye), point_text(dir), point_text(up), f, rx, ry, x, y,
      corner ? "lower-left corner (offsets x − resX/2, y − resY/2)" : "centre");
  draft.fields["convention"] = corner ? "corner" : "center";
  draft.fields["camera"] = {{"eye", vector_json(eye)},
                            {"direction", vector_json(dir)},
                            {"up", vector_json(up)},
                            {"focal_length", f},
                            {"resolution", {rx, ry}}};
  draft.fields["pixel"] = {x, y};
  draft.fields["expected"][part_names::kRay] = {{part_names::kOrigin, vector_json(eye)},
                                                {part_names::kDirection, vector_json(ray)}};
  return draft;
}

}  // namespace raygrade
