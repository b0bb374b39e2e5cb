// Worked solutions of ray trees.
#include "scenes/tree_steps.h"

#include "derivation/number_format.h"
#include "scenes/tree_draw.h"
#include "scenes/tree_json.h"

namespace raygrade {
namespace {

std::string names_list(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  return fmt::format("{}", fmt::join(names, ", "));
}

// The counts in words: "1 primary, 2 reflection, 1 refraction and 5 shadow rays (9 in all)".
std::string counts_sentence(const RayCounts& c) {
  return fmt::format(
      "Rays cast: {} primary, {} reflection, {} refraction and {} shadow ({} in all).", c.primary,
      c.reflection, c.refraction, c.shadow, c.total());
}

SolutionPart overview(const RayTree& tree, const Scene& scene) {
  Deriver d("whitted", "The ray tree");
  for (const auto& e : tree.effects) {
    d.conclude(
        fmt::format("{} {}: {}.", e.simulated ? "Simulated:" : "Skipped:", e.name, e.reason));
  }
  d.conclude(counts_sentence(tree.counts));
  SolutionPart part{"", std::move(d).finish(), {}};
  if (shades(tree.ask)) {
    part.figures.push_back(
        Figure{"The ray tree (R: reflection, T: refraction, dashed: shadow rays)",
               tree_svg(tree, scene), tree_dot(tree, scene), tree_text(tree, scene)});
  } else {
    // A question of the hit or of the media: the scene and the primary ray to its first hit.
    part.figures.push_back(Figure{"The scene and the primary ray, to its first hit",
                                  tree_svg(tree, scene), tree_dot(tree, scene),
                                  tree_text(tree, scene)});
  }
  return part;
}

// Shadow ray and Phong steps for one light. `cast_anyway`: the course casts a shadow ray toward
// a light the surface faces away from (its facing_away convention "shadow-ray").
void light_steps(Deriver& d, const Scene& scene, const TreeNode& node, const ShadowCheck& s, int k,
                 bool intensity, bool cast_anyway) {
  const Light& light = scene.lights[s.light];
  std::string i = std::to_string(k + 1);
  E L;
  if (light.type == LightType::kPoint) {
    E pos = d.given("Lpos_" + i, "S_" + i, light.position,
                    fmt::format("the position of light {}", light.name));
    d.step("L_" + i, "L_" + i, (pos - d.sym("P")) / norm(pos - d.sym("P")),
           "the unit direction from P to the light");
  } else {
    E dir = d.given("Ldir_" + i, "d_L" + i, light.direction,
                    fmt::format("the direction light {} travels", light.name));
    d.step("L_" + i, "L_" + i, -dir / norm(dir), "toward the light: against its direction");
  }
  L = d.sym("L_" + i);
  bool flipped = s.normal == -node.facing_normal;
  E N = flipped ? -d.sym("N_f") : d.sym("N_f");
  d.step("NL_" + i, "N·L_" + i, dot(N, L),
         flipped ? "the surface is transparent: it is lit from the light's side, so N is "
                   "taken on that side."
                 : "");
  const Material& m = scene.objects[node.object].material;
  std::string verdict;
  switch (s.status) {
    case LightStatus::kBehind:
      if (cast_anyway && !s.behind_blockers.empty()) {
        std::vector<std::string> by;
        for (int b : s.behind_blockers) by.push_back(scene.objects[b].name);
        verdict = fmt::format(
            "N·L ≤ 0: the surface faces away from {}; the course casts the shadow ray anyway, "
            "and it meets {}.",
            light.name, names_list(by));
      } else {
        verdict = fmt::format("N·L ≤ 0: the surface faces away from {}; no shadow ray is needed.",
                              light.name);
      }
      break;
    case LightStatus::kVisible:
      verdict = fmt::format("The shadow ray toward {} meets no object: the light is visible.",
                            light.name);
      break;
    case LightStatus::kBlocked:
    case LightStatus::kTransmitted: {
      std::vector<std::string> by;
      for (int b : s.blockers) by.push_back(scene.objects[b].name);
      verdict = s.status == LightStatus::kBlocked
                    ? fmt::format("The shadow ray toward {} is blocked by {}.", light.name,
                                  names_list(by))
                    : fmt::format(
                          "The shadow ray toward {} passes only transparent objects ({}): "
                          "{} of the light arrives.",
                          light.name, names_list(by), format_number(s.transmission));
      break;
    }
  }
  d.note(verdict);
  if (!intensity || !s.reaches()) return;
  E ip = d.given("Ip_" + i, "I_p" + i, light.intensity * s.transmission,
                 s.transmission < 1 ? "the light's intensity times the transmission" : "");
  d.step("diffuse_" + i, "I_d" + i, m.diffuse * ip * d.sym("NL_" + i),
         fmt::format("k_d = {}", format_number(m.diffuse)));
  if (m.specular == 0) {
    d.note(fmt::format("k_s = 0: no specular term for {}.", light.name));
    return;
  }
  d.step("R_" + i, "R_" + i, 2 * d.sym("NL_" + i) * N - L, "the light's mirror direction");
  Value rv = d.step("RV_" + i, "R·V_" + i, dot(d.sym("R_" + i), d.sym("V")));
  d.given("specular_" + i, "I_s" + i, s.phong.specular,
          rv.scalar > 0 ? fmt::format("k_s·I_p·(R·V)^n with k_s = {}, n = {}",
                                      format_number(m.specular), format_number(m.shininess))
                        : "R·V ≤ 0: the highlight points away from the viewer");
}

void secondary_steps(Deriver& d, const Scene& scene, const TreeNode& node) {
  const Material& m = scene.objects[node.object].material;
  if (node.reflection >= 0) {
    d.step("R_dir", "R", d.sym("D_hat") - 2 * dot(d.sym("D_hat"), d.sym("N_f")) * d.sym("N_f"),
           fmt::format("the reflection ray's direction (k_r = {})", format_number(m.reflectivity)));
  }
  if (m.transmits() && scene.objects[node.object].solid &&
      (node.refraction >= 0 || node.refraction_math.total_internal_reflection)) {
    Crossing c = cross_boundary(scene, node.media, node.object, node.t);
    E n1 = d.given("n1", "n_1", node.n1,
                   fmt::format("the ray travels in {}", media_words(scene, c.before)));
    const std::string& name = scene.objects[node.object].name;
    E n2 = d.given("n2", "n_2", node.n2,
                   c.enters ? fmt::format("entering {}", name)
                            : fmt::format("leaving {} into {}", name, media_words(scene, c.after)));
    d.step("eta", "eta", n1 / n2);
    d.step("cos_i", "cos_i", -dot(d.sym("D_hat"), d.sym("N_f")), "the angle of incidence");
    Value k = d.step("k", "k", 1 - square(d.sym("eta")) * (1 - square(d.sym("cos_i"))),
                     "cos²θt by Snell's law");
    if (k.scalar < 0) d.note("k < 0: total internal reflection, there is no refracted ray.");
    if (node.fresnel) {
      fresnel_steps(d, m.fresnel, k.scalar < 0);
      d.note(
          fmt::format("The {} reflectance shares the light: F·k_r = {} to the reflection, "
                      "(1 − F)·k_t = {} to the refraction.",
                      m.fresnel == FresnelModel::kSchlick ? "Schlick" : "Fresnel",
                      format_number(*node.fresnel * m.reflectivity),
                      format_number((1 - *node.fresnel) * m.transparency)));
    }
    if (k.scalar >= 0) {
      d.step(
          "T_dir", "T",
          d.sym("eta") * d.sym("D_hat") +
              (d.sym("eta") * d.sym("cos_i") - sqrt(d.sym("k"))) * d.sym("N_f"),
          fmt::format("the refraction ray's direction (k_t = {})", format_number(m.transparency)));
    }
  }
}

// The list of media along the primary ray's line, boundary by boundary.
Derivation media_steps(const RayTree& tree, const Scene& scene) {
  Deriver d("media", "n1 and n2 by the list of media the ray is inside");
  auto list = [&](const std::vector<int>& media) {
    std::vector<std::string> names;
    names.reserve(media.size());
    for (int m : media) names.push_back(scene.objects[m].name);
    return fmt::format("[{}]", fmt::join(names, ", "));
  };
  const Ray& ray = tree.nodes.front().ray;
  d.given("O", "O", ray.origin, "the ray's origin");
  d.given("D", "D", ray.direction);
  std::vector<int> start = media_at_origin(scene, ray);
  d.given(
      "n_0", "n_0", medium_index(scene, start),
      fmt::format(
          "The list of media holds the transparent objects the ray is inside, innermost last. At "
          "O it is {}: {}. At each hit, n1 is the innermost medium's index; the object hit leaves "
          "the list if it is on it and joins it as the innermost if not; n2 is then the innermost "
          "medium's index (the scene's, {}, when the list is empty).",
          list(start), media_words(scene, start), format_number(scene.refractive_index)));
  for (std::size_t k = 0; k < tree.crossings.size(); ++k) {
    const Crossing& c = tree.crossings[k];
    const SceneObject& o = scene.objects[c.object];
    std::string i = std::to_string(k + 1);
    d.given("t_" + i, "t_" + i, c.t, fmt::format("hit {} of the line, on {}", i, o.name));
    d.given("n1_" + i, "n1_" + i, c.n1, fmt::format("the list before is {}", list(c.before)));
    d.given("n2_" + i, "n2_" + i, c.n2,
            !is_medium(o) ? fmt::format("{} is no medium (opaque, or a thin sheet): the list "
                                        "stays {}",
                                        o.name, list(c.after))
            : c.enters    ? fmt::format("{} is not on the list: the ray enters it; the list "
                                           "becomes {}",
                                        o.name, list(c.after))
                          : fmt::format("{} is on the list: the ray leaves it; the list becomes {}",
                                        o.name, list(c.after)));
  }
  return std::move(d).finish();
}

}  // namespace

std::string node_heading(const RayTree& tree, const TreeNode& node) {
  if (node.parent < 0) return fmt::format("{}: the primary ray", node.label);
  return fmt::format("{}: {} ray from {}", node.label, to_string(node.kind),
                     tree.nodes[node.parent].label);
}

Derivation node_steps(const RayTree& tree, const Scene& scene, const TreeNode& node,
                      const Overrides* overrides) {
  Deriver d("whitted", "Nearest hit, lights and spawned rays", overrides);
  E O = d.given("O", "O", node.from,
                node.parent < 0 ? "the ray's origin"
                                : fmt::format("{}'s hit point; the ray is cast from {:.2g} off the "
                                              "surface (the bound on P's rounding error)",
                                              tree.nodes[node.parent].label, node.offset));
  E D = d.given("D", "D", node.ray.direction);
  std::vector<E> ts;
  for (const auto& h : all_hits(scene, node.ray)) {
    const SceneObject& o = scene.objects[h.object];
    std::string name = fmt::format("t_{}", h.object + 1);
    std::string note = fmt::format("the nearest hit of {}", o.name);
    if (!o.transform.identity()) {
      note += fmt::format(
          ", found in its own space (transform: {}) with O' = {}, D' = {}; t "
          "is the same",
          describe_transform(o.transform), format_vector(h.object_ray.origin),
          format_vector(h.object_ray.direction));
    }
    ts.push_back(d.given(name, name, h.hit.t, note));
  }
  if (!node.hit) {
    d.conclude(fmt::format("The ray hits nothing: it leaves the scene (background intensity {}).",
                           scene.background_rgb ? colour_text(*scene.background_rgb)
                                                : format_number(scene.background)));
    return std::move(d).finish();
  }
  const SceneObject& obj = scene.objects[node.object];
  if (ts.size() > 1) {
    d.step("t", "t", min(ts), "the nearest hit");
  } else {
    d.step("t", "t", ts.front(), "the only hit");
  }
  d.step("P", "P", O + d.sym("t") * D);
  d.given("N", "N", node.normal,
          obj.transform.identity()
              ? "the object's unit normal at P"
              : "the object-space normal taken back by the inverse transpose (A⁻¹)ᵀ, normalized");
  if (node.facing_normal == node.normal) {
    d.step("N_f", "N_f", d.sym("N"), "it faces the incoming ray");
  } else {
    d.step("N_f", "N_f", -d.sym("N"),
           node.inside ? "the ray is inside the object: the normal is turned toward it"
                       : "turned to face the incoming ray");
  }
  d.step("D_hat", "D_hat", D / norm(D));
  d.conclude(fmt::format("{} is on {} at t = {}, P = {}.", node.label, obj.name,
                         format_number(node.t), format_vector(node.point)));
  if (!shades(tree.ask)) return std::move(d).finish();
  bool intensity = tree.ask == Ask::kIntensity;
  if (intensity) d.step("V", "V", -d.sym("D_hat"), "toward the viewer");
  for (std::size_t k = 0; k < node.lights.size(); ++k) {
    light_steps(d, scene, node, node.lights[k], static_cast<int>(k), intensity,
                tree.facing_away == Conventions::FacingAway::kShadowRay);
  }
  std::vector<std::string> terms = node_terms(node);
  if (scene.lights.empty()) {
    d.conclude("The scene has no lights: only the ambient term applies.");
  } else if (ShadowReading shadow = shadow_reading(tree, node); shadow.in_shadow) {
    d.conclude(fmt::format(
        "{} is in shadow, blocked by {}{}: only the ambient term applies.", node.label,
        names_list(shadow_blockers(tree, scene, node)),
        shadow.faces_away ? " (it faces away from the light too, but the course lets the shadow "
                            "ray decide)"
                          : ""));
  } else if (shadow.faces_away) {
    d.conclude(fmt::format(
        "{} faces away from every light (N·L ≤ 0), which is not a shadow: only the ambient "
        "term applies.",
        node.label));
  } else {
    d.conclude(fmt::format("Phong terms at {}: {}.", node.label, fmt::join(terms, ", ")));
  }
  if (intensity) {
    E ka = d.given("k_a", "k_a", obj.material.ambient, "the ambient coefficient");
    E ia = d.given("I_a", "I_a", scene.ambient_light, "the ambient light");
    d.step("ambient", "I_amb", ka * ia, "the ambient term, which always applies");
  }
  secondary_steps(d, scene, node);
  for (int c : tree.children(node.index)) {
    const TreeNode& child = tree.nodes[c];
    d.conclude(fmt::format("The {} ray {} {}.", to_string(child.kind),
                           child.hit ? "goes on to" : "leaves the scene:",
                           child.hit ? child.label : "it hits nothing"));
  }
  for (const auto& n : node.notes) d.conclude(n);
  if (intensity) {
    d.given("local", "I_local", node.local, "ambient + every light's diffuse and specular");
    d.given("total", "I", node.intensity,
            fmt::format("I_local + {} = {} + {} + {}",
                        node.fresnel ? "F·k_r·I_R + (1 − F)·k_t·I_T" : "k_r·I_R + k_t·I_T",
                        format_number(node.local), format_number(node.reflected),
                        format_number(node.transmitted)));
  }
  return std::move(d).finish();
}

Derivation tree_answer(const RayTree& tree, const Scene& scene) {
  Deriver d("whitted", "The answer");
  const TreeNode& root = tree.nodes.front();
  if (tree.ask == Ask::kMedia) {
    for (std::size_t k = 0; k < tree.crossings.size(); ++k) {
      const Crossing& c = tree.crossings[k];
      d.conclude(fmt::format("Hit {} ({} at t = {}): n1 = {}, n2 = {}.", k + 1,
                             scene.objects[c.object].name, format_number(c.t), format_number(c.n1),
                             format_number(c.n2)));
    }
    if (tree.crossings.empty()) d.conclude("The ray crosses no boundary.");
    return std::move(d).finish();
  }
  if (tree.ask == Ask::kHit) {
    d.conclude(root.hit ? fmt::format("The ray first hits {} at t = {}, at P = {}.",
                                      scene.objects[root.object].name, format_number(root.t),
                                      format_vector(root.point))
                        : "The ray hits nothing.");
    return std::move(d).finish();
  }
  std::vector<std::string> all, ambient;
  std::vector<std::string> why;
  for (const auto& n : tree.nodes) {
    if (!n.hit) continue;
    if (n.diffuse) {
      all.push_back(n.label);
      continue;
    }
    ambient.push_back(n.label);
    std::vector<std::string> by = shadow_blockers(tree, scene, n);
    if (scene.lights.empty()) continue;
    why.push_back(by.empty()
                      ? fmt::format("{} faces away from every light", n.label)
                      : fmt::format("{}'s shadow ray is blocked by {}", n.label, names_list(by)));
  }
  std::size_t points = all.size() + ambient.size();
  d.conclude(fmt::format("The tree has {} point{} where intensity is computed.", points,
                         points == 1 ? "" : "s"));
  d.conclude(
      fmt::format("All three Phong terms (ambient, diffuse, specular): {}.", names_list(all)));
  if (!ambient.empty()) {
    d.conclude(fmt::format(
        "Only the ambient term: {}{}.", names_list(ambient),
        why.empty() ? " (the scene has no lights)" : fmt::format(" ({})", fmt::join(why, "; "))));
  }
  if (tree.ask == Ask::kIntensity) {
    d.conclude(fmt::format("The intensity seen along the primary ray is {}.",
                           format_number(root.intensity)));
  }
  return std::move(d).finish();
}

std::vector<SolutionPart> tree_parts(const RayTree& tree, const Scene& scene,
                                     const Overrides* overrides) {
  std::vector<SolutionPart> parts;
  parts.push_back(overview(tree, scene));
  if (tree.ask == Ask::kMedia) {
    parts.push_back(SolutionPart{"The media along the ray", media_steps(tree, scene), {}});
    parts.push_back(SolutionPart{"", tree_answer(tree, scene), {}});
    return parts;
  }
  for (const auto& n : tree.nodes) {
    parts.push_back(SolutionPart{node_heading(tree, n), node_steps(tree, scene, n, overrides), {}});
  }
  parts.push_back(SolutionPart{"", tree_answer(tree, scene), {}});
  return parts;
}

}  // namespace raygrade
