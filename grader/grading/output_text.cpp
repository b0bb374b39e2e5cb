// Text and JSON forms of graded submissions.
#include <fmt/format.h>

#include <cmath>

#include "core/escape.h"
#include "grading/outputs.h"
#include "json/numbers.h"

namespace raygrade {

std::string format_points(double p) {
  double r = std::round(p * 100) / 100;
  if (r == 0) r = 0;  // no "-0"
  return fmt::format("{:g}", r);
}

std::vector<std::string> feedback_lines(const GradeResult& r) {
  std::vector<std::string> out;
  for (const auto& n : r.notes) out.push_back(n);
  for (const auto& p : r.parts) {
    // A part that carries no points shows no verdict beside a score.
    std::string head = p.max_points == 0
                           ? fmt::format("{} ({})", p.name, shown_status(p))
                           : fmt::format("{} ({}/{}, {})", p.name, format_points(p.points),
                                         format_points(p.max_points), shown_status(p));
    if (p.feedback.empty()) {
      out.push_back(head);
    } else {
      out.push_back(fmt::format("{}: {}", head, p.feedback.front()));
      for (std::size_t i = 1; i < p.feedback.size(); ++i) out.push_back("  " + p.feedback[i]);
    }
  }
  for (const auto& m : r.mistakes) {
    out.push_back(fmt::format("Mistake [{}] in {}: {}", m.id, m.part, m.message));
  }
  return out;
}

// Everything a student controls (name, file name, the answers quoted in feedback) goes
// through printable(): a report read on a terminal cannot carry an escape sequence to it.
std::string text_report(const SubmissionGrade& g) {
  std::string s = fmt::format("{} ({})", printable(g.student), printable(g.file));
  if (!g.gradable) {
    return s + fmt::format(": not gradable\n  {}\n", g.fault ? format_diagnostic(*g.fault) : "");
  }
  s += fmt::format(": {} / {}\n", format_points(g.score), format_points(g.max_score));
  for (const auto& d : g.findings) s += "  " + format_diagnostic(d) + "\n";
  for (const auto& r : g.results) {
    s += fmt::format("  {}{}: {} / {}\n", printable(r.problem_id),
                     r.title.empty() ? "" : " — " + printable(r.title), format_points(r.score),
                     format_points(r.max_score));
    for (const auto& line : feedback_lines(r)) s += "    " + printable(line) + "\n";
  }
  return s;
}

std::string json_text(const nlohmann::json& j, int indent) {
  std::string dumped =
      without_negative_zeros(j).dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
  // nlohmann writes C0 controls as \u00XX already; C1 controls (U+0080 to U+009F, bytes C2 80
  // to C2 9F) and DEL it writes raw. Outside strings the text is ASCII, so every such byte is
  // inside a string, where an escape means the same character.
  std::string out;
  out.reserve(dumped.size());
  for (std::size_t i = 0; i < dumped.size(); ++i) {
    auto c = static_cast<unsigned char>(dumped[i]);
    if (c == 0xC2 && i + 1 < dumped.size() && static_cast<unsigned char>(dumped[i + 1]) < 0xA0) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned char>(dumped[++i]));
    } else if (c == 0x7F) {
      out += "\\u007f";
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

nlohmann::json submission_json(const SubmissionGrade& g) {
  // A file name need not be UTF-8 (Latin-1's "jos\xe9.json"): JSON text must be.
  nlohmann::json j = {{"file", printable(g.file)}, {"student", g.student}};
  if (!g.identity.id.empty()) j["student_id"] = g.identity.id;
  if (!g.identity.email.empty()) j["email"] = g.identity.email;
  j["gradable"] = g.gradable;
  if (!g.gradable) {
    const Diagnostic& d = *g.fault;
    j["fault"] = {{"file", printable(d.file)}, {"path", d.path}, {"line", d.line},
                  {"column", d.column},        {"code", d.code}, {"message", d.message}};
    return j;
  }
  j["score"] = g.score;
  j["max_score"] = g.max_score;
  nlohmann::json results = nlohmann::json::array();
  for (const auto& r : g.results) results.push_back(result_json(r));
  j["problems"] = results;
  nlohmann::json findings = nlohmann::json::array();
  for (const auto& d : g.findings) {
    findings.push_back({{"file", printable(d.file)},
                        {"path", d.path},
                        {"line", d.line},
                        {"column", d.column},
                        {"code", d.code},
                        {"message", d.message}});
  }
  j["findings"] = findings;
  return j;
}

void JsonArrayStream::add(const std::string& item) {
  std::string indented = first_ ? "{\n  \"submissions\": [\n    " : ",\n    ";
  for (char c : item) {
    indented += c;
    if (c == '\n') indented += "    ";
  }
  out_ << indented;
  first_ = false;
}

void JsonArrayStream::finish() {
  out_ << (first_ ? "{\n  \"submissions\": []\n}\n" : "\n  ]\n}\n");
}

}  // namespace raygrade
