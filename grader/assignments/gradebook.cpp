// The gradebook of a class.
#include "assignments/gradebook.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

#include "assignments/variants.h"
#include "core/escape.h"
#include "grading/outputs.h"

namespace raygrade {

std::optional<PickPolicy> parse_pick_policy(std::string_view name) {
  if (name == "latest") return PickPolicy::kLatest;
  if (name == "best") return PickPolicy::kBest;
  if (name == "first") return PickPolicy::kFirst;
  return std::nullopt;
}

RosterGradebook::RosterGradebook(const std::vector<StudentIdentity>& roster,
                                 const std::vector<std::string>& problem_ids, PickPolicy pick)
    : roster_(roster), problem_ids_(problem_ids), pick_(pick), handed_(roster.size()) {}

bool RosterGradebook::add(const SubmissionGrade& g) {
  std::size_t row = roster_.size();
  if (!g.identity.empty()) {
    for (std::size_t i = 0; i < roster_.size() && row == roster_.size(); ++i) {
      if (student_key(roster_[i]) == student_key(g.identity)) row = i;
    }
  } else if (!g.gradable && !g.claimed.id.empty()) {
    // Rejected before it was tied to a student (its fields disagree, say): shown on the row of
    // the id it gives, which earns nothing by it.
    for (std::size_t i = 0; i < roster_.size() && row == roster_.size(); ++i) {
      if (roster_[i].id == trimmed(g.claimed.id)) row = i;
    }
  }
  if (row == roster_.size()) return false;
  Handed h;
  h.file = g.file;
  h.submitted = g.submitted;
  h.file_time = g.file_time;
  h.gradable = g.gradable;
  if (g.fault) h.fault = g.fault->message;
  h.score = g.score;
  h.max_score = g.max_score;
  std::map<std::string_view, double> by_id;
  for (const auto& r : g.results) by_id[r.problem_id] = r.answered ? r.score : 0.0;
  for (const auto& id : problem_ids_) {
    auto it = by_id.find(id);
    h.points.push_back(it == by_id.end() ? 0.0 : it->second);
  }
  handed_[row].push_back(std::move(h));
  return true;
}

const RosterGradebook::Handed* RosterGradebook::chosen(const std::vector<Handed>& handed) const {
  const Handed* best = nullptr;
  // When: the submission's own time where it gives one, then the file's, then its name.
  auto when = [](const Handed& h) {
    return std::make_tuple(h.submitted.value_or(h.file_time), h.file_time, h.file);
  };
  for (const auto& h : handed) {
    if (!h.gradable) continue;
    bool better = !best;
    if (best) {
      switch (pick_) {
        case PickPolicy::kLatest: better = when(h) > when(*best); break;
        case PickPolicy::kFirst: better = when(h) < when(*best); break;
        case PickPolicy::kBest:
          better = h.score > best->score || (h.score == best->score && when(h) > when(*best));
          break;
      }
    }
    if (better) best = &h;
  }
  return best;
}

std::string RosterGradebook::status(std::size_t student) const {
  const auto& handed = handed_[student];
  if (handed.empty()) return "no submission";
  const Handed* pick = chosen(handed);
  if (!pick) return "rejected: " + printable(handed.back().fault);
  if (handed.size() == 1) return "graded";
  static constexpr const char* kWhy[] = {"latest", "best", "first"};
  std::string others;
  for (const auto& h : handed) {
    if (&h == pick) continue;
    others +=
        fmt::format("{}{}{}", others.empty() ? "" : ", ", h.file, h.gradable ? "" : " (rejected)");
  }
  return fmt::format("graded: {} of {} submissions, {}; not counted: {}",
                     kWhy[static_cast<int>(pick_)], handed.size(), pick->file, others);
}

std::vector<std::string> RosterGradebook::choices() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    if (handed_[i].size() > 1)
      out.push_back(fmt::format("student '{}': {}", roster_[i].id, status(i)));
  }
  return out;
}

