// Learning platforms' "download all submissions" zips, read by their file naming.
#include "assignments/bulk_submissions.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <regex>

#include "assignments/roster.h"
#include "assignments/variants.h"
#include "core/escape.h"
#include "core/name_key.h"
#include "core/zip.h"

namespace raygrade {
namespace {

// A name as Canvas writes it into a file's name, as a key: case-folded and normalised
// (name_key), then without ASCII spaces and punctuation. Letters outside ASCII are kept.
std::string canvas_name_key(std::string_view s) {
  std::string out;
  for (unsigned char c : name_key(s)) {
    if (std::isalnum(c) || c >= 0x80) out += static_cast<char>(c);
  }
  return out;
}

// The one roster entry `matches` accepts, or nullptr with `problem` saying why.
template <class Match>
const StudentIdentity* only_entry(const std::vector<StudentIdentity>& roster, Match matches,
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

// Canvas's "Download Submissions": "<lastfirst>[_LATE]_<user id>_<submission id>_<file>", the
// name the student's sortable name in lower case without spaces or punctuation.
std::optional<BulkName> parse_canvas(std::string_view path) {
  static const std::regex kCanvas(R"(^([^_/]+?)(_LATE)?_([0-9]+)_([0-9]+)_([^/]+)$)");
  std::cmatch m;
  if (!std::regex_match(path.data(), path.data() + path.size(), m, kCanvas)) return std::nullopt;
  return BulkName{m[3].str(), m[1].str(), m[5].str()};
}

// By the roster's canvas_id column when it has one; else by the name, as Canvas writes it (last
// name first): a roster name's last word is taken as the last name.
const StudentIdentity* canvas_owner(const BulkName& n, const BulkRoster& r, std::string& problem) {
  const auto& roster = *r.roster;
  bool by_id = false;
  for (const auto& id : r.canvas_ids) by_id = by_id || !id.empty();
  if (by_id) {
    std::size_t i = 0;
    return only_entry(
        roster, [&](const StudentIdentity&) { return r.canvas_ids[i++] == n.platform_id; },
        fmt::format("Canvas user {} ({})", n.platform_id, n.name), problem);
  }
  // A name with no letter or digit is nobody's (its key is empty).
  std::string want = canvas_name_key(n.name);
  std::size_t i = 0;
  return only_entry(
      roster, [&](const StudentIdentity&) { return !want.empty() && r.canvas_keys[i++] == want; },
      fmt::format("Canvas's '{}' (user {}; the roster has no canvas_id column to find it by)",
                  n.name, n.platform_id),
      problem);
}

// Moodle's "Download all submissions": "<full name>_<participant>_assignsubmission_<plugin>"
// then '/' (in folders, Moodle's default) or '_' (without), then the file; Moodle writes '_' in a
// name as a space.
std::optional<BulkName> parse_moodle(std::string_view path) {
  static const std::regex kMoodle(R"(^([^/]+?)_([0-9]+)_assignsubmission_[a-z0-9]+[/_](.+)$)");
  std::cmatch m;
  if (!std::regex_match(path.data(), path.data() + path.size(), m, kMoodle)) return std::nullopt;
  std::string file = m[3].str();
  std::size_t slash = file.rfind('/');
  if (slash != std::string::npos) file = file.substr(slash + 1);
  return BulkName{m[2].str(), m[1].str(), file};
}

// By the grading worksheet's row of the participant (its email) when there is a worksheet; else
// by the full name.
const StudentIdentity* moodle_owner(const BulkName& n, const BulkRoster& r, std::string& problem) {
  const auto& roster = *r.roster;
  if (r.moodle_worksheet && !r.moodle_worksheet->empty()) {
    const auto& rows = *r.moodle_worksheet;
    const auto& header = rows.front();
    std::size_t identifier = header.size(), email = header.size();
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == "Identifier") identifier = c;
      if (header[c] == "Email address") email = c;
    }
    for (std::size_t i = 1; i < rows.size() && identifier < header.size(); ++i) {
      const std::string& id = rows[i][identifier];
      std::size_t digits = id.find_last_not_of("0123456789") + 1;
      if (digits == id.size() || id.substr(digits) != n.platform_id) continue;
      std::string mail = email < rows[i].size() ? email_key(rows[i][email]) : std::string();
      if (mail.empty()) {
        // An empty address is nobody's, not that of a roster student who has none.
        problem = fmt::format(
            "Moodle participant {} ({}) has no email address on the worksheet {}, which ties "
            "the participant to a roster student",
            n.platform_id, n.name, r.moodle_worksheet_file);
        return nullptr;
      }
      return only_entry(
          roster, [&](const StudentIdentity& s) { return email_key(s.email) == mail; },
          fmt::format("Moodle participant {} ({}, {} on the worksheet)", n.platform_id, n.name,
                      rows[i][email]),
          problem);
    }
    problem = fmt::format("Moodle participant {} ({}) has no row on the worksheet {}",
                          n.platform_id, n.name, r.moodle_worksheet_file);
    return nullptr;
  }
  std::string want = name_key(trimmed(n.name));
  std::size_t i = 0;
  return only_entry(
      roster, [&](const StudentIdentity&) { return !want.empty() && r.moodle_keys[i++] == want; },
      fmt::format("Moodle's '{}' (participant {}; without --moodle-worksheet the full name finds "
                  "the student)",
                  n.name, n.platform_id),
      problem);
}

bool is_json_name(std::string_view file) {
  return file.size() > 5 && ascii_lower(std::string(file.substr(file.size() - 5))) == ".json";
}

}  // namespace

