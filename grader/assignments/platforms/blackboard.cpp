// Blackboard's offline grade upload.
#include "assignments/platforms/blackboard.h"

#include <fmt/format.h>

#include "core/escape.h"
#include "grading/outputs.h"

namespace raygrade {
namespace {

// A field in quotation marks, as Blackboard's upload wants every field: the text csv_cell writes
// (control characters as \xNN, a formula neutralised), its quotation marks doubled.
std::string quoted_cell(std::string_view s) {
  std::string v = printable(s);
  if (!v.empty() && (v[0] == '=' || v[0] == '+' || v[0] == '-' || v[0] == '@')) {
    v.insert(v.begin(), '\'');
  }
  std::string out = "\"";
  for (char c : v) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// Blackboard's "Uploading External Grade Center Items": a column is matched by the Column ID
// after '|' in its header, so a title may hold no '|'; without a Column ID the upload adds a new
// text column with 0 points possible (a warning).
ColumnCheck blackboard_column(const std::string& title, const std::string& column_id) {
  ColumnCheck c;
  if (!column_id.empty() && !is_column_id(column_id)) {
    c.error = fmt::format("--blackboard-column-id '{}' is not a Blackboard Column ID (digits)",
                          printable(column_id));
    return c;
  }
  if (title.find('|') != std::string::npos) {
    c.error = fmt::format(
        "the assignment's title \"{}\" holds '|', where Blackboard reads a column's Column ID: "
        "give the assignment another title",
        printable(title));
    return c;
  }
  if (column_id.empty()) {
    c.warning =
        "without --blackboard-column-id, Blackboard adds the column as a new text column with "
        "0 points possible (its Grade Center: the column's menu, Column Information, shows the "
        "id of an existing column)";
  }
  return c;
}

// Username identifies the student (the roster's id), a column its Column ID after '|' (without
// one, the upload adds a new text column), and every field is in quotation marks.
std::string blackboard_gradebook(const ClassRows& book, const std::string& title,
                                 const std::string& column_id) {
  std::string column = fmt::format("{} [Total Pts: {} Score]", title,
                                   book.points ? format_points(*book.points) : "");
  if (!column_id.empty()) column += " |" + column_id;
  std::string s =
      "\"Last Name\",\"First Name\",\"Username\",\"Student ID\"," + quoted_cell(column) + "\n";
  for (const ClassRow& row : book.rows) {
    const StudentIdentity& who = row.student;
    std::string name = who.name.empty() ? who.id : who.name;
    // A name's last word is its last name, as Blackboard's columns want it.
    std::size_t cut = name.rfind(' ');
    std::string first = cut == std::string::npos ? "" : name.substr(0, cut);
    std::string last = cut == std::string::npos ? name : name.substr(cut + 1);
    s += quoted_cell(last) + "," + quoted_cell(first) + "," + quoted_cell(who.id) + "," +
         quoted_cell(who.id) + "," + quoted_cell(format_points(row.score)) + "\n";
  }
  return s;
}

}  // namespace

GradebookLayout Blackboard::gradebook() {
  return {"csv-blackboard",
          "with --roster: Blackboard's offline grade upload",
          "--blackboard-column-id",
          "the Column ID of the Grade Center column to fill in (without it, the upload adds a "
          "new text column)",
          &blackboard_column,
          &blackboard_gradebook};
}

}  // namespace raygrade