std::optional<double> RosterGradebook::max_score() const {
  // Every student's maximum is the assignment's, whichever variant they have.
  for (const auto& handed : handed_) {
    if (const Handed* pick = chosen(handed)) return pick->max_score;
  }
  return std::nullopt;
}

namespace {

// Canvas's NON_ASSIGNMENT_COLUMN_HEADERS (app/models/gradebook_importer.rb): a column whose title
// contains one of them is not read as an assignment.
constexpr std::string_view kCanvasNonAssignmentWords[] = {
    "Current Score", "Current Points", "Current Grade",  "Final Score",    "Final Points",
    "Final Grade",   "Override Score", "Override Grade", "Override Status"};

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Ruby's \s: space, tab, line feed, vertical tab, form feed, carriage return.
bool ruby_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

// The id Canvas's Assignment.title_and_id reads at the end of a title (/\A(.*)\s\((\d+)\)\z/),
// or "".
std::string canvas_title_id(std::string_view title) {
  if (title.size() < 4 || title.back() != ')') return "";
  std::size_t open = title.rfind('(');
  if (open == std::string_view::npos || open == 0 || !ruby_space(title[open - 1])) return "";
  std::string_view digits = title.substr(open + 1, title.size() - open - 2);
  // (.*) matches no line break: the id must be on the title's only line.
  if (!all_digits(digits) || title.substr(0, open).find('\n') != std::string_view::npos) return "";
  return std::string(digits);
}

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

}  // namespace

ColumnCheck check_platform_column(std::string_view layout, const std::string& title,
                                  const std::string& column_id) {
  ColumnCheck c;
  if (layout == "csv-canvas") {
    if (!column_id.empty() && !all_digits(column_id)) {
      c.error = fmt::format("--canvas-assignment-id '{}' is not a Canvas assignment id (digits)",
                            printable(column_id));
      return c;
    }
    for (std::string_view words : kCanvasNonAssignmentWords) {
      if (title.find(words) != std::string::npos) {
        c.error = fmt::format(
            "the assignment's title \"{}\" contains \"{}\": Canvas's gradebook import drops "
            "such a column as one of its own totals; give the assignment another title",
            printable(title), words);
        return c;
      }
    }
    std::string id = canvas_title_id(title);
    if (column_id.empty() && !id.empty()) {
      c.error = fmt::format(
          "Canvas reads the title \"{}\" as the assignment of id {}: give the assignment's "
          "Canvas id with --canvas-assignment-id (the column is then \"Title (id)\"), or "
          "another title",
          printable(title), id);
    }
  } else if (layout == "csv-blackboard") {
    if (!column_id.empty() && !all_digits(column_id)) {
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
  }
  return c;
}

std::string RosterGradebook::platform_csv(std::string_view layout, const std::string& title,
                                          const std::string& column_id) const {
  std::optional<double> most = max_score();
  std::string points = most ? format_points(*most) : "";
  std::string s;
  if (layout == "csv-canvas") {
    // Canvas matches a row by its ID (the roster's canvas_id, when it has one), SIS User ID
    // (the roster's id) or SIS Login ID (the email);
    // the row under the header gives the points possible, and a new column name makes a new
    // assignment.
    // With the assignment's id, Canvas's own "Title (id)": matched by the id.
    std::string column = column_id.empty() ? title : fmt::format("{} ({})", title, column_id);
    s = "Student,ID,SIS User ID,SIS Login ID,Section," + csv_cell(column) + "\n";
    s += "    Points Possible,,,,," + points + "\n";
  } else if (layout == "csv-moodle") {
    // Moodle's grade import from CSV: map "Email address" to the user's email, and the grade
    // column to the assignment's grade item.
    s = "ID number,Full name,Email address," + csv_cell(title) + "\n";
  } else {
    // Blackboard's offline grade upload: Username identifies the student (the roster's id), a
    // column its Column ID after '|' (without one, the upload adds a new text column), and
    // every field is in quotation marks.
    std::string column = fmt::format("{} [Total Pts: {} Score]", title, points);
    if (!column_id.empty()) column += " |" + column_id;
    s = "\"Last Name\",\"First Name\",\"Username\",\"Student ID\"," + quoted_cell(column) + "\n";
  }
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    const StudentIdentity& who = roster_[i];
    const Handed* pick = chosen(handed_[i]);
    std::string score = format_points(pick ? pick->score : 0.0);
    std::string name = who.name.empty() ? who.id : who.name;
    if (layout == "csv-canvas") {
      std::string canvas_id = i < canvas_ids_.size() ? canvas_ids_[i] : "";
      s += csv_cell(name) + "," + csv_cell(canvas_id) + "," + csv_cell(who.id) + "," +
           csv_cell(who.email) + ",," + score;
    } else if (layout == "csv-moodle") {
      s += csv_cell(who.id) + "," + csv_cell(name) + "," + csv_cell(who.email) + "," + score;
    } else {
      // A name's last word is its last name, as Blackboard's columns want it.
      std::size_t cut = name.rfind(' ');
      std::string first = cut == std::string::npos ? "" : name.substr(0, cut);
      std::string last = cut == std::string::npos ? name : name.substr(cut + 1);
      s += quoted_cell(last) + "," + quoted_cell(first) + "," + quoted_cell(who.id) + "," +
           quoted_cell(who.id) + "," + quoted_cell(score);
    }
    s += "\n";
  }
  return s;
}

