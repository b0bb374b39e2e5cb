// GradeResult helpers and its JSON form.
#include "grading/result.h"

#include <fmt/format.h>

#include <cmath>

namespace raygrade {

const char* to_string(PartStatus s) {
  switch (s) {
    case PartStatus::kRight: return "right";
    case PartStatus::kPartial: return "partial";
    case PartStatus::kWrong: return "wrong";
    case PartStatus::kMissing: return "missing";
  }
  return "missing";
}

const char* shown_status(const PartResult& p) {
  if (p.max_points == 0 && p.status != PartStatus::kMissing) return "not counted";
  return to_string(p.status);
}

double GradeResult::fraction() const {
  if (max_score > 0) return score / max_score;
  for (const auto& p : parts) {
    if (p.status != PartStatus::kRight) return 0;
  }
  return answered ? 1 : 0;
}

bool GradeResult::has_mistake(std::string_view id) const {
  for (const auto& m : mistakes) {
    if (m.id == id) return true;
  }
  return false;
}

nlohmann::json result_json(const GradeResult& r) {
  nlohmann::json parts = nlohmann::json::array();
  for (const auto& p : r.parts) {
    parts.push_back({{"name", p.name},
                     {"points", p.points},
                     {"max_points", p.max_points},
                     {"status", to_string(p.status)},
                     {"feedback", p.feedback}});
  }
  nlohmann::json mistakes = nlohmann::json::array();
  for (const auto& m : r.mistakes) {
    mistakes.push_back({{"id", m.id}, {"kind", m.kind}, {"part", m.part}, {"message", m.message}});
  }
  return {
      {"problem", r.problem_id},  {"title", r.title},       {"score", r.score},
      {"max_score", r.max_score}, {"answered", r.answered}, {"parts", parts},
      {"mistakes", mistakes},     {"notes", r.notes},       {"carried_forward", r.carried_forward}};
}

namespace {

void append_string(std::string& out, std::string_view s) {
  out += '"';
  for (char ch : s) {
    auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          out += fmt::format("\\u{:04x}", c);
        } else {
          out += ch;
        }
    }
  }
  out += '"';
}

void append_number(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  fmt::format_to(std::back_inserter(out), "{}", v);
}

void append_strings(std::string& out, const std::vector<std::string>& v) {
  out += '[';
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) out += ',';
    append_string(out, v[i]);
  }
  out += ']';
}

}  // namespace

void append_result_json(std::string& out, const GradeResult& r) {
  out += "{\"problem\":";
  append_string(out, r.problem_id);
  out += ",\"title\":";
  append_string(out, r.title);
  out += ",\"score\":";
  append_number(out, r.score);
  out += ",\"max_score\":";
  append_number(out, r.max_score);
  out += r.answered ? ",\"answered\":true" : ",\"answered\":false";
  out += ",\"parts\":[";
  for (std::size_t i = 0; i < r.parts.size(); ++i) {
    const PartResult& p = r.parts[i];
    if (i) out += ',';
    out += "{\"name\":";
    append_string(out, p.name);
    out += ",\"points\":";
    append_number(out, p.points);
    out += ",\"max_points\":";
    append_number(out, p.max_points);
    out += ",\"status\":";
    append_string(out, to_string(p.status));
    out += ",\"feedback\":";
    append_strings(out, p.feedback);
    out += '}';
  }
  out += "],\"mistakes\":[";
  for (std::size_t i = 0; i < r.mistakes.size(); ++i) {
    const FoundMistake& m = r.mistakes[i];
    if (i) out += ',';
    out += "{\"id\":";
    append_string(out, m.id);
    out += ",\"kind\":";
    append_string(out, m.kind);
    out += ",\"part\":";
    append_string(out, m.part);
    out += ",\"message\":";
    append_string(out, m.message);
    out += '}';
  }
  out += "],\"notes\":";
  append_strings(out, r.notes);
  out += r.carried_forward ? ",\"carried_forward\":true}" : ",\"carried_forward\":false}";
}

}  // namespace raygrade
