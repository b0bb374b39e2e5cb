// Plain-text rendering of worked solutions, for terminals.
#pragma once

#include <string>
#include <vector>

#include "reports/solution.h"

namespace raygrade {

std::string render_text(const Solution& solution);

// The parts of one method, without the sketch.
std::string render_text(const Problem& problem, const std::vector<SolutionPart>& parts,
                        const NumberFormat& numbers);

}  // namespace raygrade