MoodleWorksheet::MoodleWorksheet(const std::vector<std::vector<std::string>>& rows,
                                 const std::string& file) {
  auto fault = [&](int row, std::string message) {
    return Error(
        Diagnostic{file, "", row, 0, Severity::kError, std::move(message), "moodle-worksheet"});
  };
  if (rows.empty()) throw fault(1, "the worksheet is empty: download it from the assignment");
  const std::vector<std::string>& header = rows.front();
  auto column = [&](std::string_view name) {
    auto it = std::find(header.begin(), header.end(), name);
    if (it != header.end()) return static_cast<std::size_t>(it - header.begin());
    throw fault(1, fmt::format("the worksheet has no \"{}\" column: use the file Moodle's "
                               "\"Download grading worksheet\" gives, with the email address "
                               "shown (Site administration > Users > Show user identity)",
                               name));
  };
  identifier = column("Identifier");
  full_name = column("Full name");
  email = column("Email address");
  grade = column("Grade");
  maximum = column("Maximum Grade");
  column("Last modified (grade)");
  maxima.assign(rows.size(), 0.0);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    int line = static_cast<int>(r + 1);
    if (rows[r].size() != header.size()) {
      throw fault(line, fmt::format("row {} has {} cells, the header {}", r + 1, rows[r].size(),
                                    header.size()));
    }
    std::string most = rows[r][maximum];
    std::replace(most.begin(), most.end(), ',', '.');  // a decimal comma
    // strtod in the C locale (Emscripten's libc++ has no floating-point std::from_chars).
    char* end = nullptr;
    double value = std::strtod(most.c_str(), &end);
    if (most.empty() || end != most.c_str() + most.size() || !(value > 0) ||
        !std::isfinite(value)) {
      throw fault(line, fmt::format("row {}'s Maximum Grade \"{}\" is not a number of points: "
                                    "raygrade fills in point grades (Grade > Type: Point)",
                                    r + 1, rows[r][maximum]));
    }
    maxima[r] = value;
  }
}

