// The zip a learning platform gives for "download all submissions" (Canvas, Moodle): each file
// tied, by the platform's own file naming, to the roster student who handed it in.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "grading/submission.h"

namespace raygrade {

// What a platform's file naming says of one file of its zip.
struct BulkName {
  std::string platform_id;  // Canvas's user ID, Moodle's participant number
  std::string name;         // the student's name as the platform wrote it
  std::string file;         // the file's own name, as the student uploaded it
};

// What ties a platform's ids to the roster.
struct BulkRoster {
  const std::vector<StudentIdentity>* roster = nullptr;
  std::vector<std::string> canvas_ids;  // per roster student: the roster's "canvas_id" column
  // Moodle's grading worksheet as downloaded (csv_rows), or empty: its "Identifier" column
  // ("Participant 101") and "Email address" tie a participant number to a roster email.
  const std::vector<std::vector<std::string>>* moodle_worksheet = nullptr;
  std::string moodle_worksheet_file;
  // Per roster student, its name as each platform's naming is matched (filled by
  // read_bulk_submissions, once per zip rather than once per file).
  std::vector<std::string> canvas_keys, moodle_keys;
};

// One platform's file naming: one row of bulk_formats().
struct BulkFormat {
  std::string_view title;   // "Canvas"
  std::string_view naming;  // how its files are named, for the message of a file it does not name
  std::optional<BulkName> (*parse)(std::string_view path);
  // The roster student a parsed name is, or nullptr and `problem` says why.
  const StudentIdentity* (*owner)(const BulkName& name, const BulkRoster& roster,
                                  std::string& problem);
};
const std::vector<BulkFormat>& bulk_formats();

// A file of the zip, ready to grade, or the reason it cannot be.
struct BulkSubmission {
  std::string file;  // "<zip>/<path inside the zip>"
  std::string text;
  std::int64_t modified = 0;               // the file's time in the zip
  const StudentIdentity* owner = nullptr;  // the roster student the platform says handed it in
  std::string_view platform;               // "Canvas" or "Moodle"
  std::optional<Diagnostic> fault;         // why this file alone is not graded
  std::optional<StudentIdentity> claimed;  // whom the platform's naming names, for a fault's row
};

// The files of the zip at `path`, each tied to its roster student by one platform's naming,
// chosen for the whole zip: Canvas's when any file follows it (Moodle never writes such a
// name), else Moodle's. A file no platform's naming fits, one whose student is not on the roster,
// one that is not a .json file or one that cannot be unpacked comes back with its fault alone.
// Throws Error naming `path` when it is no zip archive.
std::vector<BulkSubmission> read_bulk_submissions(const std::string& path,
                                                  const BulkRoster& roster);

// Whether `path` is a zip archive by its name (".zip", in any case).
bool is_zip_path(std::string_view path);

}  // namespace raygrade
