// The changes a new bank makes to one submission's grade, paired by problem id.
#include "grading/regrade.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

#include "grading/outputs.h"

namespace raygrade {
namespace {

std::string mistake_ids(const GradeResult& r) {
  std::string out;
  for (const auto& m : r.mistakes) out += (out.empty() ? "" : ", ") + m.id;
  return out.empty() ? "none" : out;
}

// What changed in one problem's grade: empty when nothing did.
std::string difference(const GradeResult& before, const GradeResult& after) {
  if (result_json(before) == result_json(after)) return "";
  std::vector<std::string> what;
  if (before.score != after.score)
    what.push_back(
        fmt::format("points {} → {}", format_points(before.score), format_points(after.score)));
  if (before.max_score != after.max_score)
    what.push_back(fmt::format("points available {} → {}", format_points(before.max_score),
                               format_points(after.max_score)));
  if (mistake_ids(before) != mistake_ids(after))
    what.push_back(fmt::format("mistakes {} → {}", mistake_ids(before), mistake_ids(after)));
  if (what.empty()) what.emplace_back("feedback");
  return fmt::format("{}", fmt::join(what, "; "));
}

}  // namespace

std::vector<GradeChange> grade_changes(const std::vector<GradeResult>& before,
                                       const std::vector<GradeResult>& after) {
  // The old grades of each id, in order of occurrence, each taken once.
  std::map<std::string, std::vector<std::size_t>> old_of;
  for (std::size_t k = before.size(); k-- > 0;) old_of[before[k].problem_id].push_back(k);
  std::vector<bool> paired(before.size(), false);
  std::vector<GradeChange> changes;
  for (const auto& a : after) {
    auto it = old_of.find(a.problem_id);
    if (it == old_of.end() || it->second.empty()) {
      changes.push_back(
          {a.problem_id, fmt::format("added ({} of {} points)", format_points(a.score),
                                     format_points(a.max_score))});
      continue;
    }
    std::size_t k = it->second.back();
    it->second.pop_back();
    paired[k] = true;
    std::string d = difference(before[k], a);
    if (!d.empty()) changes.push_back({a.problem_id, std::move(d)});
  }
  for (std::size_t k = 0; k < before.size(); ++k)
    if (!paired[k])
      changes.push_back({before[k].problem_id, fmt::format("removed (was {} of {} points)",
                                                           format_points(before[k].score),
                                                           format_points(before[k].max_score))});
  return changes;
}

}  // namespace raygrade