std::vector<ZipEntry> moodle_feedback_files(const std::vector<std::vector<std::string>>& rows,
                                            const std::string& file,
                                            const std::vector<StudentIdentity>& roster,
                                            const std::vector<StudentPage>& pages,
                                            std::vector<std::string>& notes) {
  MoodleWorksheet sheet(rows, file);
  std::map<std::string, std::string> email_of;  // roster id → email, in lower case
  for (const auto& who : roster) {
    if (!email_key(who.email).empty()) email_of[who.id] = email_key(who.email);
  }
  std::map<std::string, std::string> folder_of;  // email → the folder Moodle reads
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const std::string& id = rows[r][sheet.identifier];
    std::size_t digits = id.find_last_not_of("0123456789") + 1;
    if (digits == id.size()) continue;  // no participant number
    // A row without an email address is nobody's, not a roster student's who has none.
    if (email_key(rows[r][sheet.email]).empty()) continue;
    // Moodle's importer splits the folder name at '_': the name may hold none.
    std::string name = rows[r][sheet.full_name];
    std::replace_if(
        name.begin(), name.end(), [](char c) { return c == '_' || c == '/' || c == '\\'; }, ' ');
    folder_of[email_key(rows[r][sheet.email])] =
        fmt::format("{}_{}_assignfeedback_file", name, id.substr(digits));
  }
  std::vector<ZipEntry> out;
  for (const auto& page : pages) {
    auto email = email_of.find(page.student_id);
    auto folder = email == email_of.end() ? folder_of.end() : folder_of.find(email->second);
    if (folder == folder_of.end()) {
      notes.push_back(
          fmt::format("the feedback page {} is no worksheet row's: not in the zip", page.file));
      continue;
    }
    out.push_back({folder->second + "/" + page.file, page.text, false});
  }
  return out;
}

std::string RosterGradebook::moodle_worksheet(const std::vector<std::vector<std::string>>& rows,
                                              const std::string& file,
                                              std::vector<std::string>& notes) const {
  MoodleWorksheet sheet(rows, file);
  std::size_t email = sheet.email, grade = sheet.grade;
  double total = max_score().value_or(0.0);
  std::set<double> scaled;  // the Moodle maxima that differ from the assignment's points
  std::map<std::string, std::size_t> by_email;
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    if (!email_key(roster_[i].email).empty()) by_email[email_key(roster_[i].email)] = i;
  }
  std::vector<bool> has_row(roster_.size(), false);
  std::string out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::vector<std::string> cells = rows[r];
    if (r > 0) {
      auto it = by_email.find(email_key(cells[email]));
      if (it == by_email.end()) {
        notes.push_back(fmt::format("worksheet row {} ({}) is no roster student's: left as it was",
                                    r + 1, cells[email]));
      } else {
        std::size_t i = it->second;
        has_row[i] = true;
        const Handed* pick = chosen(handed_[i]);
        double score = pick ? pick->score : 0.0;
        double most = sheet.maxima[r];
        if (total > 0 && most != total) {
          // Moodle reads the grade out of its own maximum.
          score = score * most / total;
          scaled.insert(most);
        }
        cells[grade] = format_points(score);
      }
    }
    for (std::size_t c = 0; c < cells.size(); ++c) out += (c ? "," : "") + csv_field(cells[c]);
    out += "\n";
  }
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    if (!has_row[i]) {
      notes.push_back(
          fmt::format("student '{}' ({}) has no row on the worksheet: no grade for them",
                      roster_[i].id, roster_[i].email));
    }
  }
  for (double most : scaled) {
    notes.push_back(fmt::format(
        "the worksheet's Maximum Grade is {}, the assignment's {} points: each total scaled to "
        "it (to 2 decimals)",
        format_points(most), format_points(total)));
  }
  return out;
}

std::string RosterGradebook::csv() const {
  std::optional<double> max_score = this->max_score();
  std::string s = gradebook_csv_header(problem_ids_);
  for (std::size_t i = 0; i < roster_.size(); ++i) {
    const StudentIdentity& who = roster_[i];
    const Handed* pick = chosen(handed_[i]);
    // The file that counts; for a student whose every file was rejected, the last of them.
    std::string file = pick ? pick->file : handed_[i].empty() ? "" : handed_[i].back().file;
    s += csv_cell(who.name.empty() ? who.id : who.name) + "," + csv_cell(who.id) + "," +
         csv_cell(who.email) + "," + csv_cell(file);
    for (std::size_t p = 0; p < problem_ids_.size(); ++p)
      s += "," + format_points(pick ? pick->points[p] : 0.0);
    s += fmt::format(",{},{},{}\n", format_points(pick ? pick->score : 0.0),
                     max_score ? format_points(*max_score) : std::string(), csv_cell(status(i)));
  }
  return s;
}

}  // namespace raygrade
