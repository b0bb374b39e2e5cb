// Moodle XML: one calculated question per number of an answer, whose dataset items are
// raygrade's sets.
//
// What Moodle's XML importer reads of a calculated question: name, questiontext,
// generalfeedback, defaultgrade, penalty, synchronize, single, answernumbering, shuffleanswers;
// per answer (fraction) its text (a formula of {wildcards}), tolerance, tolerancetype (1
// relative, 2 nominal, 3 geometric), correctanswerformat (1 decimals, 2 significant figures),
// correctanswerlength and feedback; unitgradingtype, unitpenalty, showunits, unitsleft; and
// dataset_definitions/dataset_definition with status, name, type, distribution, minimum,
// maximum, decimals, itemcount, dataset_items/dataset_item (number, value) and
// number_of_items. Moodle picks one item number per attempt and puts each dataset's value of
// that item in place of its {moodle_wildcard}, in the question text and in the general feedback.
#include "assignments/platforms/moodle.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <pugixml.hpp>
#include <regex>
#include <sstream>

#include "assignments/roster.h"
#include "assignments/variants.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "core/name_key.h"
#include "grading/outputs.h"

namespace raygrade {
namespace {

void moodle_text(pugi::xml_node parent, const char* name, const std::string& text,
                 const char* format = nullptr) {
  pugi::xml_node n = parent.append_child(name);
  if (format) n.append_attribute("format") = format;
  n.append_child("text").text().set(text.c_str());
}

void moodle_value(pugi::xml_node parent, const char* name, const std::string& value) {
  parent.append_child(name).text().set(value.c_str());
}

std::string moodle_wildcard(const std::string& name) { return "{" + name + "}"; }

// Text in a question's HTML: escaped, with '{' and '}' as &#123; and &#125;. Moodle replaces
// every {=formula} and every {name} of a dataset in the stored text before it formats it
// (qtype_calculated_variable_substituter::replace_expressions_in_text: a regular expression for
// the formulas, str_replace for the names), so no brace of the text may be one; the browser
// shows the entity as the brace.
std::string moodle_text_html(std::string_view s) { return html_escape_braces(s); }

std::string moodle_question_html(const QuizProblem& q, const QuizPart& part) {
  std::string statement;
  for (const QuizText& t : q.statement) {
    statement += t.variable.empty() ? moodle_text_html(t.text) : moodle_wildcard(t.variable);
  }
  return fmt::format("<p>{}</p>\n<p>Give {}.</p>\n<p>An answer {} counts as right.</p>", statement,
                     moodle_text_html(part.label),
                     moodle_text_html(quiz_tolerance_text(part.tolerance)));
}

// The worked solution with each set's own numbers, where every set's solution has the same
// steps; else where to find it.
std::string moodle_feedback_html(const QuizProblem& q, const QuizPart& part) {
  std::string out = fmt::format("<p>The answer: {}.</p>\n", moodle_wildcard(q.answer_variable));
  if (q.steps.empty()) {
    return out +
           "<p>The worked solution differs from set to set: `raygrade solve` with the "
           "set's variant (sets.csv) shows it.</p>";
  }
  out += "<p>The worked solution:</p>\n";
  bool open = false;
  for (const QuizStep& s : q.steps) {
    if (!s.heading.empty()) {
      if (open) out += "</ul>\n";
      out += fmt::format("<p>{}</p>\n", moodle_text_html(s.heading));
      open = false;
    }
    if (!open) out += "<ul>\n";
    open = true;
    std::string value;
    if (s.variables.size() == 1) {
      value = moodle_wildcard(s.variables[0]);
    } else {
      value = fmt::format("({}, {}, {})", moodle_wildcard(s.variables[0]),
                          moodle_wildcard(s.variables[1]), moodle_wildcard(s.variables[2]));
    }
    out += fmt::format("<li>{} = {}</li>\n", moodle_text_html(s.text), value);
  }
  if (open) out += "</ul>";
  (void)part;
  return out;
}

void moodle_dataset(pugi::xml_node definitions, const std::string& name,
                    const std::vector<double>& values, int decimals) {
  pugi::xml_node d = definitions.append_child("dataset_definition");
  moodle_text(d, "status", "private");
  moodle_text(d, "name", name);
  moodle_value(d, "type", "calculated");
  moodle_text(d, "distribution", "uniform");
  auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  moodle_text(d, "minimum", quiz_number(*lo));
  moodle_text(d, "maximum", quiz_number(*hi));
  moodle_text(d, "decimals", std::to_string(decimals));
  moodle_value(d, "itemcount", std::to_string(values.size()));
  pugi::xml_node items = d.append_child("dataset_items");
  for (std::size_t i = 0; i < values.size(); ++i) {
    pugi::xml_node item = items.append_child("dataset_item");
    moodle_value(item, "number", std::to_string(i + 1));
    moodle_value(item, "value", quiz_number(values[i]));
  }
  moodle_value(d, "number_of_items", std::to_string(values.size()));
}

void moodle_question(pugi::xml_node quiz, const QuizProblem& q, const QuizPart& part) {
  std::size_t count = std::min<std::size_t>(part.sets.size(), kMoodleMaxSets);
  pugi::xml_node question = quiz.append_child("question");
  question.append_attribute("type") = "calculated";
  moodle_text(question, "name", fmt::format("{}: {}", q.title, part.label));
  moodle_text(question, "questiontext", moodle_question_html(q, part), "html");
  moodle_text(question, "generalfeedback", moodle_feedback_html(q, part), "html");
  moodle_value(question, "defaultgrade", quiz_number(part.points));
  moodle_value(question, "penalty", "0");
  moodle_value(question, "hidden", "0");
  moodle_value(question, "idnumber", part.ident);
  moodle_value(question, "synchronize", "0");
  moodle_value(question, "single", "0");
  moodle_value(question, "answernumbering", "abc");
  moodle_value(question, "shuffleanswers", "0");

  pugi::xml_node answer = question.append_child("answer");
  answer.append_attribute("fraction") = "100";
  // The answer is a moodle_wildcard of its own: Moodle's formula gives back raygrade's answer.
  answer.append_child("text").text().set(moodle_wildcard(q.answer_variable).c_str());
  bool relative = part.tolerance.kind == QuizTolerance::Kind::kRelative;
  moodle_value(answer, "tolerance", quiz_number(part.tolerance.value));
  moodle_value(answer, "tolerancetype", relative ? "1" : "2");
  // Shown to students as the right answer: significant figures enough for the tolerance.
  moodle_value(answer, "correctanswerformat", "2");
  moodle_value(answer, "correctanswerlength", "6");
  moodle_text(answer, "feedback", "", "html");

  moodle_value(question, "unitgradingtype", "0");
  moodle_value(question, "unitpenalty", "0.1");
  moodle_value(question, "showunits", "3");
  moodle_value(question, "unitsleft", "0");

  pugi::xml_node definitions = question.append_child("dataset_definitions");
  auto offered = [&](const std::vector<double>& values) {
    std::vector<double> out;
    for (std::size_t k = 0; k < count; ++k) out.push_back(values[part.sets[k]]);
    return out;
  };
  for (const QuizVariable& v : q.variables)
    moodle_dataset(definitions, v.name, offered(v.values), v.decimals);
  std::vector<double> answers(part.answers.begin(),
                              part.answers.begin() + static_cast<long>(count));
  moodle_dataset(definitions, q.answer_variable, answers, 12);
  for (const QuizVariable& v : q.step_variables) {
    moodle_dataset(definitions, v.name, offered(v.values), std::min(v.decimals, 6));
  }
}

}  // namespace

std::string moodle_xml(const Quiz& quiz) {
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node root = doc.append_child("quiz");
  // A category of its own, so that a random question can draw from the assignment alone.
  pugi::xml_node category = root.append_child("question");
  category.append_attribute("type") = "category";
  moodle_text(category, "category", "$course$/top/raygrade/" + quiz.id);
  for (const QuizProblem& q : quiz.problems) {
    for (const QuizPart& part : q.parts) moodle_question(root, q, part);
  }
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

namespace {

LmsPackage moodle_package(const LmsExportInput& in, const std::string& out) {
  Quiz quiz = build_quiz(*in.spec, *in.bank,
                         quiz_set_keys(*in.spec, in.roster, in.sets > 0 ? in.sets : 20));
  LmsPackage p;
  std::string file = safe_file_name(in.spec->id) + "-moodle.xml";
  p.files.push_back({file, moodle_xml(quiz), false});
  p.files.push_back({"sets.csv", quiz_sets_csv(quiz), false});
  p.next_step = fmt::format(
      "Wrote {0}/{1}: {2}. In Moodle: Question bank, Import, format \"Moodle XML\"; the "
      "questions are in the category raygrade/{3}. {0}/sets.csv says which variant each "
      "dataset item is.",
      out, file, quiz_summary(quiz, kMoodleMaxSets), quiz.id);
  return p;
}

// The columns of Moodle's grading worksheet that raygrade reads, and each row's "Maximum Grade"
// (Moodle writes it as "5.00", or "5,00" in a language with a decimal comma). Throws Error
// naming `file` and the row when a column Moodle needs is missing, a row is cut short, or a
// maximum is not a positive number of points (an assignment graded on a scale).
struct MoodleWorksheet {
  MoodleWorksheet(const std::vector<std::vector<std::string>>& rows, const std::string& file);
  std::size_t identifier = 0, full_name = 0, email = 0, grade = 0, maximum = 0;
  std::vector<double> maxima;  // per row; the header's is 0
};

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

// Moodle's "Upload multiple feedback files in a zip": each page in the folder Moodle's importer
// reads, "<full name>_<participant number>_assignfeedback_file", the participant number taken
// from the worksheet row whose "Email address" is the page's student's on the roster. A page
// of no worksheet row is left out and listed in `notes`.
std::vector<ZipEntry> moodle_feedback_files(const Worksheet& given,
                                            const std::vector<StudentIdentity>& roster,
                                            const std::vector<StudentPage>& pages,
                                            std::vector<std::string>& notes) {
  const auto& rows = given.rows;
  MoodleWorksheet sheet(rows, given.file);
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

// Moodle's offline grading worksheet as downloaded from the assignment, each row's "Grade" set to
// the total of the roster student whose email is its "Email address", out of the row's "Maximum
// Grade" (scaled from the assignment's points when they differ, and said once in `notes`); every
// other cell as downloaded (a status can name another student, so "Feedback comments" is not
// written), since Moodle matches a row by its "Identifier" and skips one whose "Last modified
// (grade)" is older than its own record. A row of no roster student stays as downloaded, and is
// listed in `notes`, as is each roster student without a row.
std::string moodle_worksheet(const ClassRows& book, const Worksheet& given,
                             std::vector<std::string>& notes) {
  const auto& rows = given.rows;
  MoodleWorksheet sheet(rows, given.file);
  std::size_t email = sheet.email, grade = sheet.grade;
  double total = book.points.value_or(0.0);
  std::set<double> scaled;  // the Moodle maxima that differ from the assignment's points
  std::map<std::string, std::size_t> by_email;
  for (std::size_t i = 0; i < book.rows.size(); ++i) {
    const StudentIdentity& who = book.rows[i].student;
    if (!email_key(who.email).empty()) by_email[email_key(who.email)] = i;
  }
  std::vector<bool> has_row(book.rows.size(), false);
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
        double score = book.rows[i].score;
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
  for (std::size_t i = 0; i < book.rows.size(); ++i) {
    if (!has_row[i]) {
      const StudentIdentity& who = book.rows[i].student;
      notes.push_back(fmt::format(
          "student '{}' ({}) has no row on the worksheet: no grade for them", who.id, who.email));
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

// Moodle's grading worksheet as downloaded (UTF-8, a byte-order mark allowed), refused before
// anything is graded when Moodle could not read it back.
std::vector<std::vector<std::string>> read_moodle_worksheet(const std::string& path) {
  std::optional<std::string> text = read_whole_file(path);
  if (!text) {
    throw Error(Diagnostic{path, "", 0, 0, Severity::kError, "cannot read the worksheet",
                           "moodle-worksheet"});
  }
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text->starts_with(kBom)) text->erase(0, kBom.size());
  std::vector<std::vector<std::string>> rows = csv_rows(*text, path);
  MoodleWorksheet check(rows, path);
  return rows;
}

// Moodle's grade import from CSV: map "Email address" to the user's email, and the grade column
// to the assignment's grade item.
std::string moodle_gradebook(const ClassRows& book, const std::string& title,
                             const std::string& /*column_id*/) {
  std::string s = "ID number,Full name,Email address," + csv_cell(title) + "\n";
  for (const ClassRow& row : book.rows) {
    const StudentIdentity& who = row.student;
    std::string name = who.name.empty() ? who.id : who.name;
    s += csv_cell(who.id) + "," + csv_cell(name) + "," + csv_cell(who.email) + "," +
         format_points(row.score) + "\n";
  }
  return s;
}

// Moodle's grade import reads any title.
ColumnCheck moodle_column(const std::string& /*title*/, const std::string& /*column_id*/) {
  return {};
}

// A roster student's name as Moodle's naming is matched: Moodle writes '_' in a name as a space.
std::string moodle_roster_key(const StudentIdentity& s) {
  std::string name = s.name;
  std::replace(name.begin(), name.end(), '_', ' ');
  return name_key(trimmed(name));
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
  if (r.worksheet && !r.worksheet->rows.empty()) {
    const auto& rows = r.worksheet->rows;
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
            n.platform_id, n.name, r.worksheet->file);
        return nullptr;
      }
      return only_roster_entry(
          roster, [&](const StudentIdentity& s) { return email_key(s.email) == mail; },
          fmt::format("Moodle participant {} ({}, {} on the worksheet)", n.platform_id, n.name,
                      rows[i][email]),
          problem);
    }
    problem = fmt::format("Moodle participant {} ({}) has no row on the worksheet {}",
                          n.platform_id, n.name, r.worksheet->file);
    return nullptr;
  }
  std::string want = name_key(trimmed(n.name));
  std::size_t i = 0;
  return only_roster_entry(
      roster, [&](const StudentIdentity&) { return !want.empty() && r.name_keys[i++] == want; },
      fmt::format("Moodle's '{}' (participant {}; without --moodle-worksheet the full name finds "
                  "the student)",
                  n.name, n.platform_id),
      problem);
}

}  // namespace

LmsExport Moodle::lms_export() {
  LmsExport e;
  e.summary =
      "Moodle XML: a calculated question per number asked, with raygrade's variants and "
      "reference answers as the dataset items, and the worked solution as general feedback";
  e.takes_roster = true;
  e.roster_help = "one set of numbers per roster student";
  e.make = &moodle_package;
  e.max_sets = kMoodleMaxSets;
  return e;
}

GradebookLayout Moodle::gradebook() {
  return {"csv-moodle",
          "with --roster: Moodle's grade import from CSV, matched by email",
          "",
          "",
          &moodle_column,
          &moodle_gradebook};
}

BulkFormat Moodle::bulk() {
  BulkFormat f;
  f.naming = "<full name>_<participant>_assignsubmission_file/<file>";
  f.parse = &parse_moodle;
  f.roster_key = &moodle_roster_key;
  f.owner = &moodle_owner;
  return f;
}

PlatformWorksheet Moodle::worksheet() {
  return {"--moodle-worksheet",
          "the grading worksheet downloaded from the Moodle assignment; with --format "
          "csv-moodle the gradebook is that worksheet with each student's grade filled in, with "
          "--format html --out DIR the pages also go into moodle-feedback.zip for Moodle's bulk "
          "feedback upload",
          &read_moodle_worksheet,
          &moodle_worksheet,
          &moodle_feedback_files,
          "moodle-feedback.zip"};
}

}  // namespace raygrade
