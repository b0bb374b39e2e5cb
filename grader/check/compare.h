// Comparing answers as JSON: a stated answer with the reference, and two reference answers
// with each other (for the conditioning check).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.h"

namespace raygrade {

// One difference between a stated answer and the reference, at a JSON pointer relative to
// the stated answer ("/hits/0/t").
struct Mismatch {
  std::string path;
  std::string message;
  std::string code;  // "wrong-expected", "unknown-key" or "type"
};

// How far a stated number may lie from the reference: the larger of an absolute bound and a
// relative one.
struct CompareTolerance {
  double absolute = 0;
  double relative = 0;
  double at(double reference) const;
};

// The slack every comparison allows beyond the tolerance: double rounding in the reference
// (about 1e-16 relative) magnified by the few operations of a solve, far below any digit an
// instructor prints.
constexpr double kRoundingSlack = 1e-9;

// Compares every part `stated` gives with the same part of `reference`; parts the stated
// answer leaves out are not compared. `printed_half_unit(path)` returns half a unit in the
// last digit the stated number at `path` is printed with (0 for an integer literal): a stated
// 7.2679 accepts a reference in [7.26785, 7.26795].
std::vector<Mismatch> compare_stated(
    const nlohmann::json& stated, const nlohmann::json& reference,
    const CompareTolerance& tolerance,
    const std::function<double(const std::string&)>& printed_half_unit);

// The shape of an answer with its numbers blanked out: two answers with the same outcome
// (number of hits, object hit, contained or not) have the same outcome string.
std::string answer_outcome(const nlohmann::json& answer);

// The largest difference between corresponding numbers of two answers of the same outcome,
// and the largest magnitude of a number in an answer.
double answer_difference(const nlohmann::json& a, const nlohmann::json& b);
double answer_magnitude(const nlohmann::json& answer);

// "2 hits (t = 1, 3)", "no hit", "sphere 3, t = 7.268": an answer in a few words.
std::string describe_answer(const nlohmann::json& answer);

}  // namespace raygrade
