// Reading rosters.
#include "assignments/roster.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "assignments/variants.h"
#include "core/atomic_file.h"

namespace raygrade {
namespace {

// A roster of a very large course is a few thousand lines; this is far above it.
constexpr std::size_t kMaxRosterBytes = 4u << 20;

[[noreturn]] void fail(const std::string& file, int line, int column, std::string message) {
  throw Error(Diagnostic{file, "", line, column, Severity::kError, std::move(message), "roster"});
}

// The cells of every line of a CSV text (RFC 4180: quoted cells may hold commas, quotes as "",
// and line breaks).
std::vector<std::vector<std::string>> csv_rows(const std::string& text, const std::string& file) {
  std::vector<std::vector<std::string>> rows(1);
  std::string cell;
  bool quoted = false, was_quoted = false;
  int line = 1, column = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    ++column;
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line, column = 0;
        cell += c;
      }
    } else if (c == '"' && cell.empty() && !was_quoted) {
      quoted = was_quoted = true;
    } else if (c == ',') {
      rows.back().push_back(std::move(cell));
      cell.clear();
      was_quoted = false;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      rows.back().push_back(std::move(cell));
      cell.clear();
      was_quoted = false;
      rows.emplace_back();
      ++line;
      column = 0;
    } else if (was_quoted) {
      fail(file, line, column, "text after a quoted cell's closing quote");
    } else {
      cell += c;
    }
  }
  if (quoted) fail(file, line, column, "a quoted cell is not closed");
  if (!cell.empty() || !rows.back().empty()) {
    rows.back().push_back(std::move(cell));
  } else {
    rows.pop_back();
  }
  return rows;
}

}  // namespace

std::vector<StudentIdentity> load_roster(const std::string& path) {
  std::optional<std::string> bytes = read_whole_file(path);
  if (!bytes) fail(path, 0, 0, "cannot open the roster");
  std::string text = std::move(*bytes);
  if (text.size() > kMaxRosterBytes) fail(path, 0, 0, "the roster is larger than 4 MiB");
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a spreadsheet's byte order mark
  auto rows = csv_rows(text, path);
  if (rows.empty())
    fail(path, 1, 1, "the roster is empty: its first line names the columns id, name, email");
  int id_col = -1, name_col = -1, email_col = -1;
  for (std::size_t i = 0; i < rows[0].size(); ++i) {
    std::string h = trimmed(rows[0][i]);
    std::transform(h.begin(), h.end(), h.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    int* col = h == "id" ? &id_col : h == "name" ? &name_col : h == "email" ? &email_col : nullptr;
    if (!col) fail(path, 1, 0, fmt::format("unknown column '{}' (known: id, name, email)", h));
    if (*col >= 0) fail(path, 1, 0, fmt::format("the column '{}' is named twice", h));
    *col = static_cast<int>(i);
  }
  if (id_col < 0) fail(path, 1, 0, "the roster has no 'id' column");
  std::vector<StudentIdentity> out;
  std::set<std::string> ids;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    int line = static_cast<int>(r) + 1;
    if (row.size() == 1 && trimmed(row[0]).empty()) continue;  // a blank line
    if (row.size() != rows[0].size()) {
      fail(path, line, 0,
           fmt::format("{} cells where the header has {}", row.size(), rows[0].size()));
    }
    auto cell = [&row](int col) {
      return col < 0 ? std::string() : trimmed(row[static_cast<std::size_t>(col)]);
    };
    StudentIdentity s{cell(name_col), cell(id_col), cell(email_col)};
    if (s.id.empty()) fail(path, line, id_col + 1, "a student without an id");
    if (!ids.insert(s.id).second)
      fail(path, line, id_col + 1, fmt::format("the id '{}' is listed twice", s.id));
    out.push_back(std::move(s));
  }
  return out;
}

const StudentIdentity* find_on_roster(const std::vector<StudentIdentity>& roster,
                                      const StudentIdentity& who) {
  std::string key = student_key(who);
  for (const auto& s : roster) {
    if (!who.id.empty()      ? s.id == key
        : !who.email.empty() ? student_key(StudentIdentity{"", "", s.email}) == key
                             : s.name == key) {
      return &s;
    }
  }
  return nullptr;
}

}  // namespace raygrade
