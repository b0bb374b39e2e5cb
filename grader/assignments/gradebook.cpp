// The gradebook of a class.
#include "assignments/gradebook.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

#include "assignments/variants.h"
#include "core/escape.h"
#include "grading/outputs.h"

namespace raygrade {

std::optional<PickPolicy> parse_pick_policy(std::string_view name) {
  if (name == "latest") return PickPolicy::kLatest;
  if (name == "best") return PickPolicy::kBest;
  if (name == "first") return PickPolicy::kFirst;
  return std::nullopt;
}

RosterGradebook::RosterGradebook(const std::vector<StudentIdentity>& roster,
                                 const std::vector<std::string>& problem_ids, PickPolicy pick)
    : roster_(roster), problem_ids_(problem_ids), pick_(pick), handed_(roster.size()) {}

bool RosterGradebook::add(const SubmissionGrade& g) {
  std::size_t row = roster_.size();
  if (!g.identity.empty()) {
    for (std::size_t i = 0; i < roster_.size() && row == roster_.size(); ++i) {
      if (student_key(roster_[i]) == student_key(g.identity)) row = i;
    }
  } else if (!g.gradable && !g.claimed.id.empty()) {
    // Rejected before it was tied to a student (its fields disagree, say): shown on the row of
    // the id it gives, which earns nothing by it.
    for (std::size_t i = 0; i < roster_.size() && row == roster_.size(); ++i) {
      if (roster_[i].id == trimmed(g.claimed.id)) row = i;
    }
  }
  if (row == roster_.size()) return false;
  Handed h;
  h.file = g.file;
  h.submitted = g.submitted;
  h.file_time = g.file_time;
  h.gradable = g.gradable;
  if (g.fault) h.fault = g.fault->message;
  h.score = g.score;
  h.max_score = g.max_score;
  std::map<std::string_view, double> by_id;
  for (const auto& r : g.results) by_id[r.problem_id] = r.answered ? r.score : 0.0;
  for (const auto& id : problem_ids_) {
    auto it = by_id.find(id);
    h.points.push_back(it == by_id.end() ? 0.0 : it->second);
  }
  handed_[row].push_back(std::move(h));
  return true;
}

const RosterGradebook::Handed* RosterGradebook::chosen(const std::vector<Handed>& handed) const {
  const Handed* best = nullptr;
  // When: the submission's own time where it gives one, then the file's, then its name.
  auto when = [](const Handed& h) {
    return std::make_tuple(h.submitted.value_or(h.file_time), h.file_time, h.file);
  };
  for (const auto& h : handed) {
    if (!h.gradable) continue;
    bool better = !best;
    if (best) {
      switch (pick_) {
        case PickPolicy::kLatest: better = when(h) > when(*best); break;
        case PickPolicy::kFirst: better = when(h) < when(*best); break;
        case PickPolicy::kBest:
          better = h.score > best->score || (h.score == best->score && when(h) > when(*best));
          break;
      }
    }
    if (better) best = &h;
  }
  return best;
}

std::string RosterGradebook::status(std::size_t student) const {
  const auto& handed = handed_[student];
  if (handed.empty()) return "no submission";
  const Handed* pick = chosen(handed);
  if (!pick) return "rejected: " + printable(handed.back().fault);
  if (handed.size() == 1) return "graded";
  static constexpr const char* kWhy[] = {"latest", "best", "first"};
  std::string others;
  for (const auto& h : handed) {
    if (&h == pick) continue;
    others +=
        fmt::format("{}{}{}", others.empty() ? "" : ", ", h.file, h.gradable ? "" : " (rejected)");
  }
  return fmt::format("graded: {} of {} submissions, {}; not counted: {}",
                     kWhy[static_cast<int>(pick_)], handed.size(), pick->file, others);
}

std::vector<std::string> RosterGradebook::choices() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    if (handed_[i].size() > 1)
      out.push_back(fmt::format("student '{}': {}", roster_[i].id, status(i)));
  }
  return out;
}

std::optional<double> RosterGradebook::max_score() const {
  // Every student's maximum is the assignment's, whichever variant they have.
  for (const auto& handed : handed_) {
    if (const Handed* pick = chosen(handed)) return pick->max_score;
  }
  return std::nullopt;
}

bool is_column_id(std::string_view id) {
  return !id.empty() &&
         std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; });
}

ClassRows RosterGradebook::class_rows() const {
  ClassRows book;
  book.points = max_score();
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    const Handed* pick = chosen(handed_[i]);
    book.rows.push_back({roster_[i], i < platform_ids_.size() ? platform_ids_[i] : std::string(),
                         pick ? pick->score : 0.0});
  }
  return book;
}

std::string RosterGradebook::csv() const {
  std::optional<double> max_score = this->max_score();
  std::string s = gradebook_csv_header(problem_ids_);
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    const StudentIdentity& who = roster_[i];
    const Handed* pick = chosen(handed_[i]);
    // The file that counts; for a student whose every file was rejected, the last of them.
    std::string file = pick ? pick->file : handed_[i].empty() ? "" : handed_[i].back().file;
    s += csv_cell(who.name.empty() ? who.id : who.name) + "," + csv_cell(who.id) + "," +
         csv_cell(who.email) + "," + csv_cell(file);
    for (std::size_t p = 0; p < problem_ids_.size(); ++p)
      s += "," + format_points(pick ? pick->points[p] : 0.0);
    s += fmt::format(",{},{},{}\n", format_points(pick ? pick->score : 0.0),
                     max_score ? format_points(*max_score) : std::string(), csv_cell(status(i)));
  }
  return s;
}

}  // namespace raygrade
