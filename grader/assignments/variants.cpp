// Drawing and checking per-student variants.
#include "assignments/variants.h"

#include <fmt/format.h>

#include <algorithm>

#include "check/literals.h"
#include "check/problem_checks.h"
#include "core/escape.h"
#include "sampling/prng.h"

namespace raygrade {
namespace {

void fnv1a(std::uint64_t& h, std::string_view bytes) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  h ^= 0xff;  // a separator no UTF-8 text contains
  h *= 0x100000001b3ULL;
}

// The problem as written, read again (its Task cannot be copied).
Problem reread(const Problem& p) {
  if (p.parameters) return read_problem_variant(p, p.values);
  const nlohmann::json& value = p.path.empty()
                                    ? p.source_file->root
                                    : p.source_file->root.at(nlohmann::json::json_pointer(p.path));
  return read_problem(Cursor(p.source_file, &value, p.path), p.file_conventions);
}

}  // namespace

std::string trimmed(const std::string& s) {
  std::size_t begin = s.find_first_not_of(" \t");
  if (begin == std::string::npos) return {};
  return s.substr(begin, s.find_last_not_of(" \t") + 1 - begin);
}

std::string email_key(const std::string& email) { return ascii_lower(trimmed(email)); }

std::string student_key(const StudentIdentity& s) {
  if (!trimmed(s.id).empty()) return trimmed(s.id);
  if (!trimmed(s.email).empty()) return email_key(s.email);
  return trimmed(s.name);
}

std::uint64_t variant_seed(const std::string& assignment, std::uint64_t seed,
                           const std::string& student, const std::string& problem) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  fnv1a(h, "raygrade variant");
  fnv1a(h, assignment);
  fnv1a(h, std::to_string(seed));
  fnv1a(h, student);
  fnv1a(h, problem);
  return h;
}

std::vector<Diagnostic> variant_findings(const Problem& variant, bool allow_degenerate) {
  // The variant's own text holds its numbers as printed; its pointers are relative to it.
  NumberLiterals literals;
  for (auto& [pointer, literal] : scan_number_literals(variant.source_file->text)) {
    literals[variant.path + pointer] = literal;
  }
  std::vector<Diagnostic> out = problem_findings(variant, literals);
  // A bank's problem may sit on a boundary on purpose (its statement says so); a drawn variant
  // does not, unless the assignment allows it.
  if (!allow_degenerate && probe_boundaries(variant).exact_boundary) {
    out.push_back(problem_diagnostic(
        variant, "/parameters", Severity::kWarning,
        "the ray meets an edge, a vertex, a rim or a tangent exactly: one rounding turns the "
        "answer around",
        "degenerate"));
  }
  if (variant.parameters && variant.parameters->nice &&
      !has_nice_numbers(variant.task->answer(), *variant.parameters->nice)) {
    out.push_back(
        problem_diagnostic(variant, "/nice_numbers", Severity::kError,
                           fmt::format("the answer has numbers with more than {} decimals",
                                       variant.parameters->nice->decimals),
                           "not-nice"));
  }
  return out;
}

Problem draw_variant(const Problem& base, std::uint64_t seed, bool allow_degenerate) {
  if (!base.parameters) return reread(base);
  Prng rng(seed);
  Diagnostic last;
  for (int draw = 0; draw < kMaxVariantDraws; ++draw) {
    ParameterValues values = base.parameters->draw(rng);
    try {
      Problem p = read_problem_variant(base, values);
      auto findings = variant_findings(p, allow_degenerate);
      bool fails = std::any_of(findings.begin(), findings.end(),
                               [](const Diagnostic& d) { return d.severity != Severity::kNote; });
      if (!fails) return p;
      for (const auto& d : findings) {
        if (d.severity != Severity::kNote) last = d;
      }
    } catch (const Error& e) {
      last = e.diagnostic();
    }
  }
  throw Error(Diagnostic{
      base.file, base.path + "/parameters", 0, 0, Severity::kError,
      fmt::format("no usable variant of '{}' in {} draws (the last failed: {}); widen the "
                  "parameters' ranges or loosen nice_numbers",
                  base.id, kMaxVariantDraws, last.message),
      "no-variant"});
}

std::vector<Problem> student_problems(const AssignmentSpec& spec,
                                      const std::vector<const Problem*>& bank_problems,
                                      const std::string& student) {
  std::vector<Problem> out;
  out.reserve(bank_problems.size());
  for (std::size_t i = 0; i < bank_problems.size(); ++i) {
    const Problem& base = *bank_problems[i];
    const AssignmentProblem& ap = spec.problems[i];
    bool vary = spec.per_student && ap.variants && !student.empty() && base.parameters;
    out.push_back(vary ? draw_variant(base, variant_seed(spec.id, spec.seed, student, base.id),
                                      spec.allow_degenerate)
                       : reread(base));
  }
  return out;
}

bool has_per_student_numbers(const AssignmentSpec& spec,
                             const std::vector<const Problem*>& bank_problems) {
  if (!spec.per_student) return false;
  for (std::size_t i = 0; i < bank_problems.size() && i < spec.problems.size(); ++i) {
    const Problem& base = *bank_problems[i];
    if (spec.problems[i].variants && base.parameters && !base.parameters->empty()) return true;
  }
  return false;
}

Bank student_bank(const AssignmentSpec& spec, const std::string& student) {
  AssignmentBank from = load_assignment_bank(spec);
  Bank out;
  out.errors = from.errors;
  if (from.problems.size() != spec.problems.size()) return out;
  out.problems = student_problems(spec, from.problems, student);
  return out;
}

}  // namespace raygrade
