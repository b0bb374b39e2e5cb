// The bank check: reading every file, running every check on every problem, and the checks
// across problems (unique ids, repeated geometry, worked solutions present).
#include "check/check.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <set>

#include "check/geometry_key.h"
#include "check/problem_checks.h"
#include "check/self_tests.h"
#include "check/spans.h"
#include "core/escape.h"
#include "grading/tolerance.h"

namespace raygrade {
namespace {

// Faults that mean a file could not be read at all (exit code 2), not that its content is wrong.
bool is_unreadable(const Diagnostic& d) { return d.code == "unreadable" || d.code == "limit"; }

// The names (without extension) of every file under the solutions folder.
std::set<std::string> solution_stems(const std::string& dir) {
  namespace fs = std::filesystem;
  std::set<std::string> stems;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_regular_file(ec)) stems.insert(it->path().stem().string());
  }
  return stems;
}

ProblemResult file_result(const std::string& file, Diagnostic d) {
  ProblemResult r;
  r.name = file;
  r.file = file;
  r.line = d.line;
  r.column = d.column;
  r.diagnostics.push_back(std::move(d));
  return r;
}

class BankChecker {
 public:
  explicit BankChecker(const CheckOptions& options) : options_(options) {}

  void check_file(const std::string& name, CheckReport& report) {
    std::shared_ptr<const SourceFile> file;
    std::vector<Cursor> items;
    Conventions conventions;  // the bank file's, for all its problems
    try {
      file = load_json_file(name);
      Cursor root(file);
      items = problem_items(root);
      if (root.is_object() && root.has("conventions")) {
        conventions = read_conventions(root.at("conventions"), conventions);
      }
    } catch (const Error& e) {
      if (is_unreadable(e.diagnostic())) report.unreadable = true;
      report.problems.push_back(file_result(name, e.diagnostic()));
      return;
    }
    NumberLiterals literals = scan_number_literals(file->text);
    for (const auto& item : items) {
      auto start = std::chrono::steady_clock::now();
      report.problems.push_back(check_item(item, literals, conventions));
      report.problems.back().seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  }

  void check_solutions(CheckReport& report) {
    std::string dir = options_.solutions_dir;
    std::error_code ec;
    if (dir.empty() && !options_.solutions_search.empty()) {
      for (const auto& candidate : options_.solutions_search) {
        if (std::filesystem::is_directory(candidate, ec)) {
          dir = candidate;
          break;
        }
      }
      if (dir.empty()) {
        report.general.push_back(
            Diagnostic{options_.solutions_search.front(), "", 0, 0, Severity::kWarning,
                       fmt::format("no solutions folder: looked in {}; cannot check that every "
                                   "problem has a worked solution (name one with --solutions)",
                                   fmt::join(options_.solutions_search, ", ")),
                       "no-solutions-folder"});
        return;
      }
      report.general.push_back(
          Diagnostic{dir, "", 0, 0, Severity::kNote,
                     fmt::format("worked solutions read from {} (looked in {})", dir,
                                 fmt::join(options_.solutions_search.begin(),
                                           std::find(options_.solutions_search.begin(),
                                                     options_.solutions_search.end(), dir) +
                                               1,
                                           ", ")),
                     "solutions-folder"});
    }
    if (dir.empty()) return;
    if (!std::filesystem::is_directory(dir, ec)) {
      Diagnostic d{dir,
                   "",
                   0,
                   0,
                   options_.solutions_required ? Severity::kError : Severity::kWarning,
                   "no solutions folder: cannot check that every problem has a worked solution",
                   "no-solutions-folder"};
      report.general.push_back(std::move(d));
      return;
    }
    std::set<std::string> stems = solution_stems(dir);
    for (auto& r : report.problems) {
      if (r.id.empty() || !r.solved) continue;
      std::string stem = safe_file_name(r.id);
      if (stems.count(stem)) continue;
      r.diagnostics.push_back(
          at(r, "/id", Severity::kError,
             fmt::format("no worked solution: {} holds no file named {}.*", dir, stem),
             "no-solution"));
    }
  }

 private:
  Diagnostic at(const ProblemResult& r, const std::string& relative, Severity s, std::string msg,
                std::string code) {
    Diagnostic d{r.file, r.path + relative, 0, 0, s, std::move(msg), std::move(code)};
    locate_in(r, d);
    return d;
  }

  const std::vector<TextPlace>& places_of(const std::string& file, const std::string& text) {
    auto [it, fresh] = places_.try_emplace(file);
    if (fresh) it->second = problem_places(text);
    return it->second;
  }

  // Fills in the line and column of a finding inside problem `r`, scanning from the
  // problem's own start.
  void locate_in(const ProblemResult& r, Diagnostic& d) {
    if (d.line > 0 || d.file != r.file) return;
    auto src = sources_.find(r.file);
    if (src == sources_.end()) return;
    const std::string& text = src->second->text;
    if (r.path.empty()) {
      std::tie(d.line, d.column) = src->second->locate(d.path);
      if (d.line == 0) std::tie(d.line, d.column) = src->second->locate("");
      return;
    }
    const std::string prefix = "/problems/";
    if (r.path.compare(0, prefix.size(), prefix) != 0) return;
    std::size_t index = std::stoul(r.path.substr(prefix.size()));
    const auto& places = places_of(r.file, text);
    if (index >= places.size()) return;
    std::string relative =
        d.path.compare(0, r.path.size(), r.path) == 0 ? d.path.substr(r.path.size()) : "";
    std::tie(d.line, d.column) = locate_from(text, places[index], relative);
    if (d.line == 0) std::tie(d.line, d.column) = locate_from(text, places[index], "");
  }

  ProblemResult check_item(const Cursor& item, const NumberLiterals& literals,
                           const Conventions& conventions) {
    ProblemResult r;
    r.file = item.file_name();
    r.path = item.path();
    sources_.emplace(r.file, item.file());
    if (item.is_object() && item.json().contains("id") && item.json()["id"].is_string()) {
      r.id = item.json()["id"].get<std::string>();
    }
    r.name = r.id.empty() ? fmt::format("{}{}", r.file, r.path) : r.id;
    Problem p;
    nlohmann::json reference;
    try {
      p = read_problem(item, conventions);
      r.kind = p.kind;
      (void)read_tolerance_policy(p);  // a faulty tolerance is reported like any other fault
      reference = p.task->answer();
    } catch (const Error& e) {
      r.diagnostics.push_back(e.diagnostic());
      return r;
    }
    r.solved = true;
    auto [seen, fresh] = ids_.emplace(p.id, fmt::format("{}{}", p.file, p.path));
    if (!fresh) {
      r.name = fmt::format("{} ({}{})", p.id, p.file, p.path);  // testcase names stay unique
      r.diagnostics.push_back(problem_diagnostic(
          p, "/id", Severity::kError,
          fmt::format("duplicate id '{}' (first used at {})", p.id, seen->second), "duplicate-id"));
    }
    auto [same, unique] = geometry_.emplace(geometry_key(p), p.id);
    if (!unique) {
      r.diagnostics.push_back(problem_diagnostic(
          p, "", Severity::kError,
          fmt::format("the same geometry as problem '{}' (same ray, object and method) under "
                      "another id",
                      same->second),
          "duplicate-geometry"));
    }
    auto add = [&r](std::vector<Diagnostic> ds) {
      for (auto& d : ds) r.diagnostics.push_back(std::move(d));
    };
    auto stated = check_expected(p, reference, literals);
    BoundaryProbe probe = probe_boundaries(p);
    bool wrong = std::any_of(stated.begin(), stated.end(),
                             [](const Diagnostic& d) { return d.code == "wrong-expected"; });
    add(std::move(stated));
    if (wrong && probe.exact_boundary) {
      r.diagnostics.push_back(problem_diagnostic(
          p, "/ray", Severity::kNote,
          "the ray passes within a billionth of the object's boundary: a tangent or edge case "
          "exact in decimal numbers may be a near miss (or two hits) in the binary numbers of "
          "the reference; write such cases with integers or binary fractions (0.5, 0.25)",
          "inexact-boundary"));
    }
    add(std::move(probe.diagnostics));
    if (options_.conditioning) {
      add(check_conditioning(p, reference, literals, probe.exact_boundary));
    }
    add(run_self_tests(p, reference));
    for (auto& d : r.diagnostics) locate_in(r, d);
    return r;
  }

  const CheckOptions& options_;
  std::map<std::string, std::string> ids_;       // id -> where first used
  std::map<std::string, std::string> geometry_;  // geometry key -> id
  std::map<std::string, std::shared_ptr<const SourceFile>> sources_;
  std::map<std::string, std::vector<TextPlace>> places_;  // file -> where its problems start
};

}  // namespace

