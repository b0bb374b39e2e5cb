// A class roster: the students an assignment's handouts are written for, read from CSV.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "grading/submission.h"

namespace raygrade {

// Reads a roster: a CSV file whose first line names its columns, among them "id" (required),
// "name" and "email" (any order; other columns are errors, so that a misspelt header is seen).
// Cells may be quoted ("Lovelace, Ada"). Throws Error naming the file, line and column.
// The cells of every line of a CSV text (RFC 4180: quoted cells may hold commas, quotes as "",
// and line breaks). Throws Error naming `file` and the line of a quote left open.
std::vector<std::vector<std::string>> csv_rows(const std::string& text, const std::string& file);

// The roster's columns of platforms' user ids: the column's name → each student's cell, in roster
// order ("" where the roster gives none).
using RosterColumns = std::map<std::string, std::vector<std::string>, std::less<>>;

// A roster may also have a column of a platform's user ids, one per platform that reads one
// (PlatformEntry::roster_column, the list's): given `columns`, it receives each of them, one cell
// per student, whether the roster has the column or not ("" where none is given).
std::vector<StudentIdentity> load_roster(const std::string& path, RosterColumns* columns = nullptr);

// The roster entry a submission's student is, and why there is none: every field the
// submission gives (id, email, name) must name the same one entry. A name that two entries
// share names nobody (the candidates are listed); a field that names another entry than the
// others is a mismatch that says which.
struct RosterMatch {
  const StudentIdentity* entry = nullptr;
  std::string problem;  // when there is no entry: what is wrong, for the student to read
  std::string code;     // "not-on-roster", "ambiguous-student" or "student-mismatch"
};
RosterMatch match_on_roster(const std::vector<StudentIdentity>& roster, const StudentIdentity& who);

// The entry of match_on_roster, or nullptr.
const StudentIdentity* find_on_roster(const std::vector<StudentIdentity>& roster,
                                      const StudentIdentity& who);

}  // namespace raygrade
