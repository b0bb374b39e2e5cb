// Whitted-style tracing into a RayTree.
#include "scenes/trace.h"

#include <cmath>

#include "derivation/number_format.h"
#include "scenes/offset.h"

namespace raygrade {

const char* to_string(RayKind k) {
  switch (k) {
    case RayKind::kPrimary: return "primary";
    case RayKind::kReflection: return "reflection";
    case RayKind::kRefraction: return "refraction";
    case RayKind::kShadow: return "shadow";
  }
  return "?";
}

const char* to_string(LightStatus s) {
  switch (s) {
    case LightStatus::kVisible: return "visible";
    case LightStatus::kBlocked: return "blocked";
    case LightStatus::kTransmitted: return "transmitted";
    case LightStatus::kBehind: return "behind";
  }
  return "?";
}

const TreeNode* RayTree::find(std::string_view path) const {
  for (const auto& n : nodes) {
    if (n.path == path) return &n;
  }
  return nullptr;
}

std::vector<int> RayTree::children(int node) const {
  std::vector<int> out;
  const TreeNode& n = nodes[node];
  if (n.reflection >= 0) out.push_back(n.reflection);
  if (n.refraction >= 0) out.push_back(n.refraction);
  return out;
}

Vec3d lit_normal(const TreeNode& node, const Material& m, const Vec3d& l) {
  if (m.transmits() && dot(node.facing_normal, l) < 0) return -node.facing_normal;
  return node.facing_normal;
}

namespace {

class Tracer {
 public:
  Tracer(const Scene& scene, Ask ask) : scene_(scene) { tree_.ask = ask; }

  RayTree run(const Ray& primary) {
    trace_ray(primary, primary.origin, RayKind::kPrimary, -1, 1, "P", 1, 0,
              media_at_origin(scene_, primary));
    if (tree_.ask == Ask::kMedia) tree_.crossings = crossings(scene_, primary);
    int n = 0;
    for (auto& node : tree_.nodes) node.label = node.hit ? fmt::format("I{}", ++n) : node.path;
    describe_effects();
    return std::move(tree_);
  }

 private:
  int trace_ray(const Ray& ray, const Vec3d& from, RayKind kind, int parent, int depth,
                const std::string& path, double weight, double offset, std::vector<int> media) {
    int index = static_cast<int>(tree_.nodes.size());
    TreeNode node;
    node.index = index;
    node.parent = parent;
    node.kind = kind;
    node.depth = depth;
    node.path = path;
    node.ray = ray;
    node.from = from;
    node.weight = weight;
    node.offset = offset;
    node.media = std::move(media);
    node.n1 = node.n2 = medium_index(scene_, node.media);
    count(kind);
    SceneHit h = nearest_hit(scene_, ray);
    if (h.object < 0) {
      node.intensity = scene_.background;
      tree_.nodes.push_back(node);
      return index;
    }
    const SceneObject& obj = scene_.objects[h.object];
    node.hit = true;
    node.object = h.object;
    node.t = h.hit.t;
    node.point = h.hit.point;
    node.normal = h.hit.normal;
    node.point_error = h.point_error;
    bool against = dot(ray.direction, node.normal) > 0;
    node.inside = obj.solid && against;
    node.facing_normal = against ? -node.normal : node.normal;
    tree_.nodes.push_back(node);
    if (!shades(tree_.ask)) return index;
    shade(index, obj.material);
    spawn(index, obj, depth);
    if (tree_.ask == Ask::kIntensity) total(index, obj.material);
    return index;
  }

  void count(RayKind kind) {
    switch (kind) {
      case RayKind::kPrimary: ++tree_.counts.primary; break;
      case RayKind::kReflection: ++tree_.counts.reflection; break;
      case RayKind::kRefraction: ++tree_.counts.refraction; break;
      case RayKind::kShadow: ++tree_.counts.shadow; break;
    }
  }

