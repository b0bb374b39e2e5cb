// The 3D view's data: the givens as the problem's task answers for them (Task::scene_givens), the
// answers from its reference answer.
#include "reports/scene_view.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "core/escape.h"
#include "json/numbers.h"
#include "kinds/part_names.h"
#include "problems/scene_givens.h"
#include "shapes/disk.h"
#include "shapes/transformed.h"
#include "shapes/triangle.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

json point_json(const Vec3d& v) { return json::array({v.x, v.y, v.z}); }

// The bounding box of everything drawn that has a size, from which the viewer takes the
// scene's centre and size (and the size of an infinite plane or cylinder).
struct Bounds {
  Vec3d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3d hi = -lo;
  void add(const Vec3d& p, double r = 0) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k] - r);
      hi[k] = std::max(hi[k], p[k] + r);
    }
  }
  bool empty() const { return !(lo.x <= hi.x); }
  json frame() const {
    if (empty()) return {{"center", point_json({0, 0, 0})}, {"radius", 1.0}};
    double radius = length(hi - lo) / 2;
    // A scene of one point still needs a size to be seen at.
    if (!(radius > 0)) radius = 1;
    return {{"center", point_json((lo + hi) * 0.5)}, {"radius", radius}};
  }
};

// An object as the viewer builds it: its primitive's parameters in object space and the
// matrix that places it (rows of A with b: p_world = A·p + b), when it is transformed.
json object_json(const std::string& label, const Shape& shape, const Transform* transform) {
  const Shape* primitive = &shape;
  if (const auto* placed = dynamic_cast<const TransformedShape*>(&shape)) {
    primitive = &placed->object();
    transform = &placed->transform();
  }
  json j = {{"label", label.empty() ? std::string(primitive->type()) : label},
            {"shape", primitive->to_json()}};
  if (transform && !transform->identity()) {
    const Affine& m = transform->to_world;
    json rows = json::array();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) rows.push_back(m.rows[r][c]);
      rows.push_back(m.translation[r]);
    }
    j["matrix"] = rows;
  }
  return j;
}

// The four corners of a rectangle around `centre` with half-sides `a` and `b`.
json rectangle(const Vec3d& centre, const Vec3d& a, const Vec3d& b) {
  return json::array({point_json(centre - a - b), point_json(centre + a - b),
                      point_json(centre + a + b), point_json(centre - a + b)});
}

// The camera and its pixel: the eye, the image plane's corners, the pixel's corners (not the
// ray through it, which the camera kinds ask for).
json camera_json(const GivenCamera& cam, Bounds& bounds) {
  json j = {{"eye", point_json(cam.eye)},
            {"look", point_json(cam.look)},
            {"orthographic", cam.orthographic},
            {"corners", rectangle(cam.plane_center, cam.plane_half_x, cam.plane_half_y)},
            {"pixel", rectangle(cam.pixel_center, cam.pixel_half_x, cam.pixel_half_y)}};
  bounds.add(cam.eye);
  bounds.add(cam.plane_center - cam.plane_half_x - cam.plane_half_y);
  bounds.add(cam.plane_center + cam.plane_half_x + cam.plane_half_y);
  return j;
}

// A light as the viewer draws it: a point light at its position, a directional one by the
// direction its light travels.
json light_json(const GivenLight& l) {
  if (l.directional) return {{"label", l.name}, {"direction", point_json(l.direction)}};
  return {{"label", l.name}, {"position", point_json(l.position)}};
}

Vec3d vec3_of(const json& a) {
  return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()};
}

bool is_vec3(const json& a) { return a.is_array() && a.size() == 3 && a[0].is_number(); }

