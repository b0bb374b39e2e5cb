// The parts of every kind's answer: what each asks for, its default points and how it is
// compared. Graders take their points from here, and docs/grading.md lists the same table.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raygrade {

// How a part is compared with the reference.
enum class Comparison {
  kScalar,         // a number, by the problem's tolerance
  kPoint,          // three numbers, each by the tolerance relative to the point's size
  kDirection,      // any positive multiple of the reference direction
  kUnitDirection,  // the reference direction with length 1
  kHits,           // a set of hits matched regardless of order; [] claims a miss
  kWeights,        // barycentric weights (w_a, w_b, w_c), in the order of the vertices
  kName,           // an object's name (case, spaces, '-' and '_' ignored)
  kFlag,           // true or false
  kNames,          // a set of names (Phong terms)
  kFormula,        // a formula, compared at random points
  kTree,           // the nodes of a ray tree
  kSteps,          // named steps of the derivation, with error carried forward
};

const char* to_string(Comparison c);

struct PartSpec {
  std::string name;
  std::string asks;  // what the part asks for, in words
  double points = 0;
  Comparison compare = Comparison::kScalar;
};

// The parts of a kind ("reflect"). For `derive` the parts are the quantities the problem
// names; for `ray-tree` they depend on what it asks (see docs/grading.md).
const std::vector<PartSpec>& kind_parts(std::string_view kind);

// The part named `name` of `kind`, or nullptr.
const PartSpec* find_part(std::string_view kind, std::string_view name);

// The default points of the named parts of `kind`, in the table's order.
std::vector<std::pair<std::string, double>> default_points(std::string_view kind,
                                                           const std::vector<std::string>& names);

}  // namespace raygrade
