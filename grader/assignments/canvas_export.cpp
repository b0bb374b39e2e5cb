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
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <pugixml.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "assignments/quiz_export.h"
#include "core/escape.h"

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

std::string quiz_sets_csv(const Quiz& quiz) {
  std::string out = "problem,set,variant\n";
  for (const QuizProblem& q : quiz.problems) {
    for (std::size_t s = 0; s < q.set_keys.size(); ++s) {
      out += fmt::format("{},set-{},{}\n", csv_cell(q.id), s + 1, csv_cell(q.set_keys[s]));
    }
  }
  return out;
}

std::string quiz_summary(const Quiz& quiz, int max_sets) {
  std::size_t questions = 0, sets = 0;
  bool cut = false;
  for (const QuizProblem& q : quiz.problems) {
    questions += q.parts.size();
    sets = std::max(sets, q.set_keys.size());
    cut = cut || q.set_keys.size() > static_cast<std::size_t>(max_sets);
  }
  std::string out =
      fmt::format("{} questions from {} problems, up to {} sets of numbers each", questions,
                  quiz.problems.size(), std::min<std::size_t>(sets, max_sets));
  if (cut) out += fmt::format(" (the platform takes at most {}; the first are kept)", max_sets);
  for (const std::string& n : quiz.notes) out += "; " + n;
  // What the questions cannot carry: each sentence once, with the problems it concerns.
  std::vector<std::pair<std::string, std::vector<std::string>>> lost;
  for (const QuizProblem& q : quiz.problems) {
    for (const std::string& sentence : q.lost) {
      auto it = std::find_if(lost.begin(), lost.end(),
                             [&](const auto& l) { return l.first == sentence; });
      if (it == lost.end()) it = lost.insert(lost.end(), {sentence, {}});
      if (it->second.empty() || it->second.back() != q.id) it->second.push_back(q.id);
    }
  }
  for (const auto& [sentence, ids] : lost) {
    std::string which;
    if (ids.size() == quiz.problems.size() && ids.size() > 1) {
      which = "every problem asked";
    } else {
      for (const std::string& id : ids) which += (which.empty() ? "" : ", ") + id;
    }
    out += fmt::format("; not carried: {} ({})", sentence, which);
  }
  return out;
}

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

}  // namespace raygrade
