// A learning platform as a type: what platforms/platforms.h lists, one line each. The concept
// says what a platform may declare (its export, its results format, its gradebook layout, the
// naming of its bulk download, its worksheet, its metadata of an upload, its roster column, and
// their options); `raygrade export`, `raygrade grade` and their help take every platform from
// the list, and no code outside platforms/ names one (docs/architecture.md, "A platform").
#pragma once

#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assignments/bulk_submissions.h"
#include "assignments/gradebook.h"
#include "assignments/lms_export.h"
#include "grading/outputs.h"

namespace raygrade {

// A platform's gradebook layout: `raygrade grade --format NAME --roster ...` writes the class,
// a row per roster student, as the platform's gradebook import reads it.
struct GradebookLayout {
  std::string_view format;   // the --format name: "csv-" and the platform's name
  std::string_view summary;  // for --help and the docs' table of grade formats
  // The option that gives the platform's id of the grade column, and its help; empty when the
  // layout has none.
  std::string_view column_option;
  std::string_view column_help;
  // What the platform's importer would make of the grade column `title` (and `column_id`, the
  // option's value, "" when not given), before anything is graded.
  ColumnCheck (*check)(const std::string& title, const std::string& column_id);
  // The file: `book`'s rows under the grade column `title`.
  std::string (*write)(const ClassRows& book, const std::string& title,
                       const std::string& column_id);
};

// A platform's own gradebook file, downloaded from it and given back filled in, named by its own
// option of `raygrade grade` (`option`, with --roster): with the platform's gradebook layout
// (--format `GradebookLayout::format`) the file is written with each roster student's grade;
// with --format html --out DIR the feedback pages also go into `feedback_zip`, laid out for
// the platform's bulk feedback upload; and the file ties the platform's bulk download to roster
// students (BulkRoster::worksheet).
struct PlatformWorksheet {
  std::string_view option;
  std::string_view help;
  // The file's rows, read and checked. Throws Error naming the file when it cannot be read or
  // the platform could not read it back.
  std::vector<std::vector<std::string>> (*read)(const std::string& path);
  // The worksheet with each roster student's grade; what was left as it was goes into `notes`.
  std::string (*fill)(const ClassRows& book, const Worksheet& sheet,
                      std::vector<std::string>& notes);
  // The feedback pages as the platform's bulk feedback upload reads them; a page it cannot place
  // is left out and said in `notes`.
  std::vector<ZipEntry> (*feedback)(const Worksheet& sheet,
                                    const std::vector<StudentIdentity>& roster,
                                    const std::vector<StudentPage>& pages,
                                    std::vector<std::string>& notes);
  std::string_view feedback_zip;  // the zip's name in --out
};

// What a platform says of an upload it hands raygrade to grade (an autograder's metadata): the
// accounts that uploaded it, and its due date when the platform gives one.
struct UploadMetadata {
  std::vector<StudentIdentity> users;
  std::optional<std::int64_t> due;  // seconds since 1970 UTC
};

// A platform that runs raygrade on each upload: the option of `raygrade grade` (with
// --assignment) that reads the platform's metadata of the upload; the student a submission names
// must then be an account that uploaded it, and the platform's due date is the one in force.
struct PlatformUploads {
  std::string_view option;
  std::string_view help;
  // Throws Error naming the file and JSON path when the metadata is faulty.
  UploadMetadata (*read)(const std::string& path);
};

// A platform: one row of platform_table(), made from its type by platform_entry.
struct PlatformEntry {
  std::string_view name;   // on the command line: "gradescope"
  std::string_view title;  // in sentences: "Gradescope"
  // The roster's column of the platform's own user ids ("" when it reads none): each student's
  // cell reaches its gradebook layout (ClassRow::platform_id) and its bulk naming
  // (BulkRoster::platform_ids).
  std::string_view roster_column;
  std::optional<LmsExport> lms_export;       // `raygrade export NAME`
  std::optional<GradeFormat> results;        // `raygrade grade --format NAME`: its results document
  std::optional<GradebookLayout> gradebook;  // `raygrade grade --format csv-NAME`
  std::optional<BulkFormat> bulk;            // its "download all submissions" zip
  std::optional<PlatformWorksheet> worksheet;  // its own gradebook file, filled in
  std::optional<PlatformUploads> uploads;      // its metadata of an upload
};

template <typename P>
concept PlatformHasExport = requires {
  { P::lms_export() } -> std::same_as<LmsExport>;
};
template <typename P>
concept PlatformHasResults = requires {
  { P::results_format() } -> std::same_as<GradeFormat>;
};
template <typename P>
concept PlatformHasGradebook = requires {
  { P::gradebook() } -> std::same_as<GradebookLayout>;
};
template <typename P>
concept PlatformHasBulk = requires {
  { P::bulk() } -> std::same_as<BulkFormat>;
};
template <typename P>
concept PlatformHasWorksheet = requires {
  { P::worksheet() } -> std::same_as<PlatformWorksheet>;
};
template <typename P>
concept PlatformHasUploads = requires {
  { P::uploads() } -> std::same_as<PlatformUploads>;
};
template <typename P>
concept PlatformHasRosterColumn = requires {
  { P::kRosterColumn } -> std::convertible_to<std::string_view>;
};

// Every platform has a name and a title, and at least one of an export, a results format, a
// gradebook layout and a bulk naming; each of them, when it is declared, has the type the table
// expects (a member of another type fails the concept instead of being skipped).
template <typename P>
concept PlatformType = requires {
  { P::kName } -> std::convertible_to<std::string_view>;
  { P::kTitle } -> std::convertible_to<std::string_view>;
}
&&(PlatformHasExport<P> || !requires { P::lms_export(); }) &&
    (PlatformHasResults<P> || !requires { P::results_format(); }) &&
    (PlatformHasGradebook<P> || !requires { P::gradebook(); }) &&
    (PlatformHasBulk<P> || !requires { P::bulk(); }) &&
    (PlatformHasWorksheet<P> || !requires { P::worksheet(); }) &&
    (PlatformHasUploads<P> || !requires { P::uploads(); }) &&
    (PlatformHasExport<P> || PlatformHasResults<P> || PlatformHasGradebook<P> ||
     PlatformHasBulk<P>);

// The roster column a platform reads, or "".
template <PlatformType P>
constexpr std::string_view platform_roster_column() {
  if constexpr (PlatformHasRosterColumn<P>) return P::kRosterColumn;
  return {};
}

template <PlatformType P>
PlatformEntry platform_entry() {
  PlatformEntry e{P::kName, P::kTitle, {}, {}, {}, {}, {}, {}, {}};
  e.roster_column = platform_roster_column<P>();
  if constexpr (PlatformHasExport<P>) {
    e.lms_export = P::lms_export();
    e.lms_export->name = P::kName;
    e.lms_export->title = P::kTitle;
  }
  if constexpr (PlatformHasResults<P>) e.results = P::results_format();
  if constexpr (PlatformHasGradebook<P>) e.gradebook = P::gradebook();
  if constexpr (PlatformHasBulk<P>) {
    e.bulk = P::bulk();
    e.bulk->title = P::kTitle;
    e.bulk->roster_column = e.roster_column;
  }
  if constexpr (PlatformHasWorksheet<P>) e.worksheet = P::worksheet();
  if constexpr (PlatformHasUploads<P>) e.uploads = P::uploads();
  return e;
}

// The platforms, in order: PlatformList<A, B>::entries() is the table.
template <PlatformType... Ps>
struct PlatformList {
  static std::vector<PlatformEntry> entries() { return {platform_entry<Ps>()...}; }
  // The roster columns of those that read one (from their types alone).
  static std::vector<std::string_view> roster_columns() {
    std::vector<std::string_view> columns;
    for (std::string_view c : {platform_roster_column<Ps>()...}) {
      if (!c.empty()) columns.push_back(c);
    }
    return columns;
  }
};

}  // namespace raygrade