// What the answer holds that can be drawn, whatever the kind: hits (with normals), a ray tree's
// nodes, a ray (the camera kinds), a normal at the given point.
json answers_json(const json& answer, const json& data, double size) {
  json hits = json::array(), segments = json::array();
  auto ray_segment = [&](const Vec3d& origin, const Vec3d& direction, const char* role) {
    double len = length(direction);
    if (!(len > 0)) return;
    segments.push_back({{"from", point_json(origin)},
                        {"to", point_json(origin + (2 * size / len) * direction)},
                        {"role", role}});
  };
  if (answer.contains("hits") && answer["hits"].is_array()) {
    for (const auto& h : answer["hits"]) {
      if (!h.is_object() || !h.contains("point") || !is_vec3(h["point"])) continue;
      json hit = {{"point", h["point"]}};
      if (h.contains("normal")) hit["normal"] = h["normal"];
      hits.push_back(hit);
    }
  }
  if (answer.contains("nodes") && answer["nodes"].is_array()) {
    std::map<std::string, json> lights;
    for (const auto& l : data.value("lights", json::array())) lights[l.value("label", "")] = l;
    for (const auto& n : answer["nodes"]) {
      if (!n.contains("origin") || !n.contains("direction")) continue;
      std::string role = n.value("ray", "primary");
      Vec3d origin = vec3_of(n["origin"]);
      if (n.value("hit", false) && n.contains("point") && is_vec3(n["point"])) {
        Vec3d point = vec3_of(n["point"]);
        segments.push_back(
            {{"from", point_json(origin)}, {"to", point_json(point)}, {"role", role}});
        json hit = {{"point", n["point"]}};
        if (n.contains("normal")) hit["normal"] = n["normal"];
        hits.push_back(hit);
        for (const auto& l : n.value("lights", json::array())) {
          auto found = lights.find(l.value("light", ""));
          if (found == lights.end() || !found->second.contains("position")) continue;
          segments.push_back(
              {{"from", point_json(point)}, {"to", found->second["position"]}, {"role", "shadow"}});
        }
      } else {
        ray_segment(origin, vec3_of(n["direction"]), role.c_str());
      }
    }
  }
  namespace part = part_names;
  if (answer.contains(part::kRay) && answer[part::kRay].is_object()) {
    const json& ray = answer[part::kRay];
    ray_segment(vec3_of(ray.at(part::kOrigin)), vec3_of(ray.at(part::kDirection)), "answer");
  } else if (answer.contains(part::kOrigin) && answer.contains(part::kDirection) &&
             is_vec3(answer[part::kOrigin]) && is_vec3(answer[part::kDirection])) {
    ray_segment(vec3_of(answer[part::kOrigin]), vec3_of(answer[part::kDirection]), "answer");
  }
  if (answer.contains(part::kNormal) && is_vec3(answer[part::kNormal]) && data.contains("points")) {
    // not a part: the view's keys of a hit, the given point P and the answer's normal there
    hits.push_back({{"point", data["points"][0]["at"]}, {"normal", answer[part::kNormal]}});
  }
  return {{"hits", hits}, {"segments", segments}};
}

// A problem at one point of a surface and no objects: the surface as a small disk through the
// point across its normal (or the triangle the point lies on), the normal as an arrow, the
// incoming direction arriving at the point, the eye and the lights. `words` gets what is drawn,
// for the text alternative. False when the surface has neither a normal nor a triangle.
bool local_surface(const SceneGivens& g, const GivenSurface& surface, json& data, Bounds& bounds,
                   std::vector<std::string>& words) {
  if (!surface.normal && !surface.vertices) return false;
  Vec3d point = g.point.value_or(Vec3d{});
  // The size of what is drawn: the distance to the farthest eye or light, at least 1.
  double size = 1;
  std::vector<Vec3d> around;
  if (surface.eye) around.push_back(*surface.eye);
  for (const auto& l : g.lights) {
    if (!l.directional) around.push_back(l.position);
  }
  for (const Vec3d& a : around) size = std::max(size, length(a - point));
  data["arrows"] = json::array();
  if (surface.vertices) {
    const std::array<Vec3d, 3>& vertices = *surface.vertices;
    Triangle t(vertices[0], vertices[1], vertices[2]);
    data["objects"].push_back({{"label", std::string(Triangle::kType)}, {"shape", t.to_json()}});
    words.emplace_back("the triangle with its vertex normals (blue)");
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const Vec3d& v = vertices[i];
      bounds.add(v);
      const Vec3d& n = surface.vertex_normals[i];
      if (length(n) > 0) {
        bounds.add(v + normalized(n));
        data["arrows"].push_back(
            {{"from", point_json(v)}, {"to", point_json(v + normalized(n))}, {"role", "normal"}});
      }
    }
    bounds.add(point);
  } else {
    Vec3d n = normalized(*surface.normal);
    double radius = 0.6 * size;
    data["objects"].push_back({{"label", "surface"}, {"shape", Disk(point, n, radius).to_json()}});
    data["arrows"].push_back({{"from", point_json(point)},
                              {"to", point_json(point + 0.5 * size * n)},
                              {"role", "normal"}});
    bounds.add(point, radius);
    words.emplace_back("the surface at P with its normal (blue)");
  }
  if (surface.incoming && length(*surface.incoming) > 0) {
    Vec3d d = normalized(*surface.incoming);
    Vec3d from = point - 0.8 * size * d;
    data["arrows"].push_back(
        {{"from", point_json(from)}, {"to", point_json(point)}, {"role", "ray"}});
    bounds.add(from);
    words.emplace_back("the incoming ray (black) arriving at P");
  }
  // A triangle's point is where it is given; a surface's is the origin when it is not.
  if (g.point || !surface.vertices)
    data["points"].push_back({{"at", point_json(point)}, {"label", "P"}});
  if (surface.eye) {
    data["points"].push_back({{"at", point_json(*surface.eye)}, {"label", "eye"}});
    bounds.add(*surface.eye);
    words.emplace_back("the eye (grey)");
  }
  if (!g.lights.empty()) {
    std::vector<std::string> names;
    for (const auto& l : g.lights) {
      data["lights"].push_back(light_json(l));
      names.push_back(l.name);
      if (!l.directional) bounds.add(l.position);
    }
    words.push_back(
        fmt::format("the light{} {}", names.size() > 1 ? "s" : "", fmt::join(names, ", ")));
  }
  return true;
}

}  // namespace

