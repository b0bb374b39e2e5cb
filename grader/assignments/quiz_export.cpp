// The sets, statements and numeric parts of an assignment's quiz questions, shared by the Canvas
// and Moodle exports.
#include "assignments/quiz_export.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "assignments/answer_form.h"
#include "assignments/roster.h"
#include "assignments/variants.h"
#include "core/escape.h"
#include "derivation/expr.h"
#include "grading/grade.h"
#include "grading/tolerance.h"
#include "kinds/fields/field_type.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

// The decimals a value needs, up to 12 (a parameter's value is written with few).
int decimals_needed(double v) {
  for (int d = 0; d < 12; ++d) {
    double scaled = v * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) <= 1e-9 * std::max(1.0, std::abs(scaled))) return d;
  }
  return 12;
}

// A variable's values are known for every set; its decimals are the most any value needs.
QuizVariable make_variable(std::string name, std::vector<double> values) {
  QuizVariable v{std::move(name), std::move(values), 0};
  for (double x : v.values) v.decimals = std::max(v.decimals, decimals_needed(x));
  return v;
}

const char* component_name(int c) { return c == 0 ? "x" : c == 1 ? "y" : "z"; }

// The names of a problem's variables: the parameters' own, taken first, and each name raygrade
// makes the first of "wanted", "wanted_2", "wanted_3", ... that is not taken yet. A name must
// start with a letter (Moodle's wildcards do): a parameter named "_a" is written "v_a".
class QuizNames {
 public:
  explicit QuizNames(const Problem& base) {
    if (base.parameters) {
      for (const Parameter& p : base.parameters->parameters) taken_.insert(p.name);
    }
  }
  std::string parameter(const std::string& name) {
    if (std::isalpha(static_cast<unsigned char>(name.front()))) return name;
    return make("v" + name);
  }
  std::string make(const std::string& wanted) {
    if (taken_.insert(wanted).second) return wanted;
    for (int k = 2;; ++k) {
      std::string name = fmt::format("{}_{}", wanted, k);
      if (taken_.insert(name).second) return name;
    }
  }

 private:
  std::set<std::string> taken_;
};

// The statement, with a variable for each "{expression}" whose value differs between sets
// (a vector parameter: one per component). A problem without parameters is its own text.
void statement_of(const Problem& base, const std::vector<const Problem*>& sets, QuizNames& names_of,
                  QuizProblem& q) {
  if (!base.parameters || base.parameters->empty() || !base.template_json ||
      !base.template_json->contains("statement")) {
    q.statement.push_back({base.statement, ""});
    return;
  }
  Cursor c(base.template_file, base.template_json, base.path);
  Cursor text = c.at("statement");
  std::map<std::string, std::vector<std::string>> named;  // expression → its variables
  int expressions = 0;
  for (const TextPiece& piece : split_text(text.string(), text)) {
    if (!piece.expression) {
      q.statement.push_back({piece.text, ""});
      continue;
    }
    std::string expr = trimmed(piece.text);
    auto found = named.find(expr);
    if (found == named.end()) {
      std::vector<json> values;
      values.reserve(sets.size());
      for (const Problem* s : sets) {
        values.push_back(evaluate_expression(expr, *base.parameters, s->values, text));
      }
      // A parameter keeps its name; any other expression is e1, e2, ...
      bool plain =
          std::any_of(base.parameters->parameters.begin(), base.parameters->parameters.end(),
                      [&](const Parameter& p) { return p.name == expr; });
      std::string name = plain ? expr : fmt::format("e{}", ++expressions);
      std::vector<std::string> names;
      if (values.front().is_array()) {
        for (int k = 0; k < 3; ++k) {
          std::vector<double> component;
          component.reserve(values.size());
          for (const json& v : values) component.push_back(v.at(static_cast<std::size_t>(k)));
          names.push_back(names_of.make(fmt::format("{}_{}", name, component_name(k))));
          q.variables.push_back(make_variable(names.back(), std::move(component)));
        }
      } else {
        std::vector<double> scalar;
        scalar.reserve(values.size());
        for (const json& v : values) scalar.push_back(v.get<double>());
        names.push_back(plain ? names_of.parameter(name) : names_of.make(name));
        q.variables.push_back(make_variable(names.back(), std::move(scalar)));
      }
      found = named.emplace(expr, std::move(names)).first;
    }
    const auto& names = found->second;
    if (names.size() == 3) {
      q.statement.push_back({"(", ""});
      for (int k = 0; k < 3; ++k) {
        q.statement.push_back({"", names[static_cast<std::size_t>(k)]});
        if (k < 2) q.statement.push_back({", ", ""});
      }
      q.statement.push_back({")", ""});
    } else {
      q.statement.push_back({"", names.front()});
    }
  }
}

