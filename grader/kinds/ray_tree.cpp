// The ray-tree kind.
#include "kinds/ray_tree.h"

#include <algorithm>
#include <set>

#include "core/internal_error.h"
#include "derivation/number_format.h"
#include "kinds/camera_ray.h"
#include "kinds/view_ray.h"
#include "scenes/tree_json.h"
#include "scenes/tree_steps.h"

namespace raygrade {

Ray read_primary_ray(const Cursor& problem) {
  if (problem.has("ray")) {
    if (problem.has("camera"))
      problem.at("camera").fail("give either a ray or a camera", "invalid");
    return read_ray(problem.at("ray"));
  }
  if (!problem.has("camera")) problem.fail("a ray or a camera and pixel is needed", "missing");
  if (is_view_camera(problem.at("camera"))) {
    ViewCamera view = read_view_camera(problem.at("camera"));
    auto [i, j] = read_pixel(problem, view.nx, view.ny);
    return view_ray(view, i, j, read_pixel_convention(problem));
  }
  Camera cam = read_camera(problem.at("camera"));
  auto [x, y] = read_pixel(problem, cam.res_x, cam.res_y);
  Vec3d d = camera_ray_direction(cam, x, y, read_pixel_convention(problem));
  return Ray{cam.eye, d, 0, kInfinity};
}

Ask read_ask(const Cursor& problem, Ask fallback) {
  if (!problem.has("ask")) return fallback;
  std::string a = problem.at("ask").string();
  if (a == "hit") return Ask::kHit;
  if (a == "tree") return Ask::kTree;
  if (a == "intensity") return Ask::kIntensity;
  if (a == "media") return Ask::kMedia;
  problem.at("ask").fail(fmt::format("unknown ask '{}' (known: hit, tree, intensity, media)", a),
                         "invalid");
}

const std::vector<std::string>& intensity_components() {
  static const std::vector<std::string> names = {"ambient",   "diffuse",     "specular", "local",
                                                 "reflected", "transmitted", "total"};
  return names;
}

double component_value(const TreeNode& node, std::string_view component) {
  double diffuse = 0, specular = 0;
  for (const auto& s : node.lights) {
    diffuse += s.phong.diffuse;
    specular += s.phong.specular;
  }
  if (component == "ambient") return node.ambient_term;
  if (component == "diffuse") return diffuse;
  if (component == "specular") return specular;
  if (component == "local") return node.local;
  if (component == "reflected") return node.reflected;
  if (component == "transmitted") return node.transmitted;
  if (component == "total") return node.intensity;
  throw InternalError(fmt::format("no intensity component named '{}'", component));
}

void apply_labels(RayTree& tree, const std::map<std::string, std::string>& labels) {
  for (const auto& [path, label] : labels) {
    for (auto& n : tree.nodes) {
      if (n.path == path) n.label = label;
    }
  }
}

RayTreeTask::RayTreeTask(Scene scene, Ray primary, Ask ask,
                         std::map<std::string, std::string> labels)
    : scene_(std::move(scene)), primary_(primary), tree_(trace(scene_, primary_, ask)) {
  apply_labels(tree_, labels);
}

std::unique_ptr<Task> RayTreeTask::read(const Cursor& problem) {
  Scene scene = read_scene(problem.at("scene"));
  Ray primary = read_primary_ray(problem);
  Ask ask = read_ask(problem, Ask::kTree);
  std::map<std::string, std::string> labels;
  if (auto l = problem.find("labels")) {
    if (!l->is_object()) l->fail("labels is an object from a node's path to its label", "type");
    for (const auto& [path, value] : l->json().items()) labels[path] = l->at(path).string();
  }
  auto task = std::make_unique<RayTreeTask>(std::move(scene), primary, ask, labels);
  // Every labelled path must be a hit of the tree, and the labels must stay unique.
  std::set<std::string> seen;
  for (const auto& [path, label] : labels) {
    const TreeNode* n = task->tree().find(path);
    if (!n || !n->hit) {
      std::vector<std::string> paths;
      for (const auto& node : task->tree().nodes) {
        if (node.hit) paths.push_back(node.path);
      }
      problem.at("labels").at(path).fail(
          fmt::format("the tree has no hit point at path '{}' (its points: {})", path,
                      fmt::join(paths, ", ")),
          "unknown-path");
    }
  }
  for (const auto& n : task->tree().nodes) {
    if (!seen.insert(n.label).second) {
      problem.at("labels").fail(fmt::format("the label '{}' names two nodes", n.label),
                                "duplicate-label");
    }
  }
  if (auto c = problem.find("components")) task->read_components(*c);
  return task;
}

// `components`: {"I1": ["diffuse", "specular"], "I2": ["total"]}, by the tree's labels.
void RayTreeTask::read_components(const Cursor& c) {
  if (tree_.ask != Ask::kIntensity) {
    c.fail("components are parts of intensities: the problem needs \"ask\": \"intensity\"",
           "invalid");
  }
  if (!c.is_object() || c.json().empty()) {
    c.fail("components is an object from a hit point's label to the components asked there",
           "type");
  }
  const std::vector<std::string>& known = intensity_components();
  for (const auto& [label, value] : c.json().items()) {
    const TreeNode* node = nullptr;
    std::vector<std::string> labels;
    for (const auto& n : tree_.nodes) {
      if (!n.hit) continue;
      labels.push_back(n.label);
      if (n.label == label) node = &n;
    }
    if (!node) {
      c.at(label).fail(fmt::format("the tree has no hit point labelled '{}' (its points: {})",
                                   label, fmt::join(labels, ", ")),
                       "unknown-label");
    }
    auto items = c.at(label).items();
    if (items.empty()) c.at(label).fail("name at least one component", "invalid");
    for (const auto& item : items) {
      std::string name = item.string();
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        item.fail(fmt::format("unknown component '{}' (known: {})", name, fmt::join(known, ", ")),
                  "invalid");
      }
      for (const auto& a : components_) {
        if (a.node == node->index && a.component == name) {
          item.fail(fmt::format("{} is asked twice at {}", name, label), "duplicate");
        }
      }
      components_.push_back(ComponentAsk{node->index, label, name});
    }
  }
}

