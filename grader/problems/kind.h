// What a kind of problem declares, as one row of the table of kinds (kinds/table.cpp): its
// name, the keys it reads, its parts, the grader that compares them, the student's answer form
// and its case of the problem schema. Everything that differs by kind is derived from here.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace raygrade {

class Cursor;
class Task;
struct Problem;

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
  kRows,           // one row per item (a light), each value given in a row right
};

const char* to_string(Comparison c);

struct PartSpec {
  std::string name;
  std::string asks;  // what the part asks for, in words
  double points = 0;
  Comparison compare = Comparison::kScalar;
  // For a direction that any positive multiple answers: why the reference has the length it
  // has ("r = d − 2(d·n̂)n̂ keeps the length of d"), said to a student whose length is neither 1
  // nor the reference's; empty: nothing is said.
  std::string length_note = {};
  // Other keys of an answer that answer this part when it is not given under its own name
  // (a unit direction is a direction).
  std::vector<std::string> aliases = {};
  // A flag part whose `true` answers this part as having no value (refract's
  // total_internal_reflection: then there is no refracted direction).
  std::string absent_by_flag = {};
  // When the reference has no value for the part: zero (0 or [0, 0, 0]) answers it too, besides
  // null and false (shade's specular term when k_s = 0).
  bool zero_when_absent = false;
  // When the reference has no value for the part, the answer may leave it out (shade's colour
  // without a material colour).
  bool optional_when_absent = false;
  // Why the reference has no value for the part, told to a student who gives one, from the
  // reference answer (`number` prints a number as the grader does); unset: "This problem has
  // no <name>."
  std::function<std::string(const nlohmann::json& reference,
                            const std::function<std::string(double)>& number)>
      why_absent = {};
  // For a flag: why the reference says what it says, told to a student who says the other
  // (`reference_flag` is the right value); unset: "<name> is true." or "... false.".
  std::function<std::string(const nlohmann::json& reference, bool reference_flag,
                            const std::function<std::string(double)>& number)>
      why_flag = {};
};

// The graders of grading/: the fields grader compares each part by its Comparison; the others
// grade what a field-by-field comparison cannot (sets of hits, a camera's ray with its steps,
// formulas, a ray tree).
enum class GraderFamily { kFields, kHits, kCamera, kFormula, kRayTree };

// One row of the table of kinds.
struct KindEntry {
  std::string_view name;
  std::string_view summary;
  std::vector<std::string> keys;  // the problem keys this kind reads beside the common ones
  std::unique_ptr<Task> (*read)(const Cursor& problem);
  std::vector<PartSpec> parts;  // for `derive`, one row stands for each quantity found
  GraderFamily grader = GraderFamily::kFields;
  // Every input of the student's answer form ({"fields": [...]}, docs/assignments.md).
  nlohmann::json (*answer_form)(const Problem& problem);
  // The kind's case of the problem schema: its "required" and "properties".
  std::string_view schema;
};

// The table of kinds, in the order of kinds/table.cpp; the first is the kind of a problem that
// names none.
const std::vector<KindEntry>& kind_table();

// The kind named `name`, or nullptr.
const KindEntry* find_kind(std::string_view name);

}  // namespace raygrade
