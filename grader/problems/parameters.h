// Parameters: the numbers of a problem that change from student to student. A problem declares
// them ({"r": {"integer": [1, 4], "default": 2}}) and uses them in its numbers ("=r", "=2*r + 1")
// and in its text ("radius {r}"); a set of values turns it into a plain problem.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "json/cursor.h"
#include "sampling/prng.h"

namespace raygrade {

// The values of a problem's parameters: a number, or a vector [x, y, z] drawn from choices.
using ParameterValues = std::map<std::string, nlohmann::json>;

// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct Parameter {
  enum class Domain { kInteger, kRange, kChoices };
  std::string name;
  Domain domain = Domain::kInteger;
  double lo = 0, hi = 0, step = 1;  // kInteger and kRange: lo, lo + step, ..., hi
  int step_decimals = 0;            // kRange: the decimals of the step, to round the draws
  std::vector<nlohmann::json> choices;
  std::vector<nlohmann::json> exclude;
  nlohmann::json default_value;

  // How many values the domain holds before exclusions.
  std::uint64_t size() const;
  // The i-th value of the domain (i < size()).
  nlohmann::json value(std::uint64_t i) const;
};

// A requirement on a variant's answer: every number under the named answer keys (default "t")
// has at most `decimals` decimals.
struct NiceNumbers {
  int decimals = 0;
  std::vector<std::string> fields = {"t"};
};

struct ParameterSet {
  std::vector<Parameter> parameters;
  std::optional<NiceNumbers> nice;

  bool empty() const { return parameters.empty(); }
  ParameterValues defaults() const;
  // One value per parameter, drawn in the order declared; excluded values are drawn again.
  ParameterValues draw(Prng& rng) const;
};

// Reads the "parameters" (and "nice_numbers") of a problem object. Every parameter must be
// used somewhere in the problem, every use must name known parameters, and every default must
// lie in its domain; faults throw Error at their JSON path.
ParameterSet read_parameters(const Cursor& problem);

// The plain problem for a set of values: every string "=expression" replaced by its value,
// every "{expression}" in the title and statement by its value as text ("{{" and "}}" are
// braces), and the keys "parameters" and "nice_numbers" removed. Throws Error at the JSON path
// of an expression that does not evaluate to a finite number.
nlohmann::json instantiate(const Cursor& problem, const ParameterSet& set,
                           const ParameterValues& values);

// A title or statement split at its "{expression}"s, in order: the text between them (with
// "{{" and "}}" read as braces) and the expressions (without their braces). Throws Error at
// `at` when a brace is unmatched.
struct TextPiece {
  bool expression = false;
  std::string text;
};
std::vector<TextPiece> split_text(const std::string& text, const Cursor& at);

// One expression of a text ("r", "2*r + 1", or a vector parameter's name) for a set of values:
// a number, or the vector [x, y, z]. Throws Error at `at` when it does not read or evaluate.
nlohmann::json evaluate_expression(std::string_view expr, const ParameterSet& set,
                                   const ParameterValues& values, const Cursor& at);

// Whether every number under the answer's `fields` keys has at most `decimals` decimals.
bool has_nice_numbers(const nlohmann::json& answer, const NiceNumbers& nice);

// A value as a statement prints it: 2, 0.25, -1.5, (0, 0, 1).
std::string parameter_text(const nlohmann::json& value);

}  // namespace raygrade