  // Shadow rays and the Phong terms that apply.
  void shade(int index, const Material& m) {
    TreeNode& node = tree_.nodes[index];
    node.shaded = true;
    Vec3d v = normalized(-node.ray.direction);
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      const Light& light = scene_.lights[i];
      ShadowCheck s;
      s.light = static_cast<int>(i);
      s.light_name = light.name;
      Vec3d to_light =
          light.type == LightType::kPoint ? light.position - node.point : -light.direction;
      s.l = normalized(to_light);
      s.normal = lit_normal(node, m, s.l);
      if (dot(s.normal, s.l) <= 0) {
        s.status = LightStatus::kBehind;
        Vec3d from = offset_ray_origin(node.point, node.point_error, s.normal, s.l);
        Ray would = light.type == LightType::kPoint ? Ray{from, light.position - from, 0, 1}
                                                    : Ray{from, s.l, 0, kInfinity};
        for (const auto& b : all_hits(scene_, would))
          if (b.object != node.object) s.behind_blockers.push_back(b.object);
        node.lights.push_back(s);
        continue;
      }
      // Cast the shadow ray from just off the surface, on the light's side.
      s.cast = true;
      count(RayKind::kShadow);
      Vec3d origin = offset_ray_origin(node.point, node.point_error, s.normal, s.l);
      if (light.type == LightType::kPoint) {
        s.ray = Ray{origin, light.position - origin, 0, 1};
      } else {
        s.ray = Ray{origin, s.l, 0, kInfinity};
      }
      for (const auto& b : all_hits(scene_, s.ray)) s.blockers.push_back(b.object);
      s.status = LightStatus::kVisible;
      for (int b : s.blockers) {
        const Material& bm = scene_.objects[b].material;
        if (scene_.transparent_shadows == TransparentShadows::kTransmit && bm.transmits()) {
          s.transmission *= bm.transparency;
          s.status = LightStatus::kTransmitted;
        } else {
          s.status = LightStatus::kBlocked;
          s.transmission = 0;
          break;
        }
      }
      if (s.reaches()) {
        node.diffuse = node.specular = true;
        if (tree_.ask == Ask::kIntensity) {
          s.phong = phong_light(s.normal, s.l, v, light.intensity * s.transmission, m.diffuse,
                                m.specular, m.shininess);
        }
      }
      node.lights.push_back(s);
    }
  }

  // The reflection and refraction rays the surface and the depth limit allow.
  void spawn(int index, const SceneObject& obj, int depth) {
    const Material& m = obj.material;
    auto note = [&](std::string s) { tree_.nodes[index].notes.push_back(std::move(s)); };
    TreeNode node = tree_.nodes[index];  // a copy: children are appended to the vector
    if (!m.reflects() && !m.transmits()) return;
    if (static_cast<int>(tree_.nodes.size()) >= kMaxTreeNodes) {
      note(
          fmt::format("No further rays: the tree has reached {} nodes, the most one problem may "
                      "have.",
                      kMaxTreeNodes));
      return;
    }
    if (depth >= scene_.max_depth) {
      note(fmt::format("No {} ray: the depth limit is reached (max_depth {}).",
                       m.reflects() && m.transmits() ? "reflection or refraction"
                       : m.reflects()                ? "reflection"
                                                     : "refraction",
                       scene_.max_depth));
      return;
    }
    Vec3d d = normalized(node.ray.direction);
    bool internal_skipped = node.inside && !scene_.internal_reflection;
    // Refraction first in the math (total internal reflection turns it into a reflection),
    // reflection first in the tree.
    Refraction refr;
    // The refraction ray travels in the media after the boundary, the reflection ray in the
    // media before it.
    Crossing boundary = cross_boundary(scene_, node.media, node.object, node.t);
    double n1 = boundary.n1, n2 = boundary.n2;
    if (m.transmits()) {
      if (obj.solid) {
        refr = refract(d, node.facing_normal, n1, n2);
      } else {
        refr.direction = d;  // a flat object is a thin sheet: the ray passes straight through
      }
      tree_.nodes[index].refraction_math = refr;
      tree_.nodes[index].n1 = n1;
      tree_.nodes[index].n2 = n2;
    }
    double reflect_weight = m.reflectivity;
    double refract_weight = m.transparency;
    bool tir = m.transmits() && refr.total_internal_reflection;
    if (m.fresnel != FresnelModel::kNone && obj.solid) {
      // The reflectance F shares the light: F·k_r to the reflection, (1 − F)·k_t to the
      // refraction; under total internal reflection F = 1.
      double f = fresnel_reflectance(m.fresnel, refr.cos_i, n1, n2).reflectance;
      tree_.nodes[index].fresnel = f;
      reflect_weight = f * m.reflectivity;
      refract_weight = (1 - f) * m.transparency;
    } else if (tir) {
      reflect_weight += m.transparency;
    }
    if (reflect_weight > 0) {
      if (internal_skipped) {
        note(tir ? "Total internal reflection: no refraction ray, and the internal reflection "
                   "is not traced (the problem assumes no internal reflection)."
                 : "No reflection ray: the problem assumes no internal reflection.");
      } else {
        Vec3d r = normalized(reflect(d, node.facing_normal));
        Vec3d o = offset_ray_origin(node.point, node.point_error, node.facing_normal, r);
        int child = trace_ray(Ray{o, r, 0, kInfinity}, node.point, RayKind::kReflection, index,
                              depth + 1, node.path + ".R", reflect_weight,
                              offset_distance(node.point_error, node.facing_normal), node.media);
        tree_.nodes[index].reflection = child;
        if (tir) {
          tree_.nodes[child].total_internal_reflection = true;
          note(m.fresnel != FresnelModel::kNone
                   ? "Total internal reflection: no refraction ray; the reflectance is 1."
                   : "Total internal reflection: no refraction ray; the reflection ray carries "
                     "the transmitted share too.");
        }
      }
    }
    if (m.transmits() && !tir) {
      Vec3d t = refr.direction;
      Vec3d side = obj.solid ? -node.facing_normal : node.facing_normal;
      Vec3d o = offset_ray_origin(node.point, node.point_error, side, t);
      int child = trace_ray(Ray{o, t, 0, kInfinity}, node.point, RayKind::kRefraction, index,
                            depth + 1, node.path + ".T", refract_weight,
                            offset_distance(node.point_error, side), boundary.after);
      tree_.nodes[index].refraction = child;
    }
  }