nlohmann::json RayTreeTask::answer() const {
  nlohmann::json j = tree_json(tree_, scene_);
  if (components_.empty()) return j;
  nlohmann::json c = nlohmann::json::object();
  for (const auto& a : components_) {
    c[a.label][a.component] = component_value(tree_.nodes[a.node], a.component);
  }
  j["components"] = c;
  return j;
}

std::vector<SolutionPart> RayTreeTask::derive(std::string_view /*method*/,
                                              const Overrides* overrides) const {
  std::vector<SolutionPart> parts = tree_parts(tree_, scene_, overrides);
  if (!components_.empty()) {
    Deriver d("whitted", "The components asked");
    for (auto& sentence : component_sentences()) d.conclude(std::move(sentence));
    parts.push_back(SolutionPart{"", std::move(d).finish(), {}});
  }
  return parts;
}

// "I1's diffuse component is 0.6.", one sentence per component asked.
std::vector<std::string> RayTreeTask::component_sentences() const {
  std::vector<std::string> out;
  for (const auto& c : components_) {
    out.push_back(fmt::format("{}'s {} is {}.", c.label,
                              c.component == "total" ? "intensity" : c.component + " component",
                              format_number(component_value(tree_.nodes[c.node], c.component))));
  }
  return out;
}

std::vector<std::string> RayTreeTask::conclusion() const {
  std::vector<std::string> out = tree_answer(tree_, scene_).conclusion;
  for (auto& s : component_sentences()) out.push_back(std::move(s));
  return out;
}

}  // namespace raygrade
