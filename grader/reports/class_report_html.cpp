// The class report as an HTML page, built from the report's JSON alone: every number shown
// sits in an element whose data-j attribute is its JSON pointer, so that a test (or a reader)
// can find where it comes from.
#include <fmt/format.h>

#include <map>

#include "core/escape.h"
#include "reports/class_report.h"

namespace raygrade {
// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace class_report_html_internal {

using nlohmann::json;

std::string text(std::string_view s) { return html_escape(s); }

// A number of the report, shown as the JSON holds it.
std::string num(const json& report, const std::string& pointer) {
  const json& v = report.at(json::json_pointer(pointer));
  std::string shown = v.is_null() ? "n/a" : v.dump();
  return fmt::format("<span class=\"n\" data-j=\"{}\">{}</span>", text(pointer), text(shown));
}

// A bar chart of a histogram: tenths of the points, one bar each, its count above it.
std::string histogram_svg(const json& report, const std::string& pointer) {
  const json& counts = report.at(json::json_pointer(pointer));
  int top = 1;
  for (const auto& c : counts) top = std::max(top, c.get<int>());
  constexpr int kWidth = 24, kHeight = 80, kTop = 14, kBottom = 16;
  std::string svg = fmt::format(
      "<svg class=\"hist\" role=\"img\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
      "data-j=\"{}\"><title>Scores in tenths of the points</title>",
      kWidth * counts.size(), kHeight + kTop + kBottom, kWidth * counts.size(),
      kHeight + kTop + kBottom, text(pointer));
  for (std::size_t i = 0; i < counts.size(); ++i) {
    int c = counts[i].get<int>();
    double h = static_cast<double>(kHeight) * c / top;
    svg += fmt::format(
        "<rect x=\"{}\" y=\"{:.1f}\" width=\"{}\" height=\"{:.1f}\" fill=\"#4a7ab5\"/>"
        "<text x=\"{}\" y=\"{:.1f}\" font-size=\"10\" text-anchor=\"middle\" "
        "data-j=\"{}/{}\">{}</text>",
        i * kWidth + 2, kTop + kHeight - h, kWidth - 4, h, i * kWidth + kWidth / 2,
        kTop + kHeight - h - 2, text(pointer), i, c);
  }
  svg += fmt::format(
      "<text x=\"0\" y=\"{}\" font-size=\"9\">0%</text><text x=\"{}\" y=\"{}\" font-size=\"9\" "
      "text-anchor=\"end\">100%</text></svg>",
      kHeight + kTop + kBottom - 3, kWidth * counts.size(), kHeight + kTop + kBottom - 3);
  return svg;
}

std::string shares_cells(const json& r, const std::string& at) {
  std::string out;
  for (const char* k : {"right", "partly", "wrong", "blank"})
    out += "<td>" + num(r, at + "/shares/" + k) + "</td>";
  return out;
}

std::string parts_table(const json& r, const std::string& at) {
  std::string out =
      "<table><thead><tr><th>Part</th><th>Students</th><th>Mean</th><th>Out of</th>"
      "<th>Right</th><th>Partly</th><th>Wrong</th><th>Blank</th><th>Scores</th></tr></thead>"
      "<tbody>";
  for (const auto& [name, part] : r.at(json::json_pointer(at + "/parts")).items()) {
    std::string p = fmt::format("{}/parts/{}", at, name);
    out += fmt::format(
        "<tr><th scope=\"row\">{}</th><td>{}</td><td>{}</td><td>{}</td>{}<td>{}</td></tr>",
        text(name), num(r, p + "/students"), num(r, p + "/mean"), num(r, p + "/max_points"),
        shares_cells(r, p), histogram_svg(r, p + "/histogram"));
  }
  return out + "</tbody></table>";
}

std::string student_links(const json& r, const json& ids) {
  std::map<std::string, std::string> pages;
  for (const auto& s : r["students"]) pages[s["id"]] = s["page"];
  std::string out;
  for (const auto& id : ids) {
    std::string sid = id.get<std::string>();
    const std::string& page = pages[sid];
    out += page.empty() ? fmt::format("<span class=\"st\">{}</span> ", text(sid))
                        : fmt::format("<a class=\"st\" href=\"{}\">{}</a> ", text(page), text(sid));
  }
  return out;
}

std::string mistakes_list(const json& r, const std::string& at) {
  const json& ms = r.at(json::json_pointer(at + "/mistakes"));
  if (ms.empty()) return "<p>No named mistake was found.</p>";
  std::string out = "<ul>";
  for (std::size_t i = 0; i < ms.size(); ++i) {
    std::string m = fmt::format("{}/mistakes/{}", at, i);
    out += fmt::format(
        "<li><b>{}</b> ({}): {} {}: {}</li>", text(ms[i]["title"].get<std::string>()),
        text(ms[i]["id"].get<std::string>()), num(r, m + "/count"),
        ms[i]["count"] == 1 ? "student" : "students", student_links(r, ms[i]["students"]));
  }
  return out + "</ul>";
}

std::string groups_list(const json& r, const std::string& at) {
  const json& gs = r.at(json::json_pointer(at + "/groups"));
  if (gs.empty()) return "<p>No wrong answers.</p>";
  std::string out = "<ol class=\"groups\">";
  for (std::size_t i = 0; i < gs.size(); ++i) {
    const json& g = gs[i];
    std::string p = fmt::format("{}/groups/{}", at, i);
    std::string what = !g["mistake"].is_null() ? fmt::format("named mistake <b>{}</b>",
                                                             text(g["mistake"].get<std::string>()))
                       : !g["discovered"].is_null()
                           ? fmt::format("discovered: step <b>{}</b>, <code>{}</code>",
                                         text(g["discovered"]["step"].get<std::string>()),
                                         text(g["discovered"]["change"].get<std::string>()))
                           : fmt::format("unexplained: {}", text(g.value("note", "")));
    out += fmt::format("<li>{} — {} answers; example <code>{}</code>; students: {}</li>", what,
                       num(r, p + "/count"), text(g["example"].get<std::string>()),
                       student_links(r, g["students"]));
  }
  return out + "</ol>";
}

std::string fairness_table(const json& r, const std::string& at) {
  const json& fs = r.at(json::json_pointer(at + "/fairness"));
  if (fs.empty()) return "<p>Everyone has the same numbers.</p>";
  std::string out =
      "<table><thead><tr><th>Parameter</th><th>Value</th><th>Students</th><th>Mean "
      "fraction</th><th></th></tr></thead><tbody>";
  for (std::size_t i = 0; i < fs.size(); ++i) {
    for (std::size_t k = 0; k < fs[i]["values"].size(); ++k) {
      std::string p = fmt::format("{}/fairness/{}/values/{}", at, i, k);
      bool harder = fs[i]["values"][k]["harder"].get<bool>();
      out += fmt::format("<tr{}><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
                         harder ? " class=\"harder\"" : "",
                         text(fs[i]["parameter"].get<std::string>()), num(r, p + "/value"),
                         num(r, p + "/students"), num(r, p + "/mean"),
                         harder ? "much harder than the other values" : "");
    }
  }
  return out + "</tbody></table>";
}

// The roster's students who handed in nothing, apart from the numbers (docs/report.md).
std::string absent_note(const json& r, const std::string& at) {
  if (r.at(json::json_pointer(at)).value("no_submission", 0) == 0) return "";
  return fmt::format(" No submission from {} more on the roster (not counted above).",
                     num(r, at + "/no_submission"));
}

std::string absent_section(const json& r) {
  json absent = r.value("no_submission", json::array());
  if (absent.empty()) return "";
  std::string items;
  for (const auto& s : absent) {
    std::string name = s["name"].get<std::string>();
    items += fmt::format("<li>{}{}</li>", text(s["id"].get<std::string>()),
                         name.empty() ? "" : " (" + text(name) + ")");
  }
  return fmt::format("<section id=\"no-submission\"><h2>No submission</h2><ul>{}</ul></section>",
                     items);
}

std::string problem_section(const json& r, std::size_t i) {
  std::string at = fmt::format("/problems/{}", i);
  const json& p = r["problems"][i];
  return fmt::format(
      "<section id=\"{}\"><h2>{}</h2><p>{} {}, mean {} of {} points; discrimination "
      "(point-biserial against the rest) {}.{}</p>"
      "<table><thead><tr><th>Right</th><th>Partly</th><th>Wrong</th><th>Blank</th><th>Scores"
      "</th></tr></thead><tbody><tr>{}<td>{}</td></tr></tbody></table>"
      "<h3>Parts</h3>{}<h3>Named mistakes</h3>{}<h3>Wrong answers, grouped</h3>{}"
      "<h3>Fairness of variants</h3>{}</section>",
      text(p["id"].get<std::string>()), text(p["title"].get<std::string>()),
      num(r, at + "/students"), p["students"] == 1 ? "student" : "students", num(r, at + "/mean"),
      num(r, at + "/max_points"), num(r, at + "/discrimination"), absent_note(r, at),
      shares_cells(r, at), histogram_svg(r, at + "/histogram"), parts_table(r, at),
      mistakes_list(r, at), groups_list(r, at), fairness_table(r, at));
}

}  // namespace class_report_html_internal

std::string class_report_html(const nlohmann::json& report) {
  using namespace class_report_html_internal;  // NOLINT: this file's own functions
  std::string title = text(report["title"].get<std::string>());
  std::string body;
  for (std::size_t i = 0; i < report["problems"].size(); ++i) body += problem_section(report, i);
  body += absent_section(report);
  std::string links;
  for (const auto& s : report["students"]) {
    std::string id = s["id"].get<std::string>(), page = s["page"].get<std::string>();
    if (!page.empty()) links += fmt::format("<li><a href=\"{}\">{}</a></li>", text(page), text(id));
  }
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Class report: "
      "{}</title><style>body{{font-family:sans-serif;max-width:70em;margin:auto;padding:1em}}"
      "table{{border-collapse:collapse;margin:.5em 0}}td,th{{border:1px solid #ccc;padding:"
      ".2em .5em;vertical-align:middle}}.harder{{background:#fdd}}code{{font-size:90%}}"
      "</style></head><body><main><h1>Class report: {}</h1>{}<h2>Feedback pages</h2><ul "
      "class=\"pages\">{}</ul></main></body></html>\n",
      title, title, body, links);
}

}  // namespace raygrade
