// Blackboard: the Grade Center's offline grade upload, as raygrade's gradebook layout
// csv-blackboard (docs/assignments.md, "Gradebooks").
#pragma once

#include <string_view>

#include "assignments/platforms/platform.h"

namespace raygrade {

struct Blackboard {
  static constexpr std::string_view kName = "blackboard";
  static constexpr std::string_view kTitle = "Blackboard";
  static GradebookLayout gradebook();
};

}  // namespace raygrade
