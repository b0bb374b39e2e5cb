// A class roster: the students an assignment's handouts are written for, read from CSV.
#pragma once

#include <string>
#include <vector>

#include "grading/submission.h"

namespace raygrade {

// Reads a roster: a CSV file whose first line names its columns, among them "id" (required),
// "name" and "email" (any order; other columns are errors, so that a misspelt header is seen).
// Cells may be quoted ("Lovelace, Ada"). Throws Error naming the file, line and column.
std::vector<StudentIdentity> load_roster(const std::string& path);

// The roster entry a submission's student matches (by id, else email, else name), or nullptr.
const StudentIdentity* find_on_roster(const std::vector<StudentIdentity>& roster,
                                      const StudentIdentity& who);

}  // namespace raygrade
