// A bank's own named mistakes, matched by the single change of the derivation they name.
#include "grading/bank_mistakes.h"

#include <fmt/format.h>

#include <set>

#include "core/error.h"
#include "grading/mistakes.h"
#include "json/cursor.h"

namespace raygrade {
// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace bank_mistakes_internal {

// "t_hc = √(r² − d²) → t_hc = r² − d²" or "t_hc = r² − d²": the changed step alone.
std::string changed_step(std::string text) {
  constexpr std::string_view kArrow = "→";
  if (auto at = text.rfind(kArrow); at != std::string::npos) text = text.substr(at + kArrow.size());
  auto first = text.find_first_not_of(' ');
  auto last = text.find_last_not_of(' ');
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

}  // namespace bank_mistakes_internal

BankMistakes::BankMistakes(const Problem& problem) {
  auto it = problem.source.find("mistakes");
  if (it == problem.source.end()) return;
  Cursor c(problem.source_file, &*it, problem.path + "/mistakes");
  if (!c.is_array()) c.fail("mistakes is an array of {\"id\", \"message\", \"change\"}", "type");
  std::set<std::string> ids;
  for (const Cursor& m : c.items()) {
    m.allow_only({"id", "message", "change"});
    BankMistake b{m.at("id").string(), m.at("message").string(),
                  bank_mistakes_internal::changed_step(m.at("change").string())};
    if (b.id.empty()) m.at("id").fail("a mistake's id is not empty", "invalid");
    for (const auto& known : mistake_catalogue()) {
      if (known.id == b.id)
        m.at("id").fail(fmt::format("'{}' is a mistake of the catalogue already", b.id),
                        "duplicate");
    }
    if (!ids.insert(b.id).second)
      m.at("id").fail(fmt::format("the mistake '{}' is named twice", b.id), "duplicate");
    if (b.change.find(" = ") == std::string::npos)
      m.at("change").fail(
          "change is a step and its changed formula as report.json writes it (\"t_hc = r² − "
          "d²\")",
          "invalid");
    mistakes_.push_back(std::move(b));
  }
  if (mistakes_.empty()) return;
  try {
    search_ = std::make_unique<ChangeSearch>(problem);
  } catch (const Error&) {
    // A derivation that cannot be worked has no changes to match: nothing is found.
  }
}

void BankMistakes::find(const nlohmann::json& answer, GradeResult& r) const {
  if (!search_ || !r.mistakes.empty() || r.score >= r.max_score) return;
  Discovery d = search_->explain(answer);
  if (d.verdict != Discovery::Verdict::kExplained) return;
  for (const auto& m : mistakes_) {
    for (const auto& c : d.changes) {
      if (c.key() != m.change) continue;
      std::string part;
      for (const auto& p : r.parts)
        if (part.empty() && p.status != PartStatus::kRight) part = p.name;
      r.mistakes.push_back(FoundMistake{m.id, "bank", part, m.message});
      return;
    }
  }
}

}  // namespace raygrade
