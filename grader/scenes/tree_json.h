// The ray tree as answer data: nodes with their rays, hits, lights and Phong terms, and the
// answer to "which points need all three terms" in the seed's own words.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenes/trace.h"

namespace raygrade {

// The Phong terms that apply at a hit node: "ambient", then "diffuse" and "specular" when a
// light reaches it.
std::vector<std::string> node_terms(const TreeNode& node);

// A hit node is in shadow when the scene has lights, none of them reaches it, and an object
// blocks at least one: a point whose surface faces away from every light (N·L ≤ 0) is not in
// shadow, it faces away (self-shadowed, the "attached shadow" of some texts).
bool in_shadow(const TreeNode& node);
bool faces_away(const TreeNode& node);
// A point that faces away from every light that could reach it, where a shadow ray cast anyway
// toward one of them would meet another object: both readings hold, "faces away" and "in
// shadow" (some courses cast the ray first), and grading accepts either unless the course's
// convention picks one.
bool shadow_either(const TreeNode& node);

// What the reference says of a hit node's shadow under the tree's convention (its
// facing_away): the one place that decides it, for the answer, the worked solution, the
// sketches and grading alike.
struct ShadowReading {
  bool in_shadow = false;   // the reference's verdict
  bool either = false;      // "not in shadow" is right as well (the convention leaves it open)
  bool faces_away = false;  // no light reaches it and no shadow ray is blocked: N·L ≤ 0
};
ShadowReading shadow_reading(const RayTree& tree, const TreeNode& node);

// The objects that block a node's lights, by name, nearest first for each light; at a point in
// shadow by the convention alone, those its shadow rays meet although it faces away.
std::vector<std::string> shadow_blockers(const RayTree& tree, const Scene& scene,
                                         const TreeNode& node);

nlohmann::json node_json(const RayTree& tree, const Scene& scene, const TreeNode& node);

// The whole answer of a ray-tree problem: {nodes, all_terms, ambient_only, rays, intensity}.
nlohmann::json tree_json(const RayTree& tree, const Scene& scene);

nlohmann::json counts_json(const RayCounts& c);

}  // namespace raygrade
