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
#include <fmt/format.h>

#include <algorithm>
#include <pugixml.hpp>
#include <sstream>

#include "assignments/quiz_export.h"
#include "core/escape.h"

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

}  // namespace raygrade