// One number the form asks, before its answers are looked up.
struct Asked {
  std::string part;  // the graded part it belongs to ("t", "point")
  std::string label;
  std::string pointer;  // in the answer
  bool component = false;
};

std::string ordinal_hit(std::size_t i, std::size_t count) {
  if (count == 1) return "the hit";
  if (i == 0) return "the nearest hit (smallest t)";
  return fmt::format("hit {} in order of t", i + 1);
}

// The numbers the form asks, with the largest count of hits or rows any set's answer has.
std::vector<Asked> asked_numbers(const json& form, const std::vector<json>& answers,
                                 std::vector<std::string>& lost) {
  std::vector<Asked> out;
  auto add_number_or_vector = [&](const json& f, const std::string& part, const std::string& label,
                                  const std::string& pointer) {
    if (field_type_of(f).value == FieldValue::kNumber) {
      out.push_back({part, label, pointer, false});
    } else {
      for (int k = 0; k < 3; ++k) {
        out.push_back({part, fmt::format("the {} component of {}", component_name(k), label),
                       fmt::format("{}/{}", pointer, k), true});
      }
    }
  };
  for (const json& f : form["fields"]) {
    const FieldTypeEntry& type = field_type_of(f);
    std::string key = f["key"], label = f.value("label", key);
    // Inside a sentence: "the z component of the refracted direction".
    if (!label.empty() && label[0] >= 'A' && label[0] <= 'Z')
      label[0] = static_cast<char>(label[0] - 'A' + 'a');
    std::string part = key.substr(0, key.find('/'));
    if (type.shape == FieldShape::kOne && type.numeric()) {
      add_number_or_vector(f, part, label, "/" + key);
    } else if (type.shape == FieldShape::kOpenTable) {
      std::size_t count = 0;
      for (const json& a : answers) {
        json::json_pointer at("/" + key);
        if (a.contains(at) && a[at].is_array()) count = std::max(count, a[at].size());
      }
      for (std::size_t i = 0; i < count; ++i) {
        for (const json& c : f["columns"]) {
          std::string column = c["key"];
          add_number_or_vector(
              c, column, fmt::format("{} of {}", c.value("label", column), ordinal_hit(i, count)),
              fmt::format("/{}/{}/{}", key, i, column));
        }
      }
      if (count > 1 || f.value("label", "").find("any order") != std::string::npos) {
        lost.emplace_back("raygrade takes the hits in any order, the quiz asks them in order of t");
      }
    } else if (type.shape == FieldShape::kFixedRows) {
      // Each row is the answer's item whose fixed keys are the row's.
      const json& first = answers.front();
      json::json_pointer at("/" + key);
      for (const json& r : f["rows"]) {
        std::optional<std::size_t> index;
        if (first.contains(at) && first[at].is_array()) {
          for (std::size_t i = 0; i < first[at].size(); ++i) {
            bool same = true;
            for (const auto& [k, v] : r["fixed"].items()) {
              if (!first[at][i].contains(k) || first[at][i][k] != v) same = false;
            }
            if (same) index = i;
          }
        }
        if (!index) continue;
        for (const json& c : f["columns"]) {
          if (!field_type_of(c).numeric()) continue;
          std::string column = c["key"];
          add_number_or_vector(
              c, part, fmt::format("{}: {}", r.value("label", ""), c.value("label", column)),
              fmt::format("/{}/{}/{}", key, *index, column));
        }
      }
    } else {
      lost.push_back(fmt::format("\"{}\" is not a number ({}): not asked", label, type.name));
    }
  }
  return out;
}

