// Answer data of ray trees.
#include "scenes/tree_json.h"

#include <algorithm>

#include "problems/problem.h"

namespace raygrade {

std::vector<std::string> node_terms(const TreeNode& node) {
  std::vector<std::string> out = {"ambient"};
  if (node.diffuse) out.emplace_back("diffuse");
  if (node.specular) out.emplace_back("specular");
  return out;
}

namespace {

// No light reaches the hit node, and the scene has lights.
bool unlit(const TreeNode& node) {
  if (!node.hit || !node.shaded || node.lights.empty()) return false;
  return std::none_of(node.lights.begin(), node.lights.end(),
                      [](const ShadowCheck& s) { return s.reaches(); });
}

bool any_blocked(const TreeNode& node) {
  return std::any_of(node.lights.begin(), node.lights.end(),
                     [](const ShadowCheck& s) { return s.status == LightStatus::kBlocked; });
}

}  // namespace

bool in_shadow(const TreeNode& node) { return unlit(node) && any_blocked(node); }

bool faces_away(const TreeNode& node) { return unlit(node) && !any_blocked(node); }

bool shadow_either(const TreeNode& node) {
  return faces_away(node) &&
         std::any_of(node.lights.begin(), node.lights.end(), [](const ShadowCheck& s) {
           return s.status == LightStatus::kBehind && !s.behind_blockers.empty();
         });
}

ShadowReading shadow_reading(const RayTree& tree, const TreeNode& node) {
  ShadowReading r;
  r.in_shadow = in_shadow(node);
  r.faces_away = faces_away(node);
  if (shadow_either(node)) {
    using F = Conventions::FacingAway;
    switch (tree.facing_away) {
      case F::kEither: r.either = true; break;
      case F::kShadowRay: r.in_shadow = true; break;
      case F::kNormalFirst: break;
    }
  }
  return r;
}

std::vector<std::string> shadow_blockers(const RayTree& tree, const Scene& scene,
                                         const TreeNode& node) {
  bool by_convention = !in_shadow(node) && shadow_reading(tree, node).in_shadow;
  std::vector<std::string> out;
  for (const auto& s : node.lights) {
    for (int b : by_convention ? s.behind_blockers : s.blockers) {
      const std::string& name = scene.objects[b].name;
      if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    }
  }
  return out;
}

nlohmann::json counts_json(const RayCounts& c) {
  return {{"primary", c.primary},
          {"reflection", c.reflection},
          {"refraction", c.refraction},
          {"shadow", c.shadow}};
}

nlohmann::json node_json(const RayTree& tree, const Scene& scene, const TreeNode& n) {
  nlohmann::json j = {{"label", n.label},
                      {"path", n.path},
                      {"ray", to_string(n.kind)},
                      {"parent", n.parent >= 0 ? nlohmann::json(tree.nodes[n.parent].label)
                                               : nlohmann::json(nullptr)},
                      {"depth", n.depth},
                      {"origin", vec_json(n.from)},
                      {"direction", vec_json(n.ray.direction)},
                      {"hit", n.hit}};
  if (n.total_internal_reflection) j["total_internal_reflection"] = true;
  if (!n.hit) {
    j["background"] = scene.background;
    return j;
  }
  j["object"] = scene.objects[n.object].name;
  j["t"] = n.t;
  j["point"] = vec_json(n.point);
  j["normal"] = vec_json(n.normal);
  if (n.inside) j["inside"] = true;
  if (scene.objects[n.object].solid && scene.objects[n.object].material.transmits() &&
      (n.refraction >= 0 || n.refraction_math.total_internal_reflection)) {
    j["n1"] = n.n1;
    j["n2"] = n.n2;
  }
  if (n.fresnel) j["fresnel"] = *n.fresnel;
  if (n.shaded) {
    nlohmann::json lights = nlohmann::json::array();
    for (const auto& s : n.lights) {
      nlohmann::json l = {{"light", s.light_name}, {"status", to_string(s.status)}};
      if (!s.blockers.empty()) {
        nlohmann::json by = nlohmann::json::array();
        for (int b : s.blockers) by.push_back(scene.objects[b].name);
        l["blocked_by"] = by;
      }
      if (s.status == LightStatus::kTransmitted) l["transmission"] = s.transmission;
      lights.push_back(std::move(l));
    }
    j["lights"] = lights;
    j["terms"] = node_terms(n);
    ShadowReading shadow = shadow_reading(tree, n);
    j["in_shadow"] = shadow.in_shadow;
    if (shadow.in_shadow) j["shadowed_by"] = shadow_blockers(tree, scene, n);
    if (shadow.faces_away) j["faces_away"] = true;
  }
  nlohmann::json children = nlohmann::json::array();
  for (int c : tree.children(n.index)) children.push_back(tree.nodes[c].label);
  j["children"] = children;
  if (tree.ask == Ask::kIntensity) {
    double diffuse = 0, specular = 0;
    for (const auto& s : n.lights) {
      diffuse += s.phong.diffuse;
      specular += s.phong.specular;
    }
    j["intensity"] = {{"ambient", n.ambient_term}, {"diffuse", diffuse},
                      {"specular", specular},      {"local", n.local},
                      {"reflected", n.reflected},  {"transmitted", n.transmitted},
                      {"total", n.intensity}};
  }
  return j;
}

// What the tree simulates and what it leaves out, as data:
// [{"effect": "shadow rays", "simulated": true, "rays": 5, "why": "..."}].
nlohmann::json effects_json(const RayTree& tree) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& e : tree.effects) {
    nlohmann::json j = {{"effect", e.name}, {"simulated", e.simulated}, {"why", e.reason}};
    if (e.rays >= 0) j["rays"] = e.rays;
    out.push_back(std::move(j));
  }
  return out;
}

nlohmann::json tree_json(const RayTree& tree, const Scene& scene) {
  const TreeNode& root = tree.nodes.front();
  if (tree.ask == Ask::kMedia) {
    nlohmann::json hits = nlohmann::json::array();
    for (const auto& c : tree.crossings) {
      nlohmann::json media = nlohmann::json::array();
      for (int m : c.after) media.push_back(scene.objects[m].name);
      hits.push_back({{"object", scene.objects[c.object].name},
                      {"t", c.t},
                      {"n1", c.n1},
                      {"n2", c.n2},
                      {"media", media}});
    }
    return {{"hits", hits}};
  }
  if (tree.ask == Ask::kHit) {
    nlohmann::json hits = nlohmann::json::array();
    if (root.hit) {
      hits.push_back(
          {{"t", root.t}, {"point", vec_json(root.point)}, {"normal", vec_json(root.normal)}});
    }
    return {{"object", root.hit ? nlohmann::json(scene.objects[root.object].name) : nullptr},
            {"hits", hits},
            {"rays", counts_json(tree.counts)},
            {"effects", effects_json(tree)}};
  }
  nlohmann::json nodes = nlohmann::json::array();
  nlohmann::json all = nlohmann::json::array(), ambient_only = nlohmann::json::array();
  for (const auto& n : tree.nodes) {
    nodes.push_back(node_json(tree, scene, n));
    if (!n.hit) continue;
    if (n.diffuse && n.specular) {
      all.push_back(n.label);
    } else {
      ambient_only.push_back(n.label);
    }
  }
  nlohmann::json j = {{"nodes", nodes},
                      {"all_terms", all},
                      {"ambient_only", ambient_only},
                      {"rays", counts_json(tree.counts)},
                      {"effects", effects_json(tree)}};
  if (tree.ask == Ask::kIntensity) j["intensity"] = root.intensity;
  return j;
}

}  // namespace raygrade
