// Derivation: a worked solution as data. Each step names a quantity, gives its formula and
// its value; the same steps feed the worked solution, the grading of intermediate answers and
// the diagnosis of mistakes.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "derivation/expr.h"

namespace raygrade {

struct Step {
  std::string name;  // stable, documented, used by students in submissions ("t_ca")
  E symbol;          // how the quantity is shown
  E formula;         // empty for givens
  Value value;
  std::string note;         // a short sentence: why this step, or what its value means
  bool given = false;       // an input of the problem rather than a computed quantity
  bool overridden = false;  // the value came from Overrides (a student's own earlier value)
};

// A sentence of a conclusion: words with numbers in them, kept as values so that each output
// shows them at its own precision (and in exact form where one exists).
class Sentence {
 public:
  struct Part {
    std::string text;  // words, when `value` is empty
    Value value;       // a number or a point, when its kind is not kNone
  };

  Sentence() = default;
  explicit Sentence(std::string words) { text(std::move(words)); }
  Sentence& text(std::string words);
  Sentence& value(const Value& v);
  const std::vector<Part>& parts() const { return parts_; }
  // The sentence with its numbers written by format_value (points as (x, y, z)).
  std::string plain(const NumberFormat& f = {}) const;

 private:
  std::vector<Part> parts_;
};

struct Derivation {
  std::string method;  // "geometric", "algebraic", "slab", ...
  std::string title;   // "Sphere, geometric method"
  std::vector<Step> steps;
  std::vector<std::string> conclusion;  // sentences in plain words
  std::vector<Sentence> sentences;      // the same sentences, with their numbers as values

  const Step* find(std::string_view name) const;
};

// What a derivation is run with besides the problem: a student's own values for some steps
// (error carried forward), and formula changes that model a mistake.
struct Overrides {
  Env values;
  std::function<std::optional<E>(std::string_view step, const E& formula)> formula;
};

// Records steps while a primitive's derivation code runs. Formulas are evaluated here, so
// the number shown is always the number the formula gives.
class Deriver {
 public:
  Deriver(std::string method, std::string title, const Overrides* overrides = nullptr);

  // An input quantity.
  E given(const std::string& name, const std::string& display, const Value& value,
          std::string note = "");
  // A computed quantity: evaluates `formula` (or its override) and records the step.
  Value step(const std::string& name, const std::string& display, const E& formula,
             std::string note = "");
  // The same, for a quantity shown as a formula of earlier symbols ("denominator" as N · R).
  Value step(const std::string& name, const E& shown, const E& formula, std::string note = "");
  // The symbol of an earlier step or given.
  E sym(const std::string& name) const;
  const Value& value(const std::string& name) const;
  double scalar(const std::string& name) const { return value(name).scalar; }
  // Takes the steps of a derivation worked on its own (a primitive's, inside a transformed
  // object's) into this one: later formulas may use them; their conclusions are not taken.
  void append(const Derivation& inner);
  // Adds a note to the last step.
  void note(std::string text);
  void conclude(std::string sentence);
  void conclude(Sentence sentence);

  const Env& env() const { return env_; }
  Derivation finish() &&;

 private:
  Value record(const std::string& name, const E& symbol, const E& formula, std::string note);

  Derivation d_;
  Env env_;
  std::map<std::string, E, std::less<>> symbols_;
  const Overrides* overrides_;
};

}  // namespace raygrade
