// The conditioning check: does the answer hold when each printed input moves by half a unit
// in its last printed digit?
#include <algorithm>
#include <cmath>

#include "check/problem_checks.h"
#include "derivation/number_format.h"

namespace raygrade {
namespace {

// An answer may move this many times more (relative to its size) than the input that moved
// it (relative to its size) before the problem counts as ill-conditioned. A well-posed
// exercise moves by about as much as its inputs (a factor near 1, up to ten for long lever
// arms); near a tangent the roots move with the square root of the input's error and the
// factor runs into the hundreds and thousands.
constexpr double kMaxAmplification = 100;

// Literals printed with fewer significant digits are exact values: exercises are written
// with 0.8, 1.5 and 0.25 meaning exactly that, and a student computes with them as printed.
// From three digits on (0.333, 1.414, 7.2679) a literal may be a rounded value, and half a
// unit in its last digit is the uncertainty it carries.
constexpr int kMinRoundedDigits = 3;

// The problem object with the number at `relative` (a JSON pointer inside it) replaced.
std::shared_ptr<const SourceFile> with_input(const Problem& p, const std::string& relative,
                                             double value) {
  auto file = std::make_shared<SourceFile>();
  file->name = p.file;
  file->root = p.source;
  file->root[nlohmann::json::json_pointer(relative)] = value;
  return file;
}

struct Finding {
  double amplification = 0;
  std::string relative;  // the input that moved
  std::string message;
};

}  // namespace

std::vector<Diagnostic> check_conditioning(const Problem& p, const nlohmann::json& reference,
                                           const NumberLiterals& literals, bool exact_boundary) {
  const KindEntry* entry = nullptr;
  for (const auto& k : kind_table()) {
    if (k.name == p.kind) entry = &k;
  }
  if (!entry) return {};
  std::string outcome = answer_outcome(reference);
  double scale = std::max(1.0, answer_magnitude(reference));
  std::optional<Finding> worst;
  for (const auto& key : entry->keys) {
    std::string prefix = p.path + "/" + key;
    for (auto it = literals.lower_bound(prefix); it != literals.end(); ++it) {
      if (it->first.compare(0, prefix.size(), prefix) != 0) break;
      if (it->first.size() > prefix.size() && it->first[prefix.size()] != '/') continue;
      if (significant_digits(it->second) < kMinRoundedDigits) continue;
      std::string relative = it->first.substr(p.path.size());
      double x = p.source[nlohmann::json::json_pointer(relative)].get<double>();
      double h = half_unit(it->second);
      for (double moved : {x - h, x + h}) {
        Finding f;
        f.relative = relative;
        try {
          auto file = with_input(p, relative, moved);
          Problem q = read_problem(Cursor(file));
          nlohmann::json answer = q.task->answer();
          if (answer_outcome(answer) != outcome) {
            // A designed tangent or edge case changes under any move; the boundary probe
            // has judged it already.
            if (exact_boundary) continue;
            f.amplification = kInfinity;
            f.message = fmt::format(
                "ill-conditioned: moving {} from {} to {} (half a unit in its last printed "
                "digit) changes the answer from {} to {}",
                relative, it->second, format_number(moved, NumberFormat{12, -1}),
                describe_answer(reference), describe_answer(answer));
          } else {
            double change = answer_difference(answer, reference) / scale;
            f.amplification = change / (h / std::max(1.0, std::abs(x)));
            if (f.amplification <= kMaxAmplification) continue;
            f.message = fmt::format(
                "ill-conditioned: moving {} from {} to {} (half a unit in its last printed "
                "digit) moves the answer by {}, {} times as much relative to its size: {} "
                "instead of {}",
                relative, it->second, format_number(moved, NumberFormat{12, -1}),
                format_number(answer_difference(answer, reference)),
                format_number(std::round(f.amplification)), describe_answer(answer),
                describe_answer(reference));
          }
        } catch (const Error& e) {
          f.amplification = kInfinity;
          f.message = fmt::format(
              "ill-conditioned: moving {} from {} to {} (half a unit in its last printed digit) "
              "makes the problem invalid: {}",
              relative, it->second, format_number(moved, NumberFormat{12, -1}),
              e.diagnostic().message);
        }
        if (!worst || f.amplification > worst->amplification) worst = f;
      }
    }
  }
  if (!worst) return {};
  return {
      problem_diagnostic(p, worst->relative, Severity::kError, worst->message, "ill-conditioned")};
}

}  // namespace raygrade
