// An assignment as numeric quiz questions with precomputed sets of numbers: what Canvas's
// formula questions (QTI 1.2, calculated_question with var_sets) and Moodle's calculated
// questions (dataset items) carry. Each set is a variant raygrade draws and solves; its answers
// are raygrade's reference answers, never the platform's own arithmetic (docs/assignments.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "assignments/assignment.h"
#include "assignments/lms_export.h"

namespace raygrade {

// A number of the statement that changes from set to set: a parameter, a component of a
// vector parameter ("d_x"), or an expression of the statement ("e1"); or the reference answer
// itself ("answer"), which the questions use as their formula so that the platform's answer
// is raygrade's. A parameter keeps its name; every name raygrade makes is the first of "answer",
// "answer_2", "answer_3", ... (and so for "e1", "s1", "d_x") that no parameter and no other
// variable of the problem has, since both platforms put a variable's value in place of its name
// wherever the name appears.
struct QuizVariable {
  std::string name;
  std::vector<double> values;  // one per set
  int decimals = 0;            // the most any value needs, up to 12
};

// How close an answer must be. kRelative: |x − a| ≤ value·|a|; kAbsolute: |x − a| ≤ value.
// A relative tolerance keeps
// raygrade's relative part and leaves out its absolute floor (1e-6 by default), which matters
// only near zero; where the platform cannot say raygrade's rule (a vector's component, whose
// relative tolerance refers to the vector's length; significant figures), the quiz takes the
// strictest error raygrade accepts in any set, so it never accepts what raygrade refuses.
struct QuizTolerance {
  enum class Kind { kRelative, kAbsolute };
  Kind kind = Kind::kRelative;
  double value = 0;
  std::string rule;  // raygrade's rule, in words: "relative 0.1%"
};

// One question: one number of the answer.
struct QuizPart {
  std::string ident;              // unique in the quiz: "variant-sphere-hits-0-t"
  std::string label;              // what is asked: "the nearest hit: t"
  std::string pointer;            // where the number is in the answer: "/hits/0/t"
  std::vector<std::size_t> sets;  // the sets that have this number (indices)
  std::vector<double> answers;    // their reference answers, in the same order
  QuizTolerance tolerance;
  double points = 0;
};

// One piece of a statement: text, or a variable's value.
struct QuizText {
  std::string text;
  std::string variable;  // when not empty, the piece is this variable
};

// One step of the worked solution, with its value as variables (one, or three for a vector):
// "t = (−b − √Δ)/(2a)" and ["s4"].
struct QuizStep {
  std::string heading;  // the part's heading, on the first step of a part
  std::string text;
  std::vector<std::string> variables;
};

struct QuizProblem {
  std::string id;
  std::string title;
  std::vector<std::string> set_keys;  // the variant key each set was drawn for
  std::vector<QuizVariable> variables;
  std::vector<QuizText> statement;
  std::vector<QuizPart> parts;
  // The worked solution, when every set's has the same steps (else empty): its values are
  // variables of their own, so that each set's solution shows that set's numbers.
  std::vector<QuizStep> steps;
  std::vector<QuizVariable> step_variables;
  // The name of the variable that holds each part's reference answer (the question's formula):
  // "answer" unless a parameter has that name.
  std::string answer_variable = "answer";
  std::vector<std::string> lost;  // what the quiz cannot carry, in sentences (in the summary)
};

struct Quiz {
  std::string id;
  std::string title;
  std::vector<QuizProblem> problems;
  // Problems left out and why, and text changed so that the files are well-formed XML.
  std::vector<std::string> notes;
};

// The variant keys of the sets: the roster's students (their student_key), else "set-1" ...
// "set-N". An assignment without per-student numbers has one set, the generic one ("").
std::vector<std::string> quiz_set_keys(const AssignmentSpec& spec, const std::string& roster,
                                       int count);

// The quiz: per problem of the assignment, the sets (duplicates of an earlier set dropped),
// the statement with its variables, and one part per number the answer form asks. A problem
// whose form asks no number (a ray tree, a yes/no) is left out with a note. Every text is as
// XML 1.0 allows it (xml_text): what was dropped or replaced is said in a note. Throws Error when
// a variant cannot be drawn or the bank is faulty.
Quiz build_quiz(const AssignmentSpec& spec, const AssignmentBank& bank,
                const std::vector<std::string>& keys);

// A number as the quiz files write it: the shortest text that reads back as the same double.
std::string quiz_number(double v);

// What a student reads of a tolerance: "within 0.1% of the right value", "within ±5.1e-05 ...".
std::string quiz_tolerance_text(const QuizTolerance& t);

// Which variant each set is: "problem,set,variant" (the key raygrade solve --student takes).
std::string quiz_sets_csv(const Quiz& quiz);
// One sentence: how many questions and sets, what was left out, and what the questions cannot
// carry (each problem's `lost`, each once, with the problems it concerns); a platform takes at
// most `max_sets` sets.
std::string quiz_summary(const Quiz& quiz, int max_sets);

}  // namespace raygrade
