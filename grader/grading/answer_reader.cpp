// Reading the values of a student's answer.
#include "grading/answer_reader.h"

#include <fmt/format.h>

#include <cmath>

#include "core/escape.h"
#include "derivation/formula.h"
#include "json/cursor.h"

namespace raygrade {

bool AnswerReader::has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

AnswerReader AnswerReader::at(std::string_view key) const {
  if (!value_->is_object()) fail("expected an object", "type");
  auto it = value_->find(key);
  if (it == value_->end()) fail(fmt::format("missing '{}'", key), "missing-key");
  return AnswerReader(*it, file_, path_ + "/" + pointer_token(key));
}

std::vector<AnswerReader> AnswerReader::items() const {
  if (!value_->is_array()) fail("expected an array", "type");
  std::vector<AnswerReader> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i) {
    out.emplace_back((*value_)[i], file_, fmt::format("{}/{}", path_, i));
  }
  return out;
}

std::string AnswerReader::string() const {
  if (!value_->is_string()) fail("expected a string", "type");
  return value_->get<std::string>();
}

void AnswerReader::allow_only(const std::vector<std::string>& allowed) const {
  if (!value_->is_object()) fail("expected an object", "type");
  for (const auto& [key, v] : value_->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string hint = closest_match(key, allowed);
    AnswerReader(v, file_, path_ + "/" + pointer_token(key))
        .fail(hint.empty()
                  ? fmt::format("unknown key '{}' (known: {})", key, fmt::join(allowed, ", "))
                  : fmt::format("unknown key '{}' (did you mean '{}'?)", key, hint),
              "unknown-key");
  }
}

void AnswerReader::fail(const std::string& message, const std::string& code) const {
  throw Error(Diagnostic{file_ ? *file_ : "", path_, 0, 0, Severity::kError, message, code});
}

namespace {

AnswerReader::Number student_number(std::string_view text, FormulaParse p) {
  AnswerReader::Number out;
  if (!p.ok) {
    out.fault = fmt::format("could not read '{}': {}", printable(text, 60), p.message);
    return out;
  }
  double v = p.formula.evaluate();
  if (!std::isfinite(v)) {
    out.fault = fmt::format("'{}' has no finite value", printable(text, 60));
    return out;
  }
  out.value = StudentNumber{v, p.digits, std::string(text)};
  return out;
}

}  // namespace

AnswerReader::Number parse_student_number(std::string_view text) {
  return student_number(text, parse_formula(text));
}

AnswerReader::Number AnswerReader::number() const {
  if (value_->is_number()) {
    double v = value_->get<double>();
    // 1e400, or an integer of 400 digits: JSON allows it, a double does not hold it.
    if (!std::isfinite(v))
      fail("number out of range: beyond what a double holds (about ±1.8e308)", "range");
    // The shortest text that reads back as v is what the student typed, up to trailing zeros.
    std::string text = value_->is_number_float() ? fmt::format("{}", v) : value_->dump();
    return Number{StudentNumber{v, typed_digits(text), text}, ""};
  }
  if (value_->is_string()) {
    const std::string& text = value_->get_ref<const std::string&>();
    FormulaParse p = parse_formula(text);
    // Beyond the parser's limits (p.over_limit) is read no further: like any number that does
    // not parse, it costs that answer alone, with the limit named in its feedback.
    return student_number(text, std::move(p));
  }
  fail("expected a number (or a number typed as a string, like \"1/3\")", "type");
}

AnswerReader::Vector AnswerReader::vector() const {
  if (!value_->is_array() || value_->size() != 3) fail("expected [x, y, z]", "type");
  Vector out;
  out.ok = true;
  for (std::size_t i = 0; i < 3; ++i) {
    Number n = AnswerReader((*value_)[i], file_, fmt::format("{}/{}", path_, i)).number();
    if (!n.value) {
      if (out.ok) out.fault = n.fault;
      out.ok = false;
      continue;
    }
    out.c[i] = *n.value;
  }
  return out;
}

}  // namespace raygrade
