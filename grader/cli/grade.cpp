// raygrade grade: grade submissions against a bank, in the form an LMS or a person reads.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "grading/outputs.h"
#include "grading/submission.h"

namespace raygrade::cli {
namespace {

struct GradeCliOptions {
  std::vector<std::string> problems = {"problems"};
  std::vector<std::string> submissions;
  std::string format = "text";
  std::string out;
  bool answered_only = false;
};

// A progress bar on standard error, only when it is a terminal.
class Progress {
 public:
  explicit Progress(std::size_t total) : total_(total), on_(total > 1 && isatty(STDERR_FILENO)) {}
  void step(std::size_t done) {
    if (!on_ || (done != total_ && done % 64 != 0)) return;
    int width = 30, filled = static_cast<int>(width * done / total_);
    fmt::print(stderr, "\r[{}{}] {}/{}", std::string(filled, '#'), std::string(width - filled, ' '),
               done, total_);
    if (done == total_) fmt::print(stderr, "\n");
  }

 private:
  std::size_t total_;
  bool on_;
};

std::string extension(const std::string& format) {
  if (format == "text") return ".txt";
  if (format == "html") return ".html";
  return ".json";
}

std::string render(const SubmissionGrade& g, const std::string& format, double seconds) {
  if (format == "text") return text_report(g);
  if (format == "html") return feedback_html(g);
  if (format == "gradescope")
    return gradescope_json(g, seconds)
               .dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
           "\n";
  if (format == "prairielearn")
    return prairielearn_json(g).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
           "\n";
  return submission_json(g).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

int run_grade(const GradeCliOptions& o) {
  static const std::set<std::string> formats = {"text",         "json", "gradescope",
                                                "prairielearn", "csv",  "html"};
  if (!formats.count(o.format)) {
    fmt::print(stderr, "raygrade grade: unknown format '{}'\n", o.format);
    return kExitBadInput;
  }
  Bank bank = load_bank(o.problems);
  for (const auto& e : bank.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  Assignment assignment(bank.problems, AssignmentOptions{o.answered_only});
  for (const auto& e : assignment.errors()) fmt::print(stderr, "{}\n", format_diagnostic(e));
  std::vector<Diagnostic> errors;
  std::vector<std::string> files = submission_files(o.submissions, errors);
  for (const auto& e : errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  bool single = files.size() == 1 && errors.empty();
  bool needs_out = (o.format == "gradescope" || o.format == "prairielearn" || o.format == "html");
  if (needs_out && !single && o.out.empty()) {
    fmt::print(stderr, "raygrade grade: --format {} with several submissions needs --out DIR\n",
               o.format);
    return kExitBadInput;
  }
  if (!o.out.empty()) std::filesystem::create_directories(o.out);
  std::vector<SubmissionGrade> grades;
  std::set<std::string> names;
  std::string stream;  // what goes to standard output
  nlohmann::json all = nlohmann::json::array();
  Progress progress(files.size());
  std::size_t rejected = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    auto start = std::chrono::steady_clock::now();
    SubmissionGrade g = assignment.grade_file(files[i]);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!g.gradable) {
      ++rejected;
      if (!single || o.format == "csv") fmt::print(stderr, "{}\n", format_diagnostic(*g.fault));
    }
    for (const auto& d : g.findings) fmt::print(stderr, "{}\n", format_diagnostic(d));
    if (o.format != "csv") {
      if (!o.out.empty()) {
        std::string base = single && (o.format == "gradescope" || o.format == "prairielearn")
                               ? "results"
                               : safe_file_name(g.student);
        std::string name = base;
        for (int k = 2; !names.insert(name).second; ++k) name = fmt::format("{}-{}", base, k);
        write_file_atomically(std::filesystem::path(o.out) / (name + extension(o.format)),
                              render(g, o.format, seconds));
      } else if (o.format == "json") {
        all.push_back(submission_json(g));
      } else {
        stream += render(g, o.format, seconds);
      }
    }
    grades.push_back(std::move(g));
    progress.step(i + 1);
  }
  if (o.format == "csv") {
    std::vector<std::string> ids;
    for (const auto& gr : assignment.graders()) ids.push_back(gr.problem().id);
    std::string csv = gradebook_csv(grades, ids);
    if (o.out.empty()) {
      stream = csv;
    } else {
      write_file_atomically(std::filesystem::path(o.out) / "gradebook.csv", csv);
    }
  }
  if (o.format == "json" && o.out.empty())
    stream = nlohmann::json{{"submissions", all}}.dump(2, ' ', false,
                                                       nlohmann::json::error_handler_t::replace) +
             "\n";
  std::cout << stream;
  if (!o.out.empty()) {
    fmt::print(stderr, "Graded {} submissions into {}{}.\n", grades.size() - rejected, o.out,
               rejected ? fmt::format(" ({} rejected)", rejected) : "");
  }
  bool bad = rejected || !errors.empty() || !bank.errors.empty() || !assignment.errors().empty();
  return bad ? kExitBadInput : kExitOk;
}

}  // namespace

int grade_sample_submissions(const Bank& bank, const std::string& folder) {
  if (!std::filesystem::is_directory(folder)) return kExitOk;
  Assignment assignment(bank.problems, AssignmentOptions{true});
  for (const auto& e : assignment.errors()) fmt::print(stderr, "{}\n", format_diagnostic(e));
  std::vector<Diagnostic> errors;
  std::size_t answers = 0, rejected = 0, mistakes = 0;
  double score = 0, max_score = 0;
  std::vector<std::string> files = submission_files({folder}, errors);
  for (const auto& f : files) {
    SubmissionGrade g = assignment.grade_file(f);
    if (!g.gradable) {
      fmt::print(stderr, "{}\n", format_diagnostic(*g.fault));
      ++rejected;
      continue;
    }
    answers += g.results.size();
    mistakes += g.mistakes();
    score += g.score;
    max_score += g.max_score;
  }
  fmt::print("Graded {} sample submissions ({} answers): {} / {} points, {} named mistakes{}.\n",
             files.size() - rejected, answers, format_points(score), format_points(max_score),
             mistakes, rejected ? fmt::format(", {} rejected", rejected) : "");
  return rejected || !errors.empty() || !assignment.errors().empty() ? kExitBadInput : kExitOk;
}

Runner setup_grade(CLI::App& sub) {
  auto o = std::make_shared<GradeCliOptions>();
  sub.add_option("--problems", o->problems, "the bank: a file or folder (repeat for more)")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub.add_option("submissions", o->submissions, "submission files or folders")->required();
  sub.add_option("--format", o->format,
                 "text, json, gradescope, prairielearn, csv (a gradebook) or html");
  sub.add_option("--out", o->out, "a folder for one file per student (or gradebook.csv)");
  sub.add_flag("--answered-only", o->answered_only,
               "count only the problems each submission answers");
  return [o] { return run_grade(*o); };
}

}  // namespace raygrade::cli