std::optional<SceneView> scene_view(const Problem& problem, bool answers) {
  // The givens, as the problem's kind reads them: only what the student is given.
  std::optional<SceneGivens> givens = problem.task ? problem.task->scene_givens() : std::nullopt;
  if (!givens) return std::nullopt;
  const SceneGivens& g = *givens;
  json data = {{"objects", json::array()}};
  Bounds bounds;
  std::vector<std::string> words;
  for (const GivenObject& o : g.objects) {
    json object = object_json(o.name, *o.shape, o.transform);
    Vec3d centre = o.shape->center();
    double extent = o.shape->extent();
    if (const Transform* t = o.transform; t && !t->identity()) {
      const auto& a = t->to_world.rows;
      centre = t->to_world.point(centre);
      extent *= std::sqrt(dot(a[0], a[0]) + dot(a[1], a[1]) + dot(a[2], a[2]));
    }
    bounds.add(centre, extent);
    words.push_back(object["label"].get<std::string>());
    data["objects"].push_back(object);
  }
  bool camera = g.camera.has_value();
  if (camera) {
    data["camera"] = camera_json(*g.camera, bounds);
    // Where the pixel lies is what a camera kind asks for: a page of givens leaves it out.
    if (!answers) data["camera"].erase("pixel");
  }
  std::vector<std::string> local_words;
  bool local = false;
  if (data["objects"].empty() && !camera) {
    local = g.surface && local_surface(g, *g.surface, data, bounds, local_words);
    if (!local) return std::nullopt;
  }
  // The lights of a scene; a surface's are drawn with it.
  std::vector<std::string> lights;
  if (!local) {
    for (const GivenLight& l : g.lights) {
      data["lights"].push_back(light_json(l));
      if (!l.directional) bounds.add(l.position);
      lights.push_back(l.name);
    }
  }
  if (g.ray) {
    data["ray"] = {{"origin", point_json(g.ray->origin)},
                   {"direction", point_json(g.ray->direction)}};
    bounds.add(g.ray->origin);
  }
  if (g.point && !local && !data["objects"].empty()) {
    data["points"].push_back({{"at", point_json(*g.point)}, {"label", "P"}});
    bounds.add(*g.point);
  }
  data["frame"] = bounds.frame();

  SceneView view;
  std::string text = "The scene in 3D";
  if (local) {
    text = fmt::format("The point P in 3D: {}", fmt::join(local_words, "; "));
  } else if (!words.empty()) {
    text += fmt::format(": {}", fmt::join(words, ", "));
  }
  // not a part: the view's given ray
  if (data.contains("ray"))
    text += "; the given ray, an arrow from its origin (its length is not t)";
  if (!lights.empty())
    text += fmt::format("; the light{} {}", lights.size() > 1 ? "s" : "", fmt::join(lights, ", "));
  if (camera) {
    text += answers ? "; the camera's eye, its image plane and the pixel (orange)"
                    : "; the camera's eye and its image plane";
  }
  if (data.contains("points")) text += "; the point P";
  if (answers) {
    const json answer = problem.task->answer();
    data["answers"] = answers_json(answer, data, data["frame"]["radius"].get<double>());
    if (local && answer.contains(part_names::kDirection) &&
        is_vec3(answer[part_names::kDirection]) && data.contains("points")) {
      // The direction asked for (reflected, refracted), leaving P.
      Vec3d at = vec3_of(data["points"][0]["at"]);
      Vec3d d = vec3_of(answer[part_names::kDirection]);
      if (length(d) > 0) {
        double size = data["frame"]["radius"].get<double>();
        data["answers"]["segments"].push_back(
            {{"from", point_json(at)},
             {"to", point_json(at + (0.8 * size) * normalized(d))},
             {"role", "answer"}});
      }
    }
    if (!data["answers"]["hits"].empty())
      text += "; the hit points (red) with their normals (blue)";
    if (!data["answers"]["segments"].empty()) text += "; the rays of the answer";
  }
  view.description = text + ".";
  view.data = std::move(data);
  return view;
}

std::string scene_view_html(const SceneView& view, const std::string& id,
                            const std::string& title) {
  return fmt::format(
      "<figure class=\"scene-view-figure\">\n<div class=\"scene-view\" data-scene=\"{0}-data\" "
      "data-label=\"{1}\" data-describedby=\"{0}-text\">The 3D view needs JavaScript and WebGL; "
      "the sketch shows the scene.</div>\n<figcaption id=\"{0}-text\">{2} Drag to turn it "
      "(or arrow keys with Shift), right-drag or arrow keys to move, wheel or + and − to zoom, "
      "0 to start again.</figcaption>\n<script type=\"application/json\" id=\"{0}-data\">{3}"
      "</script>\n</figure>\n",
      html_escape(id), html_escape("3D view: " + title), html_escape(view.description),
      script_json(view.data));
}

}  // namespace raygrade
