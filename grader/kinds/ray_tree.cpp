// The ray-tree kind.
#include "kinds/ray_tree.h"

#include <set>

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
  problem.at("ask").fail(fmt::format("unknown ask '{}' (known: hit, tree, intensity)", a),
                         "invalid");
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
  return task;
}

nlohmann::json RayTreeTask::answer() const { return tree_json(tree_, scene_); }

std::vector<SolutionPart> RayTreeTask::derive(std::string_view /*method*/,
                                              const Overrides* overrides) const {
  return tree_parts(tree_, scene_, overrides);
}

std::vector<std::string> RayTreeTask::conclusion() const {
  return tree_answer(tree_, scene_).conclusion;
}

}  // namespace raygrade
