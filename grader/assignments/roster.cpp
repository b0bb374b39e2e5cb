// Reading rosters.
#include "assignments/roster.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "assignments/platforms/platforms.h"
#include "assignments/variants.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "core/name_key.h"

namespace raygrade {
namespace {

// A roster of a very large course is a few thousand lines; this is far above it.
constexpr std::size_t kMaxRosterBytes = 4u << 20;

[[noreturn]] void fail(const std::string& file, int line, int column, std::string message) {
  throw Error(Diagnostic{file, "", line, column, Severity::kError, std::move(message), "roster"});
}

}  // namespace

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

std::vector<StudentIdentity> load_roster(const std::string& path, RosterColumns* columns) {
  std::optional<std::string> bytes = read_whole_file(path);
  if (!bytes) fail(path, 0, 0, "cannot open the roster");
  std::string text = std::move(*bytes);
  if (text.size() > kMaxRosterBytes) fail(path, 0, 0, "the roster is larger than 4 MiB");
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a spreadsheet's byte order mark
  // Rosters are UTF-8. A legacy encoding (a spreadsheet's "CSV" in Windows-1252 or Latin-1) is
  // not guessed: its names would be read wrong, so the first byte that is not UTF-8 is named.
  if (std::size_t bad = first_invalid_utf8(text); bad != std::string::npos) {
    std::size_t line_start = bad == 0 ? std::string::npos : text.rfind('\n', bad - 1);
    line_start = line_start == std::string::npos ? 0 : line_start + 1;
    int line = 1 + static_cast<int>(std::count(
                       text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n'));
    int byte = static_cast<int>(bad - line_start) + 1;
    fail(path, line, byte,
         fmt::format("byte 0x{:02X} (byte {} of line {}) is not UTF-8: save the roster as \"CSV "
                     "UTF-8\" (a spreadsheet's other CSV is Windows-1252, which is not read)",
                     static_cast<unsigned char>(text[bad]), byte, line));
  }
  auto rows = csv_rows(text, path);
  if (rows.empty())
    fail(path, 1, 1, "the roster is empty: its first line names the columns id, name, email");
  int id_col = -1, name_col = -1, email_col = -1;
  std::vector<std::string_view> platform_columns = roster_platform_columns();
  std::vector<int> platform_col(platform_columns.size(), -1);
  std::string known = "id, name, email";
  for (std::string_view c : platform_columns) known += fmt::format(", {}", c);
  for (std::size_t i = 0; i < rows[0].size(); ++i) {
    std::string h = ascii_lower(trimmed(rows[0][i]));
    int* col = h == "id" ? &id_col : h == "name" ? &name_col : h == "email" ? &email_col : nullptr;
    for (std::size_t p = 0; p < platform_columns.size() && !col; ++p) {
      if (h == platform_columns[p]) col = &platform_col[p];
    }
    if (!col) fail(path, 1, 0, fmt::format("unknown column '{}' (known: {})", h, known));
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
    for (std::size_t p = 0; p < platform_columns.size() && columns; ++p)
      (*columns)[std::string(platform_columns[p])].push_back(cell(platform_col[p]));
  }
  return out;
}

namespace {

std::string describe_entry(const StudentIdentity& s) {
  std::string d = fmt::format("id '{}'", s.id);
  if (!s.name.empty()) d += fmt::format(", name '{}'", s.name);
  if (!s.email.empty()) d += fmt::format(", email '{}'", s.email);
  return d;
}

// The entries one field names.
template <typename Same>
std::vector<const StudentIdentity*> entries_where(const std::vector<StudentIdentity>& roster,
                                                  Same same) {
  std::vector<const StudentIdentity*> out;
  for (const auto& s : roster) {
    if (same(s)) out.push_back(&s);
  }
  return out;
}

}  // namespace

RosterMatch match_on_roster(const std::vector<StudentIdentity>& roster,
                            const StudentIdentity& who) {
  struct Field {
    const char* name;
    std::string value;
    std::vector<const StudentIdentity*> entries;
  };
  std::vector<Field> fields;
  if (std::string id = trimmed(who.id); !id.empty())
    fields.push_back({"id", id, entries_where(roster, [&](const auto& s) { return s.id == id; })});
  if (std::string e = email_key(who.email); !e.empty()) {
    fields.push_back({"email", trimmed(who.email), entries_where(roster, [&](const auto& s) {
                        return email_key(s.email) == e;
                      })});
  }
  // Names in any case and Unicode form ("Émile" precomposed or not); a name with no letter
  // left (only ignorable characters) names nobody.
  if (std::string n = trimmed(who.name), key = name_key(n); !key.empty()) {
    fields.push_back({"name", n, entries_where(roster, [&](const auto& s) {
                        return name_key(trimmed(s.name)) == key;
                      })});
  }
  RosterMatch m;
  if (fields.empty()) {
    m.problem = "the submission names no student";
    m.code = "not-on-roster";
    return m;
  }
  for (const auto& f : fields) {
    if (f.entries.empty()) {
      m.problem = fmt::format("no student on the roster has the {} '{}'", f.name, f.value);
      m.code = "not-on-roster";
      return m;
    }
  }
  // The first field that names one entry decides; every other field must name it too.
  const Field* decisive = nullptr;
  for (const auto& f : fields) {
    if (f.entries.size() == 1) {
      decisive = &f;
      break;
    }
  }
  if (!decisive) {
    const Field& f = fields.front();
    std::string candidates;
    for (const auto* s : f.entries)
      candidates += fmt::format("{}{}", candidates.empty() ? "" : "; ", describe_entry(*s));
    m.problem =
        fmt::format("the {} '{}' is that of {} students on the roster ({}): give the student's id",
                    f.name, f.value, f.entries.size(), candidates);
    m.code = "ambiguous-student";
    return m;
  }
  const StudentIdentity* entry = decisive->entries.front();
  for (const auto& f : fields) {
    if (std::find(f.entries.begin(), f.entries.end(), entry) == f.entries.end()) {
      m.problem = fmt::format(
          "the submission's {} '{}' and its {} '{}' name different students on the roster "
          "(the {} belongs to {})",
          decisive->name, decisive->value, f.name, f.value, f.name,
          f.entries.size() == 1 ? describe_entry(*f.entries.front())
                                : fmt::format("{} others", f.entries.size()));
      m.code = "student-mismatch";
      return m;
    }
  }
  m.entry = entry;
  return m;
}

const StudentIdentity* find_on_roster(const std::vector<StudentIdentity>& roster,
                                      const StudentIdentity& who) {
  return match_on_roster(roster, who).entry;
}

}  // namespace raygrade
