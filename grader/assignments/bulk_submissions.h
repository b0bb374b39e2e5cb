// The zip a learning platform gives for "download all submissions": each file tied, by the
// platform's own file naming (its BulkFormat, platforms/platform.h), to the roster student who
// handed it in.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assignments/gradebook.h"
#include "assignments/roster.h"
#include "core/error.h"
#include "grading/submission.h"

namespace raygrade {

// What a platform's file naming says of one file of its zip.
struct BulkName {
  std::string platform_id;  // the platform's id of the student (a user ID, a participant number)
  std::string name;         // the student's name as the platform wrote it
  std::string file;         // the file's own name, as the student uploaded it
};

// What ties a platform's ids to the roster, for one platform's naming.
struct BulkRoster {
  const std::vector<StudentIdentity>* roster = nullptr;
  // Per roster student: its cell of the roster's column of the platform's user ids
  // (BulkFormat::roster_column), all "" when the roster has none.
  std::vector<std::string> platform_ids;
  // The platform's worksheet (PlatformWorksheet), when one was given; it can tie the platform's
  // ids to roster emails.
  const Worksheet* worksheet = nullptr;
  // Per roster student, its name as the platform's naming is matched (BulkFormat::roster_key;
  // filled by read_bulk_submissions, once per zip rather than once per file).
  std::vector<std::string> name_keys;
};

// One platform's file naming: what a platform declares of its bulk download.
struct BulkFormat {
  std::string_view title;          // the platform's, in sentences
  std::string_view roster_column;  // the platform's roster column (PlatformEntry::roster_column)
  std::string_view naming;  // how its files are named, for the message of a file it does not name
  // No other platform writes a name this naming fits: a zip with any file it fits is this
  // platform's. A zip no such naming claims is the first other platform's of the list.
  bool claims_zip = false;
  std::optional<BulkName> (*parse)(std::string_view path) = nullptr;
  // A roster student's name as this naming writes it, as a key (BulkRoster::name_keys).
  std::string (*roster_key)(const StudentIdentity& s) = nullptr;
  // The roster student a parsed name is, or nullptr and `problem` says why.
  const StudentIdentity* (*owner)(const BulkName& name, const BulkRoster& roster,
                                  std::string& problem) = nullptr;
};

// What read_bulk_submissions ties files to students with: the roster, its platform columns
// (column → per roster student), and the worksheets given, by the platform's title.
struct BulkInput {
  const std::vector<StudentIdentity>* roster = nullptr;
  const RosterColumns* columns = nullptr;
  std::map<std::string_view, const Worksheet*> worksheets;
};

// The one roster entry `matches` accepts, or nullptr with `problem` saying why (none, or more
// than one: `who` is the platform's words for the student).
template <class Match>
const StudentIdentity* only_roster_entry(const std::vector<StudentIdentity>& roster, Match matches,
                                         const std::string& who, std::string& problem) {
  const StudentIdentity* found = nullptr;
  std::string ids;
  for (const auto& s : roster) {
    if (!matches(s)) continue;
    ids += fmt::format("{}'{}'", ids.empty() ? "" : ", ", s.id);
    if (found) {
      problem = fmt::format("{} is more than one roster student ({})", who, ids);
    } else {
      found = &s;
    }
  }
  if (!problem.empty()) return nullptr;
  if (!found) problem = fmt::format("{} is no roster student", who);
  return found;
}

// A file of the zip, ready to grade, or the reason it cannot be.
struct BulkSubmission {
  std::string file;  // "<zip>/<path inside the zip>"
  std::string text;
  std::int64_t modified = 0;               // the file's time in the zip
  const StudentIdentity* owner = nullptr;  // the roster student the platform says handed it in
  std::string_view platform;               // the platform's title
  std::optional<Diagnostic> fault;         // why this file alone is not graded
  std::optional<StudentIdentity> claimed;  // whom the platform's naming names, for a fault's row
};

// The files of the zip at `path`, each tied to its roster student by one platform's naming of
// `formats` (the list's), chosen for the whole zip: the first that claims the zip (claims_zip)
// and fits any file, else the first that claims none. A file that naming does not fit, one whose
// student is not on the roster, one that is not a .json file or one that cannot be unpacked
// comes back with its fault alone. Throws Error naming `path` when it is no zip archive.
std::vector<BulkSubmission> read_bulk_submissions(const std::string& path,
                                                  const std::vector<BulkFormat>& formats,
                                                  const BulkInput& in);

// Whether `path` is a zip archive by its name (".zip", in any case).
bool is_zip_path(std::string_view path);

}  // namespace raygrade
