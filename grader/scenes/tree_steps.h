// The worked solution of a ray tree: the tree drawn, the effects simulated and skipped with
// the number of rays of each kind, each node's steps, and the answer.
#pragma once

#include <vector>

#include "problems/problem.h"
#include "scenes/trace.h"

namespace raygrade {

// Every part: the overview (with the tree drawn), one part per node, then the answer.
std::vector<SolutionPart> tree_parts(const RayTree& tree, const Scene& scene,
                                     const Overrides* overrides = nullptr);

// The steps of one node: the nearest hit, its lights and terms, its secondary rays.
Derivation node_steps(const RayTree& tree, const Scene& scene, const TreeNode& node,
                      const Overrides* overrides = nullptr);

// The answer in words: which points need all three Phong terms, which only the ambient one
// and why.
Derivation tree_answer(const RayTree& tree, const Scene& scene);

// A node's heading: "I2: reflection ray from I1".
std::string node_heading(const RayTree& tree, const TreeNode& node);

}  // namespace raygrade
