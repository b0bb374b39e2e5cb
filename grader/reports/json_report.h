// JSON rendering of derivations: the steps as data.
#pragma once

#include <nlohmann/json.hpp>

#include "problems/problem.h"
#include "reports/solution.h"

namespace raygrade {

nlohmann::json value_json(const Value& v);
nlohmann::json derivation_json(const Derivation& d, const NumberFormat& numbers);
nlohmann::json parts_json(const std::vector<SolutionPart>& parts, const NumberFormat& numbers);
nlohmann::json diagnostic_json(const Diagnostic& d);

// A whole worked solution as data: the problem, its answer, every method's parts, the steps
// with their formulas (LaTeX and text), values, exact forms and notes, and the conclusion.
nlohmann::json solution_json(const Solution& solution);

// The number format a problem asks for, with an optional override of the decimals.
NumberFormat number_format_for(const Problem& p, int decimals_override = -1);

}  // namespace raygrade
