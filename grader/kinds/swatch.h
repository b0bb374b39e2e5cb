// Swatches: a figure showing colours as filled squares beside their numbers, for the worked
// solutions of problems whose intensities are colours. The square is the colour clamped to
// [0, 1] per channel, for display only; the number beside it is the answer, unclamped.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "math/vec3.h"
#include "problems/problem.h"

namespace raygrade {

// One swatch per entry, in order: {"I", [1.9, 1.9, 1.9]} is drawn as a white square and
// "I = [1.9, 1.9, 1.9]".
Figure swatch_figure(const std::vector<std::pair<std::string, Vec3d>>& colours);

}  // namespace raygrade