// The quiz's tolerance for one number: raygrade's own rule where the platform can say it,
// else the strictest error raygrade accepts in any set.
QuizTolerance tolerance_of(const Tolerance& t, const std::vector<double>& answers,
                           const std::vector<double>& scales, bool component) {
  QuizTolerance q;
  q.rule = describe(t);
  // raygrade's relative rule for a number of its own: rtol·|a| + atol. The platforms'
  // relative tolerance is rtol·|a|: the same rule without the absolute floor, which only
  // matters for an answer near zero (where the quiz takes an absolute tolerance instead).
  bool relative = t.mode == ToleranceMode::kRelAbs && t.rtol > 0 && !component;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (answers[i] == 0 || scales[i] != std::abs(answers[i])) relative = false;
  }
  if (relative) {
    q.kind = QuizTolerance::Kind::kRelative;
    q.value = t.rtol;
    return q;
  }
  std::vector<double> allowed;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    allowed.push_back(allowed_error(answers[i], scales[i], t));
  }
  q.kind = QuizTolerance::Kind::kAbsolute;
  auto [lo, hi] = std::minmax_element(allowed.begin(), allowed.end());
  // To 12 significant figures (0.51·10⁻⁴ is written 5.1e-05, not 5.1000000000000006e-05),
  // never above the error raygrade accepts: half a unit of the 12th figure is at most 5e-12
  // of the value, so lowering it by 1e-11 first keeps the rounded value below.
  q.value = std::stod(fmt::format("{:.12g}", *lo));
  if (q.value > *lo) q.value = std::stod(fmt::format("{:.12g}", *lo * (1 - 1e-11)));
  return q;
}

// The worked solution's steps with their values as variables s1, s2, ..., when every set's
// derivation has the same steps in the same order.
void solution_steps(const std::vector<const Problem*>& sets, QuizNames& names_of, QuizProblem& q) {
  std::vector<std::vector<SolutionPart>> derived;
  derived.reserve(sets.size());
  for (const Problem* s : sets) derived.push_back(s->task->derive(s->method));
  auto shape = [](const std::vector<SolutionPart>& parts) {
    std::vector<std::string> names;
    for (const auto& part : parts) {
      for (const Step& step : part.derivation.steps) {
        names.push_back(fmt::format("{}:{}", step.name, static_cast<int>(step.value.kind)));
      }
    }
    return names;
  };
  auto first = shape(derived.front());
  for (const auto& d : derived) {
    if (shape(d) != first) return;
  }
  int n = 0;
  const auto& parts = derived.front();
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Derivation& d = parts[p].derivation;
    for (std::size_t k = 0; k < d.steps.size(); ++k) {
      const Step& step = d.steps[k];
      if (step.value.kind != Value::Kind::kScalar && step.value.kind != Value::Kind::kVector) {
        continue;
      }
      QuizStep out;
      if (k == 0) out.heading = parts[p].heading.empty() ? d.title : parts[p].heading;
      out.text = to_text(step.symbol);
      if (!step.given && !step.formula.empty()) out.text += " = " + to_text(step.formula);
      int components = step.value.kind == Value::Kind::kScalar ? 1 : 3;
      for (int c = 0; c < components; ++c) {
        std::vector<double> values;
        for (const auto& other : derived) {
          const Value& v = other[p].derivation.steps[k].value;
          values.push_back(components == 1 ? v.scalar : v.vector[c]);
        }
        out.variables.push_back(names_of.make(fmt::format("s{}", ++n)));
        q.step_variables.push_back(make_variable(out.variables.back(), std::move(values)));
      }
      q.steps.push_back(std::move(out));
    }
  }
}

// The problem's text as XML 1.0 allows it (xml_text); returns how many characters were dropped
// or replaced.
std::size_t well_formed_text(QuizProblem& q) {
  std::size_t changed = 0;
  auto clean = [&changed](std::string& s) {
    std::size_t n = 0;
    s = xml_text(s, &n);
    changed += n;
  };
  clean(q.id);
  clean(q.title);
  for (QuizText& t : q.statement) clean(t.text);
  for (QuizPart& p : q.parts) clean(p.label);
  for (QuizStep& s : q.steps) {
    clean(s.heading);
    clean(s.text);
  }
  for (std::string& l : q.lost) clean(l);
  return changed;
}

std::string xml_note(std::string_view what, std::size_t changed) {
  return fmt::format(
      "{}: {} character{} XML does not allow (control characters, ill-formed UTF-8, U+FFFE, "
      "U+FFFF) or that reorder text (bidi controls) dropped or replaced with U+FFFD",
      what, changed, changed == 1 ? "" : "s");
}

}  // namespace

std::string quiz_number(double v) { return fmt::format("{}", v); }

std::string quiz_tolerance_text(const QuizTolerance& t) {
  if (t.kind == QuizTolerance::Kind::kRelative) {
    return fmt::format("within {}% of the right value", quiz_number(t.value * 100));
  }
  return fmt::format("within ±{} of the right value", quiz_number(t.value));
}

std::vector<std::string> quiz_set_keys(const AssignmentSpec& spec, const std::string& roster,
                                       int count) {
  if (!spec.per_student) return {""};
  std::vector<std::string> keys;
  if (!roster.empty()) {
    for (const StudentIdentity& s : load_roster(roster)) keys.push_back(student_key(s));
    return keys;
  }
  for (int i = 1; i <= count; ++i) keys.push_back(fmt::format("set-{}", i));
  return keys;
}

