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

struct ConditioningInput {
  std::string relative;  // its JSON pointer inside the problem
  std::string literal;   // as printed
  double x = 0;
  double h = 0;  // half a unit in its last printed digit
};

struct Finding {
  double amplification = 0;  // over kMaxAmplification, or infinite, when it is a finding
  std::string relative;      // the input that moved (the first of a group)
  std::string message;
};

class Conditioning {
 public:
  Conditioning(const Problem& p, const nlohmann::json& reference, bool exact_boundary)
      : p_(p),
        reference_(reference),
        outcome_(answer_outcome(reference)),
        scale_(std::max(1.0, answer_magnitude(reference))),
        exact_boundary_(exact_boundary) {}

  std::vector<ConditioningInput> inputs;

  // The problem solved with the inputs `members` moved by half a unit each, in direction
  // `sign` (alternating within a group, so that moving the ray and the object together does
  // not cancel out).
  Finding moved(const std::vector<std::size_t>& members, double sign) const {
    Finding f;
    const ConditioningInput& first = inputs[members.front()];
    f.relative = first.relative;
    auto file = std::make_shared<SourceFile>();
    file->name = p_.file;
    file->root = p_.source;
    double relative_move = 0;
    for (std::size_t k = 0; k < members.size(); ++k) {
      const ConditioningInput& in = inputs[members[k]];
      double s = k % 2 == 0 ? sign : -sign;
      file->root[nlohmann::json::json_pointer(in.relative)] = in.x + s * in.h;
      relative_move = std::max(relative_move, in.h / std::max(1.0, std::abs(in.x)));
    }
    double moved_to = first.x + sign * first.h;
    std::string what =
        members.size() == 1
            ? fmt::format("moving {} from {} to {} (half a unit in its last printed digit)",
                          first.relative, first.literal,
                          format_number(moved_to, NumberFormat{12, -1}))
            : fmt::format(
                  "moving {} inputs from {} on together (half a unit in their last "
                  "printed digits)",
                  members.size(), first.relative);
    try {
      Problem q = read_problem(Cursor(file));
      nlohmann::json answer = q.task->answer();
      if (answer_outcome(answer) != outcome_) {
        // A designed tangent or edge case changes under any move; the boundary probe has
        // judged it already.
        if (exact_boundary_) return f;
        f.amplification = kInfinity;
        f.message = fmt::format("ill-conditioned: {} changes the answer from {} to {}", what,
                                describe_answer(reference_), describe_answer(answer));
      } else {
        double change = answer_difference(answer, reference_) / scale_;
        f.amplification = change / relative_move;
        if (f.amplification <= kMaxAmplification) return f;
        f.message = fmt::format(
            "ill-conditioned: {} moves the answer by {}, {} times as much relative to its size: "
            "{} instead of {}",
            what, format_number(answer_difference(answer, reference_)),
            format_number(std::round(f.amplification)), describe_answer(answer),
            describe_answer(reference_));
      }
    } catch (const Error& e) {
      f.amplification = kInfinity;
      f.message = fmt::format("ill-conditioned: {} makes the problem invalid: {}", what,
                              e.diagnostic().message);
    }
    return f;
  }

  // The worse of the two directions.
  Finding worse_direction(const std::vector<std::size_t>& members) const {
    Finding a = moved(members, -1), b = moved(members, +1);
    return b.amplification > a.amplification ? b : a;
  }

 private:
  const Problem& p_;
  const nlohmann::json& reference_;
  std::string outcome_;
  double scale_;
  bool exact_boundary_;
};

bool is_finding(const Finding& f) { return f.amplification > kMaxAmplification; }

}  // namespace

std::vector<std::vector<std::size_t>> conditioning_groups(std::size_t inputs) {
  std::size_t n = std::min(inputs, kConditioningGroups);
  std::vector<std::vector<std::size_t>> groups(n);
  for (std::size_t i = 0; i < inputs; ++i) groups[i % n].push_back(i);
  return groups;
}

std::vector<Diagnostic> check_conditioning(const Problem& p, const nlohmann::json& reference,
                                           const NumberLiterals& literals, bool exact_boundary) {
  const KindEntry* entry = find_kind(p.kind);
  if (!entry) return {};
  Conditioning c(p, reference, exact_boundary);
  for (const auto& key : entry->keys) {
    std::string prefix = p.path + "/" + key;
    for (auto it = literals.lower_bound(prefix); it != literals.end(); ++it) {
      if (it->first.compare(0, prefix.size(), prefix) != 0) break;
      if (it->first.size() > prefix.size() && it->first[prefix.size()] != '/') continue;
      if (significant_digits(it->second) < kMinRoundedDigits) continue;
      ConditioningInput in;
      in.relative = it->first.substr(p.path.size());
      in.literal = it->second;
      in.x = p.source[nlohmann::json::json_pointer(in.relative)].get<double>();
      in.h = half_unit(it->second);
      c.inputs.push_back(std::move(in));
    }
  }
  // The worst group, then the worse half of it until one input is left (or neither half
  // alone moves the answer too far: the group's finding stands).
  std::optional<Finding> worst;
  std::vector<std::size_t> culprit;
  for (const auto& group : conditioning_groups(c.inputs.size())) {
    Finding f = c.worse_direction(group);
    if (is_finding(f) && (!worst || f.amplification > worst->amplification)) {
      worst = f;
      culprit = group;
    }
  }
  if (!worst) return {};
  while (culprit.size() > 1) {
    auto half = static_cast<std::ptrdiff_t>(culprit.size() / 2);
    std::vector<std::size_t> a(culprit.begin(), culprit.begin() + half);
    std::vector<std::size_t> b(culprit.begin() + half, culprit.end());
    Finding fa = c.worse_direction(a), fb = c.worse_direction(b);
    bool take_b = fb.amplification > fa.amplification;
    const Finding& f = take_b ? fb : fa;
    if (!is_finding(f)) break;
    worst = f;
    culprit = take_b ? b : a;
  }
  return {
      problem_diagnostic(p, worst->relative, Severity::kError, worst->message, "ill-conditioned")};
}

}  // namespace raygrade
