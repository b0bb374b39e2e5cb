// Scenes: reading objects, materials and lights, and the nearest hit of a world ray.
#include "scenes/scene.h"

#include <map>
#include <set>

#include "scenes/offset.h"
#include "shapes/primitives.h"

namespace raygrade {
namespace {

// A coefficient or intensity that may be a colour: its number (the largest channel) and, for a
// colour, the channels in `rgb`.
double intensity(const Cursor& c, std::string_view key, double fallback,
                 std::optional<Vec3d>& rgb) {
  if (!c.has(key)) return fallback;
  Intensity i = read_intensity(c.at(key), key);
  rgb = i.colour;
  return i.value;
}

double coefficient(const Cursor& c, std::string_view key, double fallback) {
  if (!c.has(key)) return fallback;
  double v = c.at(key).number();
  if (v < 0) c.at(key).fail(fmt::format("{} must not be negative", key), "range");
  return v;
}

// `half_space: true` on a plane: the plane bounds the half-space its normal points away
// from, and a ray that refracts into it stays inside until it leaves through a boundary.
void read_half_space(const Cursor& c, SceneObject& o) {
  std::string_view type = o.shape->type();
  if (!bounds_half_space(type)) {
    c.fail(o.solid
               ? fmt::format("a {} already bounds its inside: half_space is for an unbounded flat "
                             "surface (a plane)",
                             type)
               : fmt::format("a {} bounds no volume: only a plane can bound a half-space (a "
                             "transparent {} is a thin sheet)",
                             type, type),
           "invalid");
  }
  if (!c.json().is_boolean()) c.fail("expected true or false", "type");
  if (!c.json().get<bool>()) return;
  if (!o.material.transmits()) {
    c.fail("half_space gives a plane an inside for refraction: its material must be transparent",
           "invalid");
  }
  o.solid = true;
  o.half_space = true;
}

}  // namespace

Material read_material(const Cursor& c) {
  if (c.has("colour")) {
    c.at("colour").fail(
        "a material's colour or pattern is read by shade problems only; in a scene, give k_a "
        "and k_d as colours [r, g, b]",
        "unsupported");
  }
  c.allow_only({"ambient", "diffuse", "specular", "shininess", "reflectivity", "transparency",
                "refractive_index", "fresnel"});
  Material m;
  m.ambient = intensity(c, "ambient", m.ambient, m.ambient_rgb);
  m.diffuse = intensity(c, "diffuse", m.diffuse, m.diffuse_rgb);
  m.specular = intensity(c, "specular", m.specular, m.specular_rgb);
  m.shininess = coefficient(c, "shininess", m.shininess);
  m.reflectivity = coefficient(c, "reflectivity", m.reflectivity);
  m.transparency = coefficient(c, "transparency", m.transparency);
  if (m.reflectivity > 1) c.at("reflectivity").fail("reflectivity is at most 1", "range");
  if (m.transparency > 1) c.at("transparency").fail("transparency is at most 1", "range");
  if (m.transmits() && !c.has("refractive_index")) {
    c.fail("a transparent material needs its refractive_index (1.5 for glass)", "missing");
  }
  if (c.has("refractive_index")) m.refractive_index = c.at("refractive_index").positive_number();
  if (c.has("fresnel")) {
    std::string model = c.at("fresnel").string();
    if (model != "schlick" && model != "exact") {
      c.at("fresnel").fail("expected \"schlick\" or \"exact\"", "invalid");
    }
    if (!m.transmits()) {
      c.at("fresnel").fail(
          "fresnel shares the light between reflection and refraction: the material must be "
          "transparent (transparency > 0)",
          "invalid");
    }
    m.fresnel = model == "schlick" ? FresnelModel::kSchlick : FresnelModel::kExact;
  }
  return m;
}

nlohmann::json material_json(const Material& m) {
  nlohmann::json j = {{"ambient", intensity_json({m.ambient, m.ambient_rgb})},
                      {"diffuse", intensity_json({m.diffuse, m.diffuse_rgb})},
                      {"specular", intensity_json({m.specular, m.specular_rgb})},
                      {"shininess", m.shininess},
                      {"reflectivity", m.reflectivity},
                      {"transparency", m.transparency}};
  if (m.transmits()) j["refractive_index"] = m.refractive_index;
  if (m.fresnel != FresnelModel::kNone) j["fresnel"] = to_string(m.fresnel);
  return j;
}

Light read_light(const Cursor& c, int index) {
  c.allow_only({"name", "type", "position", "direction", "intensity"});
  Light l;
  l.name = c.string_or("name", fmt::format("L{}", index + 1));
  std::string type = c.string_or("type", "point");
  if (type == "point") {
    l.type = LightType::kPoint;
    l.position = c.at("position").vec3();
    if (c.has("direction")) c.at("direction").fail("a point light has a position only", "invalid");
  } else if (type == "directional") {
    l.type = LightType::kDirectional;
    l.direction = c.at("direction").nonzero_vec3();
    if (c.has("position")) {
      c.at("position").fail("a directional light has a direction only", "invalid");
    }
  } else {
    c.at("type").fail(fmt::format("unknown light type '{}' (known: point, directional)", type),
                      "invalid");
  }
  l.intensity = intensity(c, "intensity", 1, l.colour);
  return l;
}

Scene read_scene(const Cursor& c) {
  c.allow_only({"objects", "lights", "materials", "ambient_light", "background", "refractive_index",
                "max_depth", "internal_reflection", "transparent_shadows"});
  Scene s;
  std::map<std::string, Material, std::less<>> named;
  if (auto m = c.find("materials")) {
    if (!m->is_object()) m->fail("materials is an object of named materials", "type");
    for (const auto& [key, value] : m->json().items()) {
      named[key] = read_material(m->at(key));
    }
  }
  std::set<std::string> names;
  std::map<std::string, int> per_type;
  auto items = c.at("objects").items();
  if (items.empty()) c.at("objects").fail("the scene has no objects", "invalid");
  for (const auto& item : items) {
    SceneObject o;
    o.shape = read_primitive(item);
    std::string type(o.shape->type());
    int n = ++per_type[type];
    o.name = item.has("name") ? item.at("name").string() : fmt::format("{} {}", type, n);
    if (o.name.empty()) item.at("name").fail("the name must not be empty", "invalid");
    if (!names.insert(o.name).second) {
      item.at(item.has("name") ? "name" : "type")
          .fail(fmt::format("duplicate object name '{}'", o.name), "duplicate-name");
    }
    if (auto m = item.find("material")) {
      if (m->json().is_string()) {
        auto it = named.find(m->string());
        if (it == named.end()) {
          m->fail(fmt::format("no material named '{}' in the scene's materials", m->string()),
                  "unknown-material");
        }
        o.material = it->second;
      } else {
        o.material = read_material(*m);
      }
    }
    if (auto t = item.find("transform")) o.transform = read_transform(*t);
    o.solid = o.shape->solid();
    if (auto h = item.find("half_space")) read_half_space(*h, o);
    s.objects.push_back(std::move(o));
  }
  if (auto lights = c.find("lights")) {
    auto list = lights->items();
    for (std::size_t i = 0; i < list.size(); ++i) {
      s.lights.push_back(read_light(list[i], static_cast<int>(i)));
      for (std::size_t j = 0; j < i; ++j) {
        if (s.lights[j].name == s.lights[i].name) {
          list[i].fail(fmt::format("duplicate light name '{}'", s.lights[i].name),
                       "duplicate-name");
        }
      }
    }
  }
  s.ambient_light = intensity(c, "ambient_light", s.ambient_light, s.ambient_light_rgb);
  s.background = intensity(c, "background", s.background, s.background_rgb);
  if (c.has("refractive_index")) s.refractive_index = c.at("refractive_index").positive_number();
  if (c.has("max_depth")) {
    s.max_depth = c.at("max_depth").integer();
    if (s.max_depth < 1 || s.max_depth > kMaxTreeDepth) {
      c.at("max_depth")
          .fail(fmt::format("max_depth counts ray generations, from 1 (the primary ray only) to {}",
                            kMaxTreeDepth),
                "range");
    }
  }
  s.internal_reflection = c.boolean_or("internal_reflection", true);
  std::string shadows = c.string_or("transparent_shadows", "block");
  if (shadows != "block" && shadows != "transmit") {
    c.at("transparent_shadows")
        .fail(fmt::format("unknown transparent_shadows '{}' (known: block, transmit)", shadows),
              "invalid");
  }
  s.transparent_shadows =
      shadows == "transmit" ? TransparentShadows::kTransmit : TransparentShadows::kBlock;
  return s;
}

bool has_colour(const Material& m) { return m.has_colour(); }
bool has_colour(const Light& l) { return l.colour.has_value(); }

bool has_colour(const Scene& s) {
  if (s.ambient_light_rgb || s.background_rgb) return true;
  for (const auto& o : s.objects) {
    if (has_colour(o.material)) return true;
  }
  for (const auto& l : s.lights) {
    if (has_colour(l)) return true;
  }
  return false;
}

namespace {

void pick(double& value, std::optional<Vec3d>& rgb, int c) {
  if (rgb) value = (*rgb)[c];
  rgb.reset();
}

}  // namespace

Material channel(const Material& m, int c) {
  Material out = m;
  pick(out.ambient, out.ambient_rgb, c);
  pick(out.diffuse, out.diffuse_rgb, c);
  pick(out.specular, out.specular_rgb, c);
  return out;
}

Light channel(const Light& l, int c) {
  Light out = l;
  pick(out.intensity, out.colour, c);
  return out;
}

void keep_channel(Scene& s, int c) {
  pick(s.ambient_light, s.ambient_light_rgb, c);
  pick(s.background, s.background_rgb, c);
  for (auto& o : s.objects) o.material = channel(o.material, c);
  for (auto& l : s.lights) l = channel(l, c);
}

namespace {

// Every hit of one object in world terms, nearest first.
std::vector<SceneHit> object_hits(const SceneObject& o, int index, const Ray& ray) {
  bool moved = !o.transform.identity();
  Ray local = moved ? o.transform.ray_to_object(ray) : ray;
  Intersection x = o.shape->intersect(local);
  if (moved) x = o.transform.hits_to_world(ray, std::move(x));
  std::vector<SceneHit> out;
  for (const Hit& hit : x.hits) {
    SceneHit h;
    h.object = index;
    h.object_ray = local;
    h.hit = hit;
    if (!moved) h.hit.point = ray.at(h.hit.t);
    h.point_error = hit_point_error(ray, h.hit.t, moved ? &o.transform : nullptr);
    out.push_back(h);
  }
  return out;
}

// The first hit of one object, in world terms.
std::optional<SceneHit> object_hit(const SceneObject& o, int index, const Ray& ray) {
  std::vector<SceneHit> hits = object_hits(o, index, ray);
  if (hits.empty()) return std::nullopt;
  return hits.front();
}

bool nearer(const SceneHit& a, const SceneHit& b) { return a.hit.t < b.hit.t; }

}  // namespace

SceneHit nearest_hit(const Scene& scene, const Ray& ray) {
  SceneHit best;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    auto h = object_hit(scene.objects[i], static_cast<int>(i), ray);
    if (h && (best.object < 0 || h->hit.t < best.hit.t)) best = *h;
  }
  return best;
}

std::vector<SceneHit> all_hits(const Scene& scene, const Ray& ray) {
  std::vector<SceneHit> out;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (auto h = object_hit(scene.objects[i], static_cast<int>(i), ray)) out.push_back(*h);
  }
  std::stable_sort(out.begin(), out.end(), nearer);
  return out;
}

std::vector<SceneHit> every_hit(const Scene& scene, const Ray& ray) {
  std::vector<SceneHit> out;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    for (auto& h : object_hits(scene.objects[i], static_cast<int>(i), ray)) out.push_back(h);
  }
  std::stable_sort(out.begin(), out.end(), nearer);
  return out;
}

}  // namespace raygrade
