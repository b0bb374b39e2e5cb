// Drawings of a ray tree: SVG for HTML pages, Graphviz DOT, and text for a terminal. Each
// shows the eye, every ray node (R: reflection, T: refraction) with the object it hits, and
// each shadow ray with its light, visible or blocked and by what.
#pragma once

#include <string>
#include <vector>

#include "scenes/trace.h"

namespace raygrade {

std::string tree_text(const RayTree& tree, const Scene& scene);
std::string tree_dot(const RayTree& tree, const Scene& scene);
// With `colours` (one per node, a colour tree's intensities), each point is drawn with a swatch
// of its colour beside it, clamped to [0, 1] for display.
std::string tree_svg(const RayTree& tree, const Scene& scene,
                     const std::vector<Vec3d>* colours = nullptr);

// Short words for a node and a shadow ray, shared by the three drawings.
std::string node_caption(const RayTree& tree, const Scene& scene, const TreeNode& node);
std::string shadow_caption(const Scene& scene, const ShadowCheck& s);

}  // namespace raygrade