  // I = k_a·I_a + Σ (diffuse + specular) + k_r·I_r + k_t·I_t.
  void total(int index, const Material& m) {
    TreeNode& node = tree_.nodes[index];
    node.ambient_term = m.ambient * scene_.ambient_light;
    node.local = node.ambient_term;
    for (const auto& s : node.lights) node.local += s.phong.diffuse + s.phong.specular;
    if (node.reflection >= 0) {
      node.reflected = tree_.nodes[node.reflection].weight * tree_.nodes[node.reflection].intensity;
    }
    if (node.refraction >= 0) {
      node.transmitted =
          tree_.nodes[node.refraction].weight * tree_.nodes[node.refraction].intensity;
    }
    node.intensity = node.local + node.reflected + node.transmitted;
  }

  void describe_effects() {
    auto& e = tree_.effects;
    bool hit_only = !shades(tree_.ask);
    const char* only = tree_.ask == Ask::kMedia
                           ? "the question asks only for the media along the ray"
                           : "the question asks only for the hit";
    bool any_reflects = false, any_transmits = false;
    for (const auto& o : scene_.objects) {
      any_reflects |= o.material.reflects();
      any_transmits |= o.material.transmits();
    }
    const RayCounts& c = tree_.counts;
    e.push_back(
        {"shading", !hit_only, hit_only ? only : "the Phong terms that apply at every hit point"});
    if (hit_only) {
      e.push_back({"shadow rays", false, only});
    } else if (scene_.lights.empty()) {
      e.push_back({"shadow rays", false, "the scene has no lights: only the ambient term applies"});
    } else {
      e.push_back({"shadow rays", true,
                   fmt::format("{} cast: one per light from each hit point, none toward a light "
                               "the surface faces away from; transparent objects {}",
                               c.shadow,
                               scene_.transparent_shadows == TransparentShadows::kBlock
                                   ? "block them like opaque ones"
                                   : "let their transparency k_t of the light through"),
                   c.shadow});
    }
    auto secondary = [&](const char* name, bool any, const char* none, int cast) {
      if (hit_only) {
        e.push_back({name, false, only});
      } else if (!any) {
        e.push_back({name, false, none});
      } else if (scene_.max_depth == 1) {
        e.push_back({name, false, "max_depth 1: the tree is the primary ray alone"});
      } else {
        e.push_back({name, true, fmt::format("{} cast", cast), cast});
      }
    };
    secondary("reflection", any_reflects, "no material reflects (every reflectivity is 0)",
              c.reflection);
    secondary("refraction", any_transmits, "nothing is transparent (every transparency is 0)",
              c.refraction);
    if (!scene_.internal_reflection && any_transmits && !hit_only) {
      e.push_back({"internal reflection", false, "the problem assumes no internal reflection"});
    }
    e.push_back({"intensity", tree_.ask == Ask::kIntensity,
                 tree_.ask == Ask::kIntensity ? "every node's intensity, leaves first"
                                              : "the question does not ask for intensities"});
  }

  const Scene& scene_;
  RayTree tree_;
};

}  // namespace

RayTree trace(const Scene& scene, const Ray& primary, Ask ask) {
  return Tracer(scene, ask).run(primary);
}

}  // namespace raygrade