Quiz build_quiz(const AssignmentSpec& spec, const AssignmentBank& bank,
                const std::vector<std::string>& keys) {
  Quiz quiz;
  std::size_t in_id = 0, in_title = 0;
  quiz.id = xml_text(spec.id, &in_id);
  quiz.title = xml_text(spec.title.empty() ? spec.id : spec.title, &in_title);
  if (in_id + in_title > 0) {
    quiz.notes.push_back(xml_note("the assignment's id and title", in_id + in_title));
  }
  // Every key's problems, drawn once.
  std::vector<std::vector<Problem>> drawn;
  drawn.reserve(keys.size());
  for (const std::string& key : keys) drawn.push_back(student_problems(spec, bank.problems, key));

  for (std::size_t i = 0; i < spec.problems.size(); ++i) {
    const Problem& base = *bank.problems[i];
    QuizProblem q;
    q.id = base.id;
    q.title = base.title.empty() ? base.id : base.title;
    // The sets: the keys' variants, each set of values once.
    std::vector<const Problem*> sets;
    std::map<std::string, bool> seen;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const Problem& p = drawn[k][i];
      if (!seen.emplace(json(p.values).dump(), true).second) continue;
      sets.push_back(&p);
      q.set_keys.push_back(keys[k]);
    }
    QuizNames names_of(base);
    statement_of(base, sets, names_of, q);
    q.answer_variable = names_of.make("answer");

    json form = answer_form(*sets.front());
    std::vector<json> answers;
    answers.reserve(sets.size());
    for (const Problem* s : sets) answers.push_back(s->task->answer());
    std::vector<Asked> asked = asked_numbers(form, answers, q.lost);
    if (asked.empty()) {
      quiz.notes.push_back(
          xml_text(fmt::format("{} is left out: its answer form asks no number ({})", base.id,
                               q.lost.empty() ? std::string("no input") : q.lost.front())));
      continue;
    }

    Grader grader(*sets.front());
    TolerancePolicy policy = read_tolerance_policy(*sets.front());
    const AssignmentProblem& ap = spec.problems[i];
    double total = ap.points ? *ap.points : grader.max_score();
    std::map<std::string, int> per_part;
    for (const Asked& a : asked) ++per_part[a.part];
    double weights = 0;
    for (const auto& [part, n] : per_part) weights += grader.part_points(part);

    std::map<std::string, int> idents;
    for (const Asked& a : asked) {
      QuizPart part;
      std::string ident = safe_file_name(fmt::format("{}{}", base.id, a.pointer));
      std::replace(ident.begin(), ident.end(), '/', '-');
      part.ident = ++idents[ident] > 1 ? fmt::format("{}-{}", ident, idents[ident]) : ident;
      part.label = a.label;
      part.pointer = a.pointer;
      std::vector<double> scales;
      json::json_pointer at(a.pointer);
      for (std::size_t s = 0; s < sets.size(); ++s) {
        if (!answers[s].contains(at) || !answers[s][at].is_number()) continue;
        double v = answers[s][at].get<double>();
        double scale = std::abs(v);
        if (a.component) {
          const json& vec = answers[s][at.parent_pointer()];
          scale = std::hypot(vec[0].get<double>(), vec[1].get<double>(), vec[2].get<double>());
        }
        part.sets.push_back(s);
        part.answers.push_back(v);
        scales.push_back(scale);
      }
      if (part.sets.empty()) continue;
      if (part.sets.size() < sets.size()) {
        q.lost.push_back(
            fmt::format("{}: {} of the {} sets have no such number and are not "
                        "offered with this question",
                        a.label, sets.size() - part.sets.size(), sets.size()));
      }
      part.tolerance = tolerance_of(policy.for_field(a.part), part.answers, scales, a.component);
      double w = weights > 0 ? grader.part_points(a.part) / weights
                             : 1.0 / static_cast<double>(per_part.size());
      part.points = total * w / per_part[a.part];
      q.parts.push_back(std::move(part));
    }
    solution_steps(sets, names_of, q);
    if (form["fields"].size() > 0) {
      q.lost.emplace_back("named-mistake feedback: the platform grades each number alone");
    }
    if (std::size_t dropped = well_formed_text(q)) quiz.notes.push_back(xml_note(q.id, dropped));
    quiz.problems.push_back(std::move(q));
  }
  return quiz;
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

}  // namespace raygrade
