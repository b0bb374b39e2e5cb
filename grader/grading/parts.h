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

// How the graders compare one value of a kind's answer: the rule of its part, and the field
// whose tolerance applies. `keys` are the object keys on the way to the value ({"hits",
// "point"}, {"ray", "direction"}, {"reflected_direction"}); `vector`: three numbers. A value
// named as a part ("point", "normal" of a hit) takes that part's rule and tolerance; one inside
// a part (a camera's ray: "origin" a point, "direction" by the part's rule) takes its part's
// tolerance; a unit direction given for a direction is compared as the direction.
struct ValueRule {
  Comparison compare = Comparison::kScalar;
  std::string tolerance_field;
};
ValueRule value_rule(std::string_view kind, const std::vector<std::string>& keys, bool vector);

}  // namespace raygrade
