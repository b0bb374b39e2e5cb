// Reading and grading submissions.
#include "grading/submission.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <tuple>

#include "core/escape.h"
#include "json/cursor.h"

namespace raygrade {

std::size_t SubmissionGrade::mistakes() const {
  std::size_t n = 0;
  for (const auto& r : results) n += r.mistakes.size();
  return n;
}

Assignment::Assignment(const std::vector<Problem>& problems, AssignmentOptions options)
    : options_(options) {
  graders_.reserve(problems.size());
  for (const auto& p : problems) {
    try {
      graders_.emplace_back(p);
      by_id_[p.id] = graders_.size() - 1;
    } catch (const Error& e) {
      Diagnostic d = e.diagnostic();
      if (d.file.empty()) d.file = p.file;
      if (d.path.empty()) d.path = p.path;
      errors_.push_back(d);
    }
  }
}

SubmissionGrade Assignment::grade_file(const std::string& path,
                                       std::optional<FileIdentity> seen) const {
  try {
    JsonLimits limits = JsonLimits::submission();
    limits.expected = seen;
    return grade(load_json_file(path, limits));
  } catch (const Error& e) {
    SubmissionGrade g;
    g.file = path;
    g.student = student_of_file(path);
    g.gradable = false;
    g.fault = e.diagnostic();
    return g;
  }
}

std::string student_of_file(const std::string& path) {
  return printable(std::filesystem::path(path).stem().string());
}

std::string StudentIdentity::display() const {
  if (!name.empty()) return name;
  if (!id.empty()) return id;
  return email;
}

std::optional<StudentIdentity> read_student(const Cursor& root) {
  if (!root.is_object() || !root.has("student")) return std::nullopt;
  Cursor s = root.at("student");
  StudentIdentity who;
  if (s.json().is_string()) {
    who.name = s.string();
  } else if (s.is_object()) {
    s.allow_only({"name", "id", "email"});
    who.name = s.string_or("name", "");
    who.id = s.string_or("id", "");
    who.email = s.string_or("email", "");
  } else {
    s.fail("student is a name, or an object with a name, id or email", "type");
  }
  if (who.empty()) s.fail("student names nobody: give a name, id or email", "invalid");
  return who;
}

namespace {

bool is_blank(const nlohmann::json& v) {
  if (!v.is_string()) return false;
  for (char c : v.get_ref<const std::string&>()) {
    if (c != ' ' && c != '\t') return false;
  }
  return true;
}

bool is_blank_vector(const nlohmann::json& v) {
  return v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), is_blank);
}

// An answer with the blanks of a template left out: a "" (or ["", "", ""]) is a part not
// given, and a trailing list item of nothing but blanks is no item. A list that held only
// blanks is left out too ("hits": [] is an answer, a blank row is not).
nlohmann::json without_blanks(const nlohmann::json& v) {
  if (v.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, value] : v.items()) {
      if (is_blank(value) || is_blank_vector(value)) continue;
      nlohmann::json kept = without_blanks(value);
      if (value.is_array() && !value.empty() && kept.empty()) continue;
      out[key] = std::move(kept);
    }
    return out;
  }
  if (v.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& item : v) out.push_back(without_blanks(item));
    std::size_t n = out.size();
    while (n > 0 && v[n - 1].is_object() && !v[n - 1].empty() && out[n - 1].empty()) --n;
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(n), out.end());
    return out;
  }
  return v;
}

}  // namespace

