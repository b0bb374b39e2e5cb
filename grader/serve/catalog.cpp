// The assignments a server offers, and grading one submission to one of them.
#include "serve/catalog.h"

#include <algorithm>
#include <filesystem>

#include "assignments/feedback.h"
#include "grading/outputs.h"

namespace raygrade::serve {

double CatalogEntry::points() const {
  double total = 0;
  for (std::size_t i = 0; i < spec.problems.size() && i < bank.problems.size(); ++i) {
    const AssignmentProblem& ap = spec.problems[i];
    total += ap.points ? *ap.points : Grader(*bank.problems[i]).max_score();
  }
  return total;
}

Catalog::Catalog(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  }
  if (ec) {
    errors_.push_back(Diagnostic{folder, "", 0, 0, Severity::kError,
                                 "cannot read the assignments folder: " + ec.message(),
                                 "unreadable"});
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    try {
      if (!is_assignment_file(f.string())) continue;
      auto entry = std::make_unique<CatalogEntry>();
      entry->name = f.filename().string();
      entry->spec = load_assignment(f.string());
      entry->bank = load_assignment_bank(entry->spec);
      if (entry->bank.problems.size() != entry->spec.problems.size()) {
        errors_.insert(errors_.end(), entry->bank.errors.begin(), entry->bank.errors.end());
        continue;
      }
      AssignmentGradeOptions options;
      options.feedback = FeedbackPolicy::kFull;
      entry->grader =
          std::make_unique<AssignmentGrader>(entry->spec, entry->bank.problems, options);
      entries_.push_back(std::move(entry));
    } catch (const Error& e) {
      errors_.push_back(e.diagnostic());
    }
  }
}

const CatalogEntry* Catalog::find(const std::string& name) const {
  for (const auto& e : entries_)
    if (e->name == name) return e.get();
  return nullptr;
}

SubmissionGrade grade_answers(const CatalogEntry& entry, const StudentIdentity& student,
                              const nlohmann::json& answers, std::int64_t now) {
  nlohmann::json submission = {{"answers", answers}};
  // The name diagnostics show: no file of the server's disk.
  return entry.grader->grade_handed_in("answers.json", submission.dump(), now, student,
                                       "the LTI launch");
}

nlohmann::json feedback_at(const CatalogEntry& entry, SubmissionGrade full, std::int64_t now) {
  for (auto& r : full.results) {
    for (const auto& ap : entry.spec.problems)
      if (ap.id == r.problem_id) apply_feedback_policy(r, entry.spec.policy(ap, now));
  }
  nlohmann::json j = submission_json(full);
  j.erase("file");
  return j;
}

}  // namespace raygrade::serve
