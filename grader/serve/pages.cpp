// The HTML pages of `raygrade serve`.
#include "serve/pages.h"

#include <fmt/format.h>

#include "core/escape.h"

namespace raygrade::serve {

namespace {

std::string attr(const std::string& s) { return html_escape(s); }

// The student page's script: sends the handout's answers, shows what comes back.
constexpr std::string_view kSubmitScript = R"JS(
(function () {
  const launch = JSON.parse(document.getElementById("raygrade-launch").textContent);
  const button = document.getElementById("raygrade-submit");
  const out = document.getElementById("raygrade-result");
  if (launch.last) {
    out.textContent = "Your last submission (" + launch.last.submission + ", " + launch.last.at +
        ") scored " + launch.last.score + " / " + launch.last.max + ".";
  }
  button.addEventListener("click", async () => {
    button.disabled = true;
    out.textContent = "Sending...";
    try {
      const answers = window.raygradeHandout.submission().answers;
      const r = await fetch(launch.submit, {
        method: "POST", credentials: "same-origin",
        headers: {"Content-Type": "application/json"},
        body: JSON.stringify({launch: launch.launch, csrf: launch.csrf, answers: answers})});
      const j = await r.json();
      if (!r.ok) { out.textContent = "Not accepted: " + (j.error || r.status); return; }
      out.textContent = "";
      const head = document.createElement("p");
      head.id = "raygrade-score";
      head.textContent = "Submission " + j.submission + " received: " + j.score + " / " + j.max;
      out.appendChild(head);
      for (const p of (j.feedback && j.feedback.problems) || []) {
        const h = document.createElement("h3");
        h.textContent = (p.title || p.problem) + ": " + p.score + " / " + p.max_score;
        out.appendChild(h);
        const lines = [];
        for (const part of p.parts || []) {
          const said = Array.isArray(part.feedback) ? part.feedback.join(" ") : part.feedback || "";
          lines.push(part.name + " (" + part.status + "): " + said);
        }
        for (const m of p.mistakes || []) lines.push(m.message);
        for (const n of p.notes || []) lines.push(n);
        for (const line of lines) {
          const li = document.createElement("p");
          li.textContent = line;
          out.appendChild(li);
        }
      }
    } catch (e) {
      out.textContent = "Could not send: " + e;
    } finally {
      button.disabled = false;
    }
  });
})();
)JS";

}  // namespace

std::string page(const std::string& title, const std::string& body) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
      "<title>{}</title><style>body{{font-family:sans-serif;max-width:50rem;margin:2rem auto;"
      "padding:0 1rem}}</style></head>\n<body>\n{}\n</body></html>\n",
      html_escape(title), body);
}

std::string refusal_page(int status, const std::string& reason) {
  return page(fmt::format("Refused ({})", status),
              fmt::format("<h1>Refused</h1>\n<p id=\"reason\">{}</p>\n<p>HTTP status {}. Nothing "
                          "was stored. Start again from your course's page.</p>",
                          html_escape(reason), status));
}

std::string launch_script(const nlohmann::json& launch) {
  // "</" and "<!--" cannot end or confuse the element: every '<' is written as \u003c.
  std::string text = launch.dump();
  std::string safe;
  for (char c : text) safe += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return "<script type=\"application/json\" id=\"raygrade-launch\">" + safe + "</script>\n";
}

std::string student_page(const std::string& handout_html, const nlohmann::json& launch) {
  std::string extra = launch_script(launch) +
                      "<section id=\"raygrade-lti\"><button type=\"button\" "
                      "id=\"raygrade-submit\">Submit to your course</button>"
                      "<div id=\"raygrade-result\" aria-live=\"polite\"></div></section>\n"
                      "<script>" +
                      std::string(kSubmitScript) + "</script>\n";
  std::string html = handout_html;
  // The handout's policy allows no connection (a page of its own, offline); this one sends
  // its answers to the tool that served it, and nowhere else.
  constexpr std::string_view kNone = "default-src 'none'; ";
  if (std::size_t csp = html.find(kNone); csp != std::string::npos)
    html.insert(csp + kNone.size(), "connect-src 'self'; ");
  std::size_t end = html.rfind("</body>");
  if (end == std::string::npos) return html + extra;
  return html.insert(end, extra);
}

std::string picker_page(const std::vector<PickerItem>& items, const std::string& deep_link_url,
                        const std::string& launch_id, const std::string& csrf) {
  std::string body = "<h1>Choose an assignment</h1>\n";
  if (items.empty()) body += "<p>The assignments folder holds no assignment.</p>\n";
  for (const auto& it : items) {
    body += fmt::format(
        "<form method=\"post\" action=\"{}\" class=\"assignment\">"
        "<input type=\"hidden\" name=\"launch\" value=\"{}\">"
        "<input type=\"hidden\" name=\"csrf\" value=\"{}\">"
        "<input type=\"hidden\" name=\"assignment\" value=\"{}\">"
        "<button type=\"submit\">{}</button> ({} points, {})</form>\n",
        attr(deep_link_url), attr(launch_id), attr(csrf), attr(it.name), html_escape(it.title),
        it.points, html_escape(it.name));
  }
  return page("Choose an assignment", body);
}

std::string deep_link_return_page(const std::string& return_url, const std::string& jwt) {
  return page("Returning to your course",
              fmt::format("<form id=\"return\" method=\"post\" action=\"{}\">"
                          "<input type=\"hidden\" name=\"JWT\" value=\"{}\">"
                          "<button type=\"submit\">Return to the course</button></form>\n"
                          "<script>document.getElementById(\"return\").submit();</script>",
                          attr(return_url), attr(jwt)));
}

std::string instructor_page(const std::string& title, const std::string& public_url,
                            const nlohmann::json& launch, int submissions) {
  std::string id = launch.value("launch", "");
  std::string csrf = launch.value("csrf", "");
  std::string body = fmt::format(
      "<h1>{}</h1>\n<p>{} submissions so far.</p>\n<ul>"
      "<li><a id=\"report\" href=\"{}/lti/report?launch={}\">Class report</a></li>"
      "<li><a id=\"gradebook\" href=\"{}/lti/gradebook.csv?launch={}\">Gradebook (CSV)</a></li>"
      "</ul>\n<h2>Regrade with a new bank</h2>\n"
      "<form method=\"post\" action=\"{}/lti/regrade\" enctype=\"multipart/form-data\">"
      "<input type=\"hidden\" name=\"launch\" value=\"{}\">"
      "<input type=\"hidden\" name=\"csrf\" value=\"{}\">"
      "<input type=\"file\" name=\"bank\" accept=\".json\" multiple> "
      "<button type=\"submit\">Regrade and send changed scores</button></form>\n",
      html_escape(title), submissions, attr(public_url), attr(id), attr(public_url), attr(id),
      attr(public_url), attr(id), attr(csrf));
  return page(title, launch_script(launch) + body);
}

std::string registration_done_page(const std::string& issuer, const std::string& client_id) {
  return page("Registered",
              fmt::format("<h1>raygrade is registered</h1><p>Platform {}, client id {}.</p>\n"
                          "<script>(window.opener || window.parent).postMessage("
                          "{{subject: \"org.imsglobal.lti.close\"}}, \"*\");</script>",
                          html_escape(issuer), html_escape(client_id)));
}

}  // namespace raygrade::serve
