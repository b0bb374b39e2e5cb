// One HTML feedback page per student: self-contained, every piece of text escaped.
#include <fmt/format.h>

#include "core/escape.h"
#include "grading/outputs.h"

namespace raygrade {
namespace {

constexpr const char* kFeedbackStyle =
    "body{font-family:system-ui,sans-serif;max-width:52rem;margin:2rem auto;padding:0 1rem;"
    "line-height:1.45;color:#222}h1{font-size:1.4rem}h2{font-size:1.1rem;margin-top:1.6rem}"
    "table{border-collapse:collapse;width:100%}td,th{border-bottom:1px solid #ddd;padding:.3rem;"
    "text-align:left;vertical-align:top}.right{color:#176b2c}.partial{color:#8a5a00}"
    ".wrong,.missing{color:#a11}.mistake{background:#fff6e0;border-left:4px solid #e0a000;"
    "padding:.4rem .7rem;margin:.4rem 0}.fault{background:#fde8e8;padding:.6rem}";

std::string h(std::string_view s) { return html_escape(s); }

}  // namespace

std::string feedback_html(const SubmissionGrade& g) {
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  s += fmt::format("<title>Feedback for {}</title>\n<style>{}</style>\n</head>\n<body>\n",
                   h(g.student), kFeedbackStyle);
  s += fmt::format("<main>\n<h1>Feedback for {}</h1>\n", h(g.student));
  if (!g.gradable) {
    s += fmt::format("<p class=\"fault\">This submission could not be graded: {}</p>\n",
                     h(g.fault ? format_diagnostic(*g.fault) : "unreadable"));
    return s + "</main>\n</body>\n</html>\n";
  }
  s += fmt::format("<p>Score: <strong>{} / {}</strong></p>\n", format_points(g.score),
                   format_points(g.max_score));
  for (const auto& d : g.findings) {
    s += fmt::format("<p class=\"fault\">{}</p>\n", h(format_diagnostic(d)));
  }
  for (const auto& r : g.results) {
    s += fmt::format("<h2>{}{} — {} / {}</h2>\n", h(r.problem_id),
                     r.title.empty() ? "" : ": " + h(r.title), format_points(r.score),
                     format_points(r.max_score));
    for (const auto& n : r.notes) s += fmt::format("<p>{}</p>\n", h(n));
    if (!r.parts.empty()) {
      s += "<table>\n<tr><th>Part</th><th>Points</th><th>Feedback</th></tr>\n";
      for (const auto& p : r.parts) {
        std::string fb;
        for (const auto& f : p.feedback) fb += (fb.empty() ? "" : "<br>") + h(f);
        std::string points = p.max_points == 0 ? "not counted"
                                               : fmt::format("{} / {}", format_points(p.points),
                                                             format_points(p.max_points));
        s += fmt::format("<tr><td>{}</td><td class=\"{}\">{}</td><td>{}</td></tr>\n", h(p.name),
                         p.max_points == 0 ? "not-counted" : to_string(p.status), points, fb);
      }
      s += "</table>\n";
    }
    for (const auto& m : r.mistakes) {
      s += fmt::format("<p class=\"mistake\"><strong>{}</strong> ({}): {}</p>\n", h(m.id),
                       h(m.part), h(m.message));
    }
  }
  return s + "</main>\n</body>\n</html>\n";
}

std::string feedback_index_html(const std::vector<FeedbackPage>& pages) {
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  s += fmt::format("<title>Feedback pages</title>\n<style>{}</style>\n</head>\n<body>\n<main>\n",
                   kFeedbackStyle);
  s += fmt::format("<h1>Feedback pages</h1>\n<table>\n<caption>{} students</caption>\n",
                   pages.size());
  s += "<tr><th scope=\"col\">Student</th><th scope=\"col\">Id</th>"
       "<th scope=\"col\">Score</th></tr>\n";
  for (const auto& p : pages) {
    std::string score =
        p.gradable ? fmt::format("{} / {}", format_points(p.score), format_points(p.max_score))
                   : "not graded";
    s += fmt::format("<tr><td><a href=\"{}\">{}</a></td><td>{}</td><td>{}</td></tr>\n", h(p.file),
                     h(p.student), h(p.id), score);
  }
  return s + "</table>\n</main>\n</body>\n</html>\n";
}

}  // namespace raygrade
