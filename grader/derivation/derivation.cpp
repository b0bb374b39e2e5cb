// Recording derivation steps.
#include "derivation/derivation.h"

#include <string_view>

#include "core/error.h"
#include "core/internal_error.h"

namespace raygrade {

const Step* Derivation::find(std::string_view name) const {
  for (const auto& s : steps) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

Deriver::Deriver(std::string method, std::string title, const Overrides* overrides)
    : overrides_(overrides) {
  d_.method = std::move(method);
  d_.title = std::move(title);
}

E Deriver::given(const std::string& name, const std::string& display, const Value& value,
                 std::string note) {
  E s = raygrade::sym(name, display);
  symbols_[name] = s;
  env_[name] = value;
  d_.steps.push_back(Step{name, s, E(), value, std::move(note), true, false});
  return s;
}

Value Deriver::step(const std::string& name, const std::string& display, const E& formula,
                    std::string note) {
  return record(name, raygrade::sym(name, display), formula, std::move(note));
}

Value Deriver::step(const std::string& name, const E& shown, const E& formula, std::string note) {
  return record(name, raygrade::sym(name, shown), formula, std::move(note));
}

Value Deriver::record(const std::string& name, const E& s, const E& formula, std::string note) {
  E f = formula;
  if (overrides_ && overrides_->formula) {
    if (auto replaced = overrides_->formula(name, formula)) f = *replaced;
  }
  Value v;
  bool overridden = false;
  if (overrides_) {
    auto it = overrides_->values.find(name);
    if (it != overrides_->values.end()) {
      v = it->second;
      overridden = true;
    }
  }
  if (!overridden) v = evaluate(f, env_);
  symbols_[name] = s;
  env_[name] = v;
  d_.steps.push_back(Step{name, s, f, v, std::move(note), false, overridden});
  return v;
}

E Deriver::sym(const std::string& name) const {
  auto it = symbols_.find(name);
  if (it == symbols_.end()) {
    throw InternalError("derivation: no step named '" + name + "'");
  }
  return it->second;
}

const Value& Deriver::value(const std::string& name) const {
  auto it = env_.find(name);
  if (it == env_.end()) {
    throw InternalError("derivation: no value for '" + name + "'");
  }
  return it->second;
}

void Deriver::append(const Derivation& inner) {
  for (const auto& s : inner.steps) {
    symbols_[s.name] = s.symbol;
    env_[s.name] = s.value;
    d_.steps.push_back(s);
  }
}

void Deriver::note(std::string text) {
  if (d_.steps.empty()) return;
  auto& n = d_.steps.back().note;
  // Two sentences, not one run-on: "cos²θt. Going into a lower index, ...".
  bool ends_sentence =
      !n.empty() && std::string_view(".!?:;").find(n.back()) != std::string_view::npos;
  n = n.empty() ? std::move(text) : n + (ends_sentence ? " " : ". ") + text;
}

void Deriver::conclude(std::string sentence) { conclude(Sentence(std::move(sentence))); }

void Deriver::conclude(Sentence sentence) {
  d_.conclusion.push_back(sentence.plain());
  d_.sentences.push_back(std::move(sentence));
}

Sentence& Sentence::text(std::string words) {
  if (!parts_.empty() && parts_.back().value.kind == Value::Kind::kNone) {
    parts_.back().text += words;
  } else {
    parts_.push_back(Part{std::move(words), Value()});
  }
  return *this;
}

Sentence& Sentence::value(const Value& v) {
  parts_.push_back(Part{"", v});
  return *this;
}

std::string Sentence::plain(const NumberFormat& f) const {
  std::string out;
  for (const auto& p : parts_)
    out += p.value.kind == Value::Kind::kNone ? p.text : format_value(p.value, f);
  return out;
}

Derivation Deriver::finish() && { return std::move(d_); }

}  // namespace raygrade