SubmissionGrade Assignment::grade(const std::shared_ptr<const SourceFile>& file) const {
  SubmissionGrade g;
  g.file = file->name;
  g.student = student_of_file(file->name);
  Cursor root(file);
  try {
    if (!root.is_object()) root.fail("a submission is a JSON object", "type");
    // A bank given where a submission goes (a second file after one --problems).
    if (root.has("problems") && !root.has("answers"))
      root.at("problems")
          .fail("this file is a problem bank, not a submission: each bank needs its own --problems",
                "not-a-submission");
    root.allow_only({"student", "answers", "$schema", "submitted"});
    if (auto who = read_student(root)) {
      g.identity = *who;
      g.student = who->display();
    }
    Cursor answers = root.at("answers");
    if (!answers.is_object()) answers.fail("answers is an object: problem id → answer", "type");
    std::vector<std::string> ids;
    for (const auto& [id, i] : by_id_) ids.push_back(id);
    // Each unknown id is reported with its closest known one and its line, for the first few:
    // past them a count, so that a file of thousands of unknown ids costs time linear in its
    // size (a suggestion scans every known id, and a line scans the text).
    constexpr std::size_t kReportedUnknown = 20;
    std::size_t unknown = 0;
    for (const auto& [id, v] : answers.json().items()) {
      if (by_id_.count(id)) continue;
      if (++unknown > kReportedUnknown) continue;
      std::string hint = closest_match(id, ids);
      Diagnostic d;
      d.file = file->name;
      d.path = answers.at(id).path();
      std::tie(d.line, d.column) = locate(file->text, d.path);
      d.severity = Severity::kWarning;
      d.message = hint.empty() ? fmt::format("no problem '{}' in this assignment: not graded", id)
                               : fmt::format(
                                     "no problem '{}' in this assignment (did you mean "
                                     "'{}'?): not graded",
                                     id, hint);
      d.code = "unknown-problem";
      g.findings.push_back(std::move(d));
    }
    if (unknown > kReportedUnknown) {
      Diagnostic d;
      d.file = file->name;
      d.path = answers.path();
      std::tie(d.line, d.column) = locate(file->text, d.path);
      d.severity = Severity::kWarning;
      d.message =
          fmt::format("{} more answers to problems this assignment does not have: not graded",
                      unknown - kReportedUnknown);
      d.code = "unknown-problem";
      g.findings.push_back(std::move(d));
    }
    for (const auto& grader : graders_) {
      const std::string& id = grader.problem().id;
      auto it = answers.json().find(id);
      if (it == answers.json().end()) {
        if (!options_.answered_only) g.results.push_back(grader.unanswered());
        continue;
      }
      GradeOptions o{file->name, "/answers/" + pointer_token(id)};
      g.results.push_back(grader.grade(without_blanks(*it), o));
    }
  } catch (const Error& e) {
    g.gradable = false;
    g.results.clear();
    Diagnostic d = e.diagnostic();
    if (d.file.empty()) d.file = file->name;
    if (d.line == 0 && !d.path.empty()) {
      auto [line, column] = file->locate(d.path);
      d.line = line;
      d.column = column;
    }
    g.fault = d;
    return g;
  } catch (const std::logic_error& e) {
    // A bug of the grader, not of the file: this submission is set aside with what went wrong,
    // and the rest of the batch is graded.
    g.gradable = false;
    g.results.clear();
    g.fault = Diagnostic{file->name,
                         "",
                         0,
                         0,
                         Severity::kError,
                         fmt::format("raygrade could not grade this file: an internal error ({}); "
                                     "the file is not at fault, please report it with the file",
                                     e.what()),
                         "internal"};
    return g;
  }
  for (const auto& r : g.results) {
    g.score += r.score;
    g.max_score += r.max_score;
  }
  return g;
}

