// What a new bank changes in one submission's grade: the grades of the two banks paired by
// problem id, so that a problem added, removed or moved in the bank is seen as such.
#pragma once

#include <string>
#include <vector>

#include "grading/result.h"

namespace raygrade {

struct GradeChange {
  std::string problem_id;
  std::string what;  // "points 2 → 0; mistakes none → sign", "added (0 of 2 points)", ...
};

// The changes from `before` to `after`, the grades of one submission under the old and the new
// bank: the new bank's problems in its order (a problem it adds is "added"), then the old bank's
// problems the new one lacks ("removed"). An id that occurs more than once on a side is paired
// occurrence by occurrence. Empty when nothing changed.
std::vector<GradeChange> grade_changes(const std::vector<GradeResult>& before,
                                       const std::vector<GradeResult>& after);

}  // namespace raygrade
