// The parts of every kind's answer: what each asks for, its default points and how it is
// compared, as each kind declares them (problems/kind.h). Graders take their points from here,
// and docs/grading.md lists the same table.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "problems/kind.h"

namespace raygrade {

// The parts of a kind ("reflect"). For `derive` the parts are the quantities the problem
// names; for `ray-tree` they depend on what it asks (see docs/grading.md).
const std::vector<PartSpec>& kind_parts(std::string_view kind);

// The part named `name` of `kind`, or nullptr.
const PartSpec* find_part(std::string_view kind, std::string_view name);

// The default points of the named parts of `kind`, in the table's order.
std::vector<std::pair<std::string, double>> default_points(std::string_view kind,
                                                           const std::vector<std::string>& names);

}  // namespace raygrade
