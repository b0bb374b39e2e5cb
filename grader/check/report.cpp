// Rendering the bank check's report.
#include "check/report.h"

#include <map>

#include "core/escape.h"
#include "reports/json_report.h"

namespace raygrade {
namespace {

std::string line_of(const Diagnostic& d) {
  return fmt::format("{} [{}]", format_diagnostic(d), d.code);
}

int failed_problems(const CheckReport& r) {
  int n = 0;
  for (const auto& p : r.problems) n += p.count(Severity::kError) > 0;
  return n;
}

// A problem whose file could not be read at all: a JUnit error rather than a failure, in
// its suite's counts and in the root's alike.
bool unreadable(const ProblemResult& p) {
  return p.count(Severity::kError) > 0 && !p.diagnostics.empty() &&
         (p.diagnostics.front().code == "unreadable" || p.diagnostics.front().code == "limit");
}

std::string plural(int n, const char* one, const char* many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

}  // namespace

std::string check_report_text(const CheckReport& report) {
  std::string out;
  for (const auto& d : report.diagnostics()) out += line_of(d) + "\n";
  int errors = report.count(Severity::kError), warnings = report.count(Severity::kWarning);
  int failed = failed_problems(report);
  out += fmt::format("Checked {} in {}: {} passed, {} failed ({}, {}).\n",
                     plural(static_cast<int>(report.problems.size()), "problem", "problems"),
                     plural(static_cast<int>(report.files.size()), "file", "files"),
                     static_cast<int>(report.problems.size()) - failed, failed,
                     plural(errors, "error", "errors"), plural(warnings, "warning", "warnings"));
  return out;
}

nlohmann::json check_report_json(const CheckReport& report) {
  nlohmann::json problems = nlohmann::json::array();
  for (const auto& p : report.problems) {
    nlohmann::json diags = nlohmann::json::array();
    for (const auto& d : p.diagnostics) diags.push_back(diagnostic_json(d));
    nlohmann::json j = {{"name", p.name},
                        {"file", p.file},
                        {"path", p.path},
                        {"status", p.count(Severity::kError) ? "failed" : "passed"},
                        {"diagnostics", diags}};
    if (!p.id.empty()) j["id"] = p.id;
    if (!p.kind.empty()) j["kind"] = p.kind;
    problems.push_back(std::move(j));
  }
  int failed = failed_problems(report);
  nlohmann::json summary = {{"files", report.files.size()},
                            {"problems", report.problems.size()},
                            {"passed", static_cast<int>(report.problems.size()) - failed},
                            {"failed", failed},
                            {"errors", report.count(Severity::kError)},
                            {"warnings", report.count(Severity::kWarning)},
                            {"unreadable", report.unreadable}};
  nlohmann::json general = nlohmann::json::array();
  for (const auto& d : report.general) general.push_back(diagnostic_json(d));
  return {{"summary", summary}, {"diagnostics", general}, {"problems", problems}};
}

std::string check_report_junit(const CheckReport& report) {
  // Problems grouped by file, in bank order.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const ProblemResult*>> by_file;
  for (const auto& p : report.problems) {
    auto& list = by_file[p.file];
    if (list.empty()) order.push_back(p.file);
    list.push_back(&p);
  }
  // Errors about the bank as a whole (a solutions folder named but missing) fail one more
  // testcase of their own; warnings about it appear in the text and JSON reports only.
  std::vector<ProblemResult> bank_level;
  for (const auto& d : report.general) {
    if (d.severity != Severity::kError) continue;
    if (bank_level.empty()) {
      bank_level.push_back(ProblemResult{});
      bank_level.back().name = "bank";
      bank_level.back().file = "bank";
    }
    bank_level.back().diagnostics.push_back(d);
  }
  for (const auto& p : bank_level) {
    order.insert(order.begin(), p.file);
    by_file[p.file].push_back(&p);
  }
  // Each suite is rendered first, so that the root can carry the sums of its suites' counts.
  std::string suites;
  int total_failures = 0, total_errors = 0;
  double total_seconds = 0;
  for (const auto& file : order) {
    const auto& list = by_file[file];
    int suite_failures = 0, suite_errors = 0;
    double suite_seconds = 0;
    for (const auto* p : list) {
      suite_seconds += p->seconds;
      if (!p->count(Severity::kError)) continue;
      (unreadable(*p) ? suite_errors : suite_failures)++;
    }
    total_failures += suite_failures;
    total_errors += suite_errors;
    total_seconds += suite_seconds;
    suites += fmt::format(
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"0\" "
        "time=\"{:.6f}\">\n",
        xml_escape(file), list.size(), suite_failures, suite_errors, suite_seconds);
    for (const auto* p : list) {
      suites +=
          fmt::format("    <testcase name=\"{}\" classname=\"{}\" file=\"{}\" time=\"{:.6f}\"",
                      xml_escape(p->name), xml_escape(file), xml_escape(file), p->seconds);
      std::string errors, warnings;
      const Diagnostic* first = nullptr;
      for (const auto& d : p->diagnostics) {
        (d.severity == Severity::kError ? errors : warnings) += line_of(d) + "\n";
        if (!first && d.severity == Severity::kError) first = &d;
      }
      if (!first && warnings.empty()) {
        suites += "/>\n";
        continue;
      }
      suites += ">\n";
      if (first) {
        const char* element = unreadable(*p) ? "error" : "failure";
        suites += fmt::format("      <{} message=\"{}\" type=\"{}\">{}</{}>\n", element,
                              xml_escape(first->message), xml_escape(first->code),
                              xml_escape(errors), element);
      }
      if (!warnings.empty()) {
        suites += fmt::format("      <system-out>{}</system-out>\n", xml_escape(warnings));
      }
      suites += "    </testcase>\n";
    }
    suites += "  </testsuite>\n";
  }
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format(
      "<testsuites name=\"raygrade check\" tests=\"{}\" failures=\"{}\" errors=\"{}\" "
      "time=\"{:.6f}\">\n",
      report.problems.size() + bank_level.size(), total_failures, total_errors, total_seconds);
  out += suites;
  out += "</testsuites>\n";
  return out;
}

}  // namespace raygrade
