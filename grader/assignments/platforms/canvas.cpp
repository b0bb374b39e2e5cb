// Canvas Classic Quizzes: a QTI 1.2 package of formula questions (calculated_question) whose
// variable sets carry raygrade's reference answers.
//
// What Canvas's QTI importer reads of a formula question (its calculated interaction):
// itemmetadata's question_type "calculated_question" and points_possible; the question text of
// presentation/material/mattext, with [name] for a variable; and in
// itemproc_extension/calculated: answer_tolerance (a number, or a percentage "0.1%"),
// formulas (decimal_places, formula), vars/var (name, scale = decimals shown, min, max) and
// var_sets/var_set (ident, var name=value ..., answer). The answer of each set is taken as
// written, so Canvas's own arithmetic and rounding never decide a student's answer.
#include "assignments/platforms/canvas.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <pugixml.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "assignments/variants.h"
#include "core/escape.h"
#include "core/name_key.h"
#include "grading/outputs.h"

namespace raygrade {
namespace {

constexpr const char* kQtiNamespace = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2";
constexpr const char* kQtiSchema = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2p1.xsd";
constexpr const char* kCpNamespace = "http://www.imsglobal.org/xsd/imscp_v1p1";
constexpr const char* kCpSchema = "http://www.imsglobal.org/xsd/imscp_v1p1.xsd";
constexpr const char* kXsi = "http://www.w3.org/2001/XMLSchema-instance";

std::string canvas_xml_text(const pugi::xml_document& doc) {
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

void canvas_field(pugi::xml_node metadata, const char* label, const std::string& entry) {
  pugi::xml_node f = metadata.append_child("qtimetadatafield");
  f.append_child("fieldlabel").text().set(label);
  f.append_child("fieldentry").text().set(entry.c_str());
}

// A tolerance as Canvas reads it: a plain decimal (an exponent would be read as a percentage's
// text), or a percentage.
std::string canvas_decimal(double v) {
  if (v == 0) return "0";
  int digits = std::clamp(17 - static_cast<int>(std::floor(std::log10(std::abs(v)))), 1, 340);
  std::string s = fmt::format("{:.{}f}", v, digits);
  // Shortest text that reads back as v, without an exponent.
  for (int d = 1; d <= digits; ++d) {
    std::string t = fmt::format("{:.{}f}", v, d);
    if (std::stod(t) == v) return t;
  }
  return s;
}

std::string canvas_tolerance(const QuizTolerance& t) {
  if (t.kind == QuizTolerance::Kind::kRelative) return quiz_number(t.value * 100) + "%";
  return canvas_decimal(t.value);
}

// The decimals Canvas shows an answer with: enough for the tolerance to tell values apart.
int canvas_answer_decimals(const QuizPart& part) {
  double smallest = 0;
  for (double a : part.answers) {
    double allowed = part.tolerance.kind == QuizTolerance::Kind::kRelative
                         ? part.tolerance.value * std::abs(a)
                         : part.tolerance.value;
    if (allowed > 0 && (smallest == 0 || allowed < smallest)) smallest = allowed;
  }
  if (smallest == 0) return 4;
  return std::clamp(static_cast<int>(std::ceil(-std::log10(smallest))) + 1, 0, 10);
}

// Text in a question's HTML: escaped, and each '[' written "<span>[</span>". Canvas puts a
// variable's value in place of every "[name]" of the stored question text (a regular expression
// per variable of the set drawn, Quizzes::Quiz#generate_submission_question), so no bracket of
// the text may be followed by a name and ']' in the HTML; an entity (&#91;) would not do, as
// the importer's HTML sanitizer writes the text out again with the bracket as a character.
std::string canvas_text(std::string_view s) {
  std::string out;
  for (char c : html_escape(s)) {
    if (c == '[') {
      out += "<span>[</span>";
    } else {
      out += c;
    }
  }
  return out;
}

std::string canvas_question_html(const QuizProblem& q, const QuizPart& part) {
  std::string statement;
  for (const QuizText& t : q.statement) {
    statement += t.variable.empty() ? canvas_text(t.text) : "[" + t.variable + "]";
  }
  return fmt::format("<p>{}</p>\n<p>Give {}.</p>\n<p>An answer {} counts as right.</p>", statement,
                     canvas_text(part.label), canvas_text(quiz_tolerance_text(part.tolerance)));
}

void canvas_item(pugi::xml_node section, const QuizProblem& q, const QuizPart& part) {
  pugi::xml_node item = section.append_child("item");
  item.append_attribute("ident") = part.ident.c_str();
  item.append_attribute("title") = fmt::format("{}: {}", q.title, part.label).c_str();
  pugi::xml_node meta = item.append_child("itemmetadata").append_child("qtimetadata");
  canvas_field(meta, "question_type", "calculated_question");
  canvas_field(meta, "points_possible", quiz_number(part.points));

  pugi::xml_node presentation = item.append_child("presentation");
  pugi::xml_node text = presentation.append_child("material").append_child("mattext");
  text.append_attribute("texttype") = "text/html";
  text.text().set(canvas_question_html(q, part).c_str());
  pugi::xml_node response = presentation.append_child("response_str");
  response.append_attribute("ident") = "response1";
  response.append_attribute("rcardinality") = "Single";
  pugi::xml_node fib = response.append_child("render_fib");
  fib.append_attribute("fibtype") = "Decimal";
  fib.append_child("response_label").append_attribute("ident") = "answer1";

  pugi::xml_node processing = item.append_child("resprocessing");
  pugi::xml_node decvar = processing.append_child("outcomes").append_child("decvar");
  decvar.append_attribute("maxvalue") = "100";
  decvar.append_attribute("minvalue") = "0";
  decvar.append_attribute("varname") = "SCORE";
  decvar.append_attribute("vartype") = "Decimal";
  pugi::xml_node right = processing.append_child("respcondition");
  right.append_attribute("title") = "correct";
  right.append_child("conditionvar").append_child("other");
  pugi::xml_node set = right.append_child("setvar");
  set.append_attribute("varname") = "SCORE";
  set.append_attribute("action") = "Set";
  set.text().set("100");
  pugi::xml_node wrong = processing.append_child("respcondition");
  wrong.append_attribute("title") = "incorrect";
  wrong.append_child("conditionvar").append_child("not").append_child("other");
  set = wrong.append_child("setvar");
  set.append_attribute("varname") = "SCORE";
  set.append_attribute("action") = "Set";
  set.text().set("0");

  pugi::xml_node calculated = item.append_child("itemproc_extension").append_child("calculated");
  calculated.append_child("answer_tolerance").text().set(canvas_tolerance(part.tolerance).c_str());
  pugi::xml_node formulas = calculated.append_child("formulas");
  formulas.append_attribute("decimal_places") = canvas_answer_decimals(part);
  // The answer is a variable of its own: the formula gives back raygrade's reference answer.
  formulas.append_child("formula").text().set(q.answer_variable.c_str());
  pugi::xml_node vars = calculated.append_child("vars");
  auto add_var = [&](const std::string& name, int scale, double lo, double hi) {
    pugi::xml_node v = vars.append_child("var");
    v.append_attribute("name") = name.c_str();
    v.append_attribute("scale") = scale;
    v.append_child("min").text().set(quiz_number(lo).c_str());
    v.append_child("max").text().set(quiz_number(hi).c_str());
  };
  for (const QuizVariable& v : q.variables) {
    std::vector<double> offered;
    for (std::size_t s : part.sets) offered.push_back(v.values[s]);
    auto [lo, hi] = std::minmax_element(offered.begin(), offered.end());
    add_var(v.name, v.decimals, *lo, *hi);
  }
  auto [lo, hi] = std::minmax_element(part.answers.begin(), part.answers.end());
  add_var(q.answer_variable, canvas_answer_decimals(part), *lo, *hi);
  pugi::xml_node sets = calculated.append_child("var_sets");
  for (std::size_t k = 0; k < part.sets.size() && k < kCanvasMaxSets; ++k) {
    std::size_t s = part.sets[k];
    pugi::xml_node vs = sets.append_child("var_set");
    vs.append_attribute("ident") = fmt::format("set-{}", s + 1).c_str();
    for (const QuizVariable& v : q.variables) {
      pugi::xml_node x = vs.append_child("var");
      x.append_attribute("name") = v.name.c_str();
      x.text().set(quiz_number(v.values[s]).c_str());
    }
    pugi::xml_node x = vs.append_child("var");
    x.append_attribute("name") = q.answer_variable.c_str();
    x.text().set(quiz_number(part.answers[k]).c_str());
    vs.append_child("answer").text().set(quiz_number(part.answers[k]).c_str());
  }
}

std::string canvas_assessment_xml(const Quiz& quiz, const std::string& ident) {
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node root = doc.append_child("questestinterop");
  root.append_attribute("xmlns") = kQtiNamespace;
  root.append_attribute("xmlns:xsi") = kXsi;
  root.append_attribute("xsi:schemaLocation") =
      fmt::format("{} {}", kQtiNamespace, kQtiSchema).c_str();
  pugi::xml_node assessment = root.append_child("assessment");
  assessment.append_attribute("ident") = ident.c_str();
  assessment.append_attribute("title") = quiz.title.c_str();
  pugi::xml_node section = assessment.append_child("section");
  section.append_attribute("ident") = "root_section";
  for (const QuizProblem& q : quiz.problems) {
    for (const QuizPart& part : q.parts) canvas_item(section, q, part);
  }
  return canvas_xml_text(doc);
}

// The package's manifest: the assessment as its one resource, and no organization (Canvas
// takes the quiz's title from the assessment).
std::string canvas_manifest_xml(const std::string& ident, const std::string& href) {
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node manifest = doc.append_child("manifest");
  manifest.append_attribute("identifier") = (ident + "-manifest").c_str();
  manifest.append_attribute("xmlns") = kCpNamespace;
  manifest.append_attribute("xmlns:xsi") = kXsi;
  manifest.append_attribute("xsi:schemaLocation") =
      fmt::format("{} {}", kCpNamespace, kCpSchema).c_str();
  manifest.append_child("organizations");
  pugi::xml_node resource = manifest.append_child("resources").append_child("resource");
  resource.append_attribute("identifier") = ident.c_str();
  resource.append_attribute("type") = "imsqti_xmlv1p2";
  resource.append_attribute("href") = href.c_str();
  resource.append_child("file").append_attribute("href") = href.c_str();
  return canvas_xml_text(doc);
}

}  // namespace

std::vector<ZipEntry> canvas_qti_files(const Quiz& quiz) {
  // An XML ident is a name: letters first, no spaces.
  std::string ident = "raygrade-" + safe_file_name(quiz.id);
  std::string href = ident + "/" + ident + ".xml";
  return {{"imsmanifest.xml", canvas_manifest_xml(ident, href), false},
          {href, canvas_assessment_xml(quiz, ident), false}};
}

namespace {

LmsPackage canvas_package(const LmsExportInput& in, const std::string& out) {
  Quiz quiz = build_quiz(*in.spec, *in.bank,
                         quiz_set_keys(*in.spec, in.roster, in.sets > 0 ? in.sets : 20));
  std::vector<ZipEntry> files = canvas_qti_files(quiz);
  LmsPackage p;
  std::string zip = safe_file_name(in.spec->id) + "-canvas-qti.zip";
  p.files.push_back({zip, zip_archive(files), false});
  for (auto& f : files) p.files.push_back({"qti/" + f.name, f.bytes, false});
  p.files.push_back({"sets.csv", quiz_sets_csv(quiz), false});
  p.next_step = fmt::format(
      "Wrote {0}/{1}: {2}. In Canvas: Settings, Import Course Content, \"QTI .zip file\", "
      "then the quiz is under Quizzes (Classic). {0}/sets.csv says which variant each set "
      "is: `raygrade solve ASSIGNMENT --student KEY` shows its worked solution.",
      out, zip, quiz_summary(quiz, kCanvasMaxSets));
  return p;
}

// Canvas's NON_ASSIGNMENT_COLUMN_HEADERS (app/models/gradebook_importer.rb): a column whose title
// contains one of them is not read as an assignment.
constexpr std::string_view kCanvasNonAssignmentWords[] = {
    "Current Score", "Current Points", "Current Grade",  "Final Score",    "Final Points",
    "Final Grade",   "Override Score", "Override Grade", "Override Status"};

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
  if (!is_column_id(digits) || title.substr(0, open).find('\n') != std::string_view::npos)
    return "";
  return std::string(digits);
}

// Canvas's gradebook importer (instructure/canvas-lms): a column whose title contains one of
// kCanvasNonAssignmentWords (case-sensitive) is dropped; a title ending in white space and
// "(digits)" is read as "Title (assignment id)" (Assignment.title_and_id), so without
// `column_id` it would grade another assignment. `column_id` must be digits.
ColumnCheck canvas_column(const std::string& title, const std::string& column_id) {
  ColumnCheck c;
  if (!column_id.empty() && !is_column_id(column_id)) {
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
  return c;
}

// Canvas matches a row by its ID (the roster's canvas_id, when it has one), SIS User ID (the
// roster's id) or SIS Login ID (the email); the row under the header gives the points possible,
// and a new column name makes a new assignment. With the assignment's id, Canvas's own
// "Title (id)": matched by the id.
std::string canvas_gradebook(const ClassRows& book, const std::string& title,
                             const std::string& column_id) {
  std::string column = column_id.empty() ? title : fmt::format("{} ({})", title, column_id);
  std::string s = "Student,ID,SIS User ID,SIS Login ID,Section," + csv_cell(column) + "\n";
  s += "    Points Possible,,,,," + (book.points ? format_points(*book.points) : "") + "\n";
  for (const ClassRow& row : book.rows) {
    const StudentIdentity& who = row.student;
    std::string name = who.name.empty() ? who.id : who.name;
    s += csv_cell(name) + "," + csv_cell(row.platform_id) + "," + csv_cell(who.id) + "," +
         csv_cell(who.email) + ",," + format_points(row.score) + "\n";
  }
  return s;
}

// A name as Canvas writes it into a file's name, as a key: case-folded and normalised
// (name_key), then without ASCII spaces and punctuation. Letters outside ASCII are kept.
std::string canvas_name_key(std::string_view s) {
  std::string out;
  for (unsigned char c : name_key(s)) {
    if (std::isalnum(c) || c >= 0x80) out += static_cast<char>(c);
  }
  return out;
}

// A roster student's name as Canvas writes it, as a key: Canvas writes the last name first, and a
// roster name's last word is taken as the last name.
std::string canvas_roster_key(const StudentIdentity& s) {
  std::string name = trimmed(s.name);
  std::size_t cut = name.rfind(' ');
  return canvas_name_key(cut == std::string::npos ? name
                                                  : name.substr(cut + 1) + name.substr(0, cut));
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
  for (const auto& id : r.platform_ids) by_id = by_id || !id.empty();
  if (by_id) {
    std::size_t i = 0;
    return only_roster_entry(
        roster, [&](const StudentIdentity&) { return r.platform_ids[i++] == n.platform_id; },
        fmt::format("Canvas user {} ({})", n.platform_id, n.name), problem);
  }
  // A name with no letter or digit is nobody's (its key is empty).
  std::string want = canvas_name_key(n.name);
  std::size_t i = 0;
  return only_roster_entry(
      roster, [&](const StudentIdentity&) { return !want.empty() && r.name_keys[i++] == want; },
      fmt::format("Canvas's '{}' (user {}; the roster has no canvas_id column to find it by)",
                  n.name, n.platform_id),
      problem);
}

}  // namespace

LmsExport Canvas::lms_export() {
  LmsExport e;
  e.summary =
      "a QTI 1.2 package of Classic Quizzes formula questions, one per number asked, with "
      "raygrade's variants and reference answers as the variable sets";
  e.takes_roster = true;
  e.roster_help = "one set of numbers per roster student";
  e.make = &canvas_package;
  e.max_sets = kCanvasMaxSets;
  return e;
}

GradebookLayout Canvas::gradebook() {
  return {"csv-canvas",
          "with --roster: Canvas's gradebook import (a Points Possible row)",
          "--canvas-assignment-id",
          "the Canvas id of the assignment (its page's address ends in it); the column is then "
          "titled \"Title (id)\", which Canvas's import matches by the id",
          &canvas_column,
          &canvas_gradebook};
}

BulkFormat Canvas::bulk() {
  BulkFormat f;
  f.naming = "<lastfirst>_<user id>_<submission id>_<file>";
  // Moodle never writes a name Canvas's naming fits (its participant number is followed by
  // "_assignsubmission", never by a number): a zip with any file this naming fits is Canvas's.
  f.claims_zip = true;
  f.parse = &parse_canvas;
  f.roster_key = &canvas_roster_key;
  f.owner = &canvas_owner;
  return f;
}

}  // namespace raygrade