const std::vector<BulkFormat>& bulk_formats() {
  // read_bulk_submissions chooses one of them for a whole zip.
  static const std::vector<BulkFormat> table = {
      {"Moodle", "<full name>_<participant>_assignsubmission_file/<file>", &parse_moodle,
       &moodle_owner},
      {"Canvas", "<lastfirst>_<user id>_<submission id>_<file>", &parse_canvas, &canvas_owner},
  };
  return table;
}

bool is_zip_path(std::string_view path) {
  return path.size() > 4 && ascii_lower(std::string(path.substr(path.size() - 4))) == ".zip";
}

std::vector<BulkSubmission> read_bulk_submissions(const std::string& path,
                                                  const BulkRoster& given) {
  BulkRoster roster = given;
  roster.canvas_keys.clear();
  roster.moodle_keys.clear();
  for (const StudentIdentity& s : *roster.roster) {
    // Canvas writes the last name first: a roster name's last word is taken as the last name.
    std::string name = trimmed(s.name);
    std::size_t cut = name.rfind(' ');
    roster.canvas_keys.push_back(canvas_name_key(
        cut == std::string::npos ? name : name.substr(cut + 1) + name.substr(0, cut)));
    // Moodle writes '_' in a name as a space.
    name = s.name;
    std::replace(name.begin(), name.end(), '_', ' ');
    roster.moodle_keys.push_back(name_key(trimmed(name)));
  }
  std::vector<BulkSubmission> out;
  std::vector<ZipFileRead> files = read_zip(path);
  // One platform's naming for the whole zip, not a choice per file: a file of a Canvas zip whose
  // student named it "x_102_assignsubmission_file_a.json" is still Canvas's, not Moodle
  // participant 102's. Moodle never writes a name Canvas's naming fits (its participant number
  // is followed by "_assignsubmission", never by a number), so a zip with any file Canvas's
  // naming fits is Canvas's; any other is Moodle's.
  const auto& formats = bulk_formats();
  const BulkFormat* platform = &formats.front();
  for (const BulkFormat& format : formats) {
    if (format.title != "Canvas") continue;
    for (const ZipFileRead& f : files)
      if (format.parse(f.name)) platform = &format;
  }
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
      for (const BulkFormat& format : bulk_formats())
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
