// Kind `ray-tree`: the tree of rays one primary ray spawns in a scene (seed 001), with shadow
// rays, the Phong terms that apply at each point and, when asked, every intensity.
#pragma once

#include <map>

#include "problems/kind.h"
#include "problems/problem.h"
#include "scenes/scene.h"
#include "scenes/trace.h"

namespace raygrade {

// The kind `ray-tree` (kinds/kind.h).
struct RayTreeKind {
  static constexpr std::string_view kName = "ray-tree";
  // A node's key of where its ray comes from ("R" reflected, "T" transmitted; docs/ray-tree.md).
  static constexpr char kNodeRay[] = "ray";
  static constexpr std::string_view kSummary =
      "the tree of rays one ray spawns in a scene: shadows, reflection, refraction, Phong";
  static constexpr GraderFamily kGrader = GraderFamily::kRayTree;
  static std::vector<std::string> keys() {
    return {"scene", "ray", "camera", "pixel", "convention", "ask", "labels", "components"};
  }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

// The primary ray of a problem: its `ray`, or the ray through its camera's pixel, with that
// camera and pixel as the 3D view draws them.
struct PrimaryRay {
  Ray ray;
  std::optional<GivenCamera> camera;  // when the ray comes from a camera
};

// Reads a problem's `ray`, or its `camera` and `pixel` (and `convention`), as the primary ray.
PrimaryRay read_primary_ray(const Cursor& problem);

// Reads `ask`: "hit", "tree" (the default), "intensity" or "media".
Ask read_ask(const Cursor& problem, Ask fallback);

// The components of a hit node's intensity a problem may ask for: ambient, diffuse, specular
// (each summed over the lights), local (their sum), reflected and transmitted (the children's
// weighted shares k_r·I_R and k_t·I_T) and total.
const std::vector<std::string>& intensity_components();
double component_value(const TreeNode& node, std::string_view component);

// One component asked at one hit node.
struct ComponentAsk {
  int node = -1;
  std::string label;  // the node's label
  std::string component;
  std::string part() const { return label + "." + component; }  // "I1.diffuse"
};

class RayTreeTask final : public Task {
 public:
  RayTreeTask(Scene scene, Ray primary, Ask ask, const std::map<std::string, std::string>& labels);
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return RayTreeKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"whitted"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  std::vector<std::string> conclusion() const override;
  // The convention on a point that faces away from a light whose shadow ray is blocked.
  void follow(const Conventions& conventions) override;
  // The scene's objects and lights, and the ray or the camera the problem gives.
  std::optional<SceneGivens> scene_givens() const override;

  const Scene& scene() const { return scene_; }
  // The tree's rays, hits, shadows and terms. When the scene has colours, its intensities are
  // in the channel trees instead and this tree is traced without them (its ask is kTree).
  const RayTree& tree() const { return tree_; }
  // What the problem asks (the tree's own ask, except for a colour scene's intensities).
  Ask ask() const { return channels_.empty() ? tree_.ask : Ask::kIntensity; }

  // A colour scene asked for intensities: the same tree traced once per channel (r, g, b), each
  // in the scene with every colour replaced by that channel's number.
  void trace_channels(std::vector<Scene> channel_scenes,
                      const std::map<std::string, std::string>& labels);
  bool colour() const { return !channels_.empty(); }
  const std::vector<RayTree>& channels() const { return channels_; }
  // The colour along the primary ray, and at every node (only when colour()).
  Vec3d colour_intensity() const;
  std::vector<Vec3d> node_colours() const;
  // The components the problem asks for (`components`); empty when it asks for the tree.
  const std::vector<ComponentAsk>& components() const { return components_; }

 private:
  void read_components(const Cursor& components);
  std::vector<std::string> component_sentences() const;
  std::vector<ComponentAsk> components_;
  Scene scene_;
  Ray primary_;
  std::optional<GivenCamera> camera_;  // the camera the primary ray comes from, if any
  RayTree tree_;
  std::vector<Scene> channel_scenes_;
  std::vector<RayTree> channels_;
};

// The problem's own names for the tree's points ({"P": "I1", "P.T": "I2"}): every path must be
// a hit node of the tree and every label unique; others keep their automatic labels.
void apply_labels(RayTree& tree, const std::map<std::string, std::string>& labels);

}  // namespace raygrade
