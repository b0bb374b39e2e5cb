// The answer form of a problem: one labelled input per part it asks for, as data that the
// handout page turns into inputs and back into an answer in the submission format.
#pragma once

#include <nlohmann/json.hpp>

#include "problems/problem.h"

namespace raygrade {

// {"fields": [...]}, each field {"type", "key", "label", ...}; types: number, vector, yesno,
// choice, set, formula, hits (rows of t, point, normal ...), rows (one row per named item),
// tree (a ray tree built point by point). No input asks for JSON. Nothing in it depends on
// the answer: the same form for a hit and a miss.
// Only the parts that carry points are asked: a part worth 0 points has no input.
nlohmann::json answer_form(const Problem& p);

// Every input the kind's form can have, asked or not.
nlohmann::json every_input(const Problem& p);

// The same answer with every input left blank: the skeleton of answers-template.json, with ""
// for every number (a blank is a part not given).
nlohmann::json blank_answer(const nlohmann::json& form);

}  // namespace raygrade