int ProblemResult::count(Severity s) const {
  int n = 0;
  for (const auto& d : diagnostics) n += d.severity == s;
  return n;
}

int CheckReport::count(Severity s) const {
  int n = 0;
  for (const auto& p : problems) n += p.count(s);
  for (const auto& d : general) n += d.severity == s;
  return n;
}

std::vector<Diagnostic> CheckReport::diagnostics() const {
  std::vector<Diagnostic> out = general;
  for (const auto& p : problems) out.insert(out.end(), p.diagnostics.begin(), p.diagnostics.end());
  return out;
}

std::vector<std::string> solution_folder_candidates(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  auto add = [&](const fs::path& folder) {
    std::string s = (folder / "solutions").lexically_normal().string();
    if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  };
  for (const auto& p : paths) {
    fs::path path = fs::path(p).lexically_normal();
    if (!path.has_filename()) path = path.parent_path();  // "A/" is the folder A
    std::error_code ec;
    if (fs::is_directory(path, ec)) add(path);
    add(path.parent_path());
  }
  add(fs::path());
  return out;
}

CheckReport check_bank(const std::vector<std::string>& paths, const CheckOptions& options) {
  CheckReport report;
  std::vector<Diagnostic> missing;
  report.files = list_bank_files(paths, missing);
  // Worked solutions in JSON beside the problems (`check DIR` after `generate --out DIR
  // --solution-format json`) are not problems.
  std::vector<std::string> solution_folders = options.solutions_search;
  if (!options.solutions_dir.empty()) solution_folders = {options.solutions_dir};
  for (const auto& dir : solution_folders) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::string prefix = (fs::path(dir) / "").lexically_normal().string();
    std::erase_if(report.files, [&](const std::string& f) {
      return fs::path(f).lexically_normal().string().rfind(prefix, 0) == 0;
    });
    break;
  }
  for (auto& d : missing) {
    report.unreadable = true;
    report.problems.push_back(file_result(d.file, d));
  }
  BankChecker checker(options);
  for (const auto& f : report.files) checker.check_file(f, report);
  checker.check_solutions(report);
  return report;
}

}  // namespace raygrade