namespace {

namespace fs = std::filesystem;

Diagnostic skipped(const fs::path& path, std::string why, std::string code = "skipped") {
  return Diagnostic{path.string(), "", 0, 0, Severity::kError, std::move(why), std::move(code)};
}

// What a file that is neither a folder nor a regular file is, for "skipped: ...".
std::string kind_of(fs::file_type type) {
  switch (type) {
    case fs::file_type::fifo: return "a FIFO (named pipe)";
    case fs::file_type::block: return "a block device";
    case fs::file_type::character: return "a character device";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

bool inside(const fs::path& path, const fs::path& folder) {
  auto [f, p] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return f == folder.end();
}

// Walks `folder` (whose canonical path is `root`), adding its .json submissions to `out` and
// reporting every entry it cannot read or will not open.
// The identity of the file at `path` now (following links), or nothing.
std::optional<FileIdentity> identity_of(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return FileIdentity{static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)};
}

void walk(const fs::path& folder, const fs::path& root, std::vector<std::string>& out,
          std::vector<Diagnostic>& errors) {
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  if (ec) {
    errors.push_back(skipped(folder, "cannot read the folder: " + ec.message(), "unreadable"));
    return;
  }
  std::vector<fs::directory_entry> entries;
  for (fs::directory_iterator end; it != end; it.increment(ec)) {
    entries.push_back(*it);
  }
  if (ec)
    errors.push_back(skipped(folder, "cannot read the folder: " + ec.message(), "unreadable"));
  std::sort(entries.begin(), entries.end());
  for (const auto& e : entries) {
    const fs::path& p = e.path();
    fs::file_status own = e.symlink_status(ec);
    if (ec) {
      errors.push_back(skipped(p, "cannot read: " + ec.message(), "unreadable"));
      continue;
    }
    if (fs::is_directory(own)) {
      walk(p, root, out, errors);
      continue;
    }
    fs::file_status target = own;
    if (fs::is_symlink(own)) {
      // A link is followed to a regular file inside the submissions folder only: a link
      // leading elsewhere (another student's folder, /etc/shadow) is not graded, nor is a
      // link to a folder (it could loop, and the folder is walked on its own anyway).
      target = fs::status(p, ec);
      if (ec || !fs::exists(target)) {
        errors.push_back(skipped(p, "skipped: a symbolic link to nothing"));
        continue;
      }
      fs::path resolved = fs::canonical(p, ec);
      if (ec || !inside(resolved, root)) {
        errors.push_back(skipped(p, "skipped: a symbolic link leading outside " + root.string()));
        continue;
      }
      if (fs::is_directory(target)) {
        errors.push_back(skipped(p, "skipped: a symbolic link to a folder (not followed)"));
        continue;
      }
    }
    if (!fs::is_regular_file(target)) {
      errors.push_back(skipped(p, "skipped: " + kind_of(target.type()) + ", not a regular file"));
      continue;
    }
    // Other regular files (a README, notes) are not submissions. A link is listed as the file
    // it was checked to lead to, which is then opened without following links: a link swapped
    // in after this check is not read.
    if (p.extension() == ".json")
      out.push_back(fs::is_symlink(own) ? fs::canonical(p, ec).string() : p.string());
  }
}

}  // namespace

std::vector<std::string> submission_files(const std::vector<std::string>& paths,
                                          std::vector<Diagnostic>& errors,
                                          std::vector<std::optional<FileIdentity>>* seen) {
  std::vector<std::string> out;
  for (const auto& p : paths) {
    std::error_code ec;
    // A path named on the command line is followed wherever it leads: the user chose it.
    fs::file_status status = fs::status(p, ec);
    if (fs::is_directory(status)) {
      fs::path root = fs::canonical(p, ec);
      walk(p, ec ? fs::path(p) : root, out, errors);
    } else if (fs::is_regular_file(status)) {
      // Named on the command line, a link is followed; it is listed as its target, which is
      // opened without following links (submission files are).
      fs::path resolved =
          fs::is_symlink(fs::symlink_status(p, ec)) ? fs::canonical(p, ec) : fs::path(p);
      out.push_back(ec ? p : resolved.string());
    } else if (fs::exists(status)) {
      errors.push_back(skipped(p, "skipped: " + kind_of(status.type()) + ", not a regular file"));
    } else {
      errors.push_back(skipped(p, "no such file or folder", "unreadable"));
    }
  }
  if (seen) {
    seen->clear();
    for (const auto& f : out) seen->push_back(identity_of(f));
  }
  return out;
}

}  // namespace raygrade
