// Mistakes a bank names for one problem (its "mistakes"): a change to a step of the problem's
// derivation, as `raygrade report` discovers it, promoted by the instructor to a named mistake
// with an id and a message (docs/report.md, "Naming a discovered mistake").
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grading/discover.h"
#include "grading/result.h"
#include "problems/problem.h"

namespace raygrade {

struct BankMistake {
  std::string id;       // new to the catalogue ("sqrt-forgotten")
  std::string message;  // what the student reads
  std::string change;   // the changed step, as the report writes it ("t_hc = r² − d²")
};

// Finds a problem's own named mistakes in wrong answers that nothing else explains.
class BankMistakes {
 public:
  // Reads the problem's "mistakes" (an array of {"id", "message", "change"}); throws Error at
  // the JSON path of a fault (an id of the catalogue, an id twice, a key it does not use).
  // Nothing to find when the problem names none.
  explicit BankMistakes(const Problem& problem);
  bool empty() const { return mistakes_.empty(); }

  // When no mistake was found in `r` and it is below full marks: the first of the problem's
  // mistakes whose change explains `answer`, added to `r.mistakes`.
  void find(const nlohmann::json& answer, GradeResult& r) const;

 private:
  std::vector<BankMistake> mistakes_;
  std::unique_ptr<ChangeSearch> search_;
};

}  // namespace raygrade
