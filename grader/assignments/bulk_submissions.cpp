// Learning platforms' "download all submissions" zips, read by their file naming.
#include "assignments/bulk_submissions.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <regex>

#include "assignments/roster.h"
#include "assignments/variants.h"
#include "core/escape.h"
#include "core/internal_error.h"
#include "core/zip.h"

namespace raygrade {
namespace {

bool is_json_name(std::string_view file) {
  return file.size() > 5 && ascii_lower(std::string(file.substr(file.size() - 5))) == ".json";
}

// One platform's naming for the whole zip, not a choice per file: the first that claims a zip
// and fits any of its files, else the first that claims none. A file of a zip one platform
// claims, whose student named it as another platform would, is still the first platform's.
const BulkFormat* zip_platform(const std::vector<BulkFormat>& formats,
                               const std::vector<ZipFileRead>& files) {
  for (const BulkFormat& format : formats) {
    if (!format.claims_zip) continue;
    for (const ZipFileRead& f : files) {
      if (format.parse(f.name)) return &format;
    }
  }
  for (const BulkFormat& format : formats) {
    if (!format.claims_zip) return &format;
  }
  throw InternalError("read_bulk_submissions: every platform's naming claims its zips");
}

}  // namespace

bool is_zip_path(std::string_view path) {
  return path.size() > 4 && ascii_lower(std::string(path.substr(path.size() - 4))) == ".zip";
}

std::vector<BulkSubmission> read_bulk_submissions(const std::string& path,
                                                  const std::vector<BulkFormat>& formats,
                                                  const BulkInput& in) {
  std::vector<BulkSubmission> out;
  std::vector<ZipFileRead> files = read_zip(path);
  const BulkFormat* platform = zip_platform(formats, files);
  BulkRoster roster{in.roster, {}, nullptr, {}};
  if (in.columns) {
    if (auto column = in.columns->find(platform->roster_column); column != in.columns->end())
      roster.platform_ids = column->second;
  }
  roster.platform_ids.resize(in.roster->size());
  if (auto w = in.worksheets.find(platform->title); w != in.worksheets.end())
    roster.worksheet = w->second;
  for (const StudentIdentity& s : *in.roster) roster.name_keys.push_back(platform->roster_key(s));
  for (ZipFileRead& f : files) {
    BulkSubmission b;
    b.file = path + "/" + f.name;
    b.modified = f.modified;
    auto fail = [&](std::string message, std::string code) {
      b.fault = Diagnostic{b.file, "", 0, 0, Severity::kError, std::move(message), std::move(code)};
    };
    std::optional<BulkName> name = platform->parse(f.name);
    b.platform = platform->title;
    if (name) {
      std::string problem;
      b.owner = platform->owner(*name, roster, problem);
      if (!b.owner) {
        fail(fmt::format("not graded: {}", problem), "not-on-roster");
        b.claimed = StudentIdentity{name->name, "", ""};
      }
    }
    if (!name) {
      std::string namings;
      for (const BulkFormat& format : formats)
        namings += fmt::format("{}{} names its files {}", namings.empty() ? "" : "; ", format.title,
                               format.naming);
      fail(fmt::format("not graded: the file's name names no student ({}; this zip is read as "
                       "{}'s)",
                       namings, platform->title),
           "no-student");
    } else if (!b.fault && !is_json_name(name->file)) {
      fail(fmt::format("not graded: {} is not a .json submission (answers.json, as the handout "
                       "page saves it)",
                       printable(name->file)),
           "not-json");
    } else if (!b.fault && !f.fault.empty()) {
      fail("not graded: " + f.fault, "zip");
    }
    if (b.fault && b.owner) b.claimed = *b.owner;  // the rejection shows on the student's row
    if (!b.fault) b.text = std::move(f.bytes);
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace raygrade
