// raygrade grade: grade submissions against a bank, in the form an LMS or a person reads.
#include <fmt/format.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "assignments/gradebook.h"
#include "assignments/grading.h"
#include "assignments/lms_export.h"
#include "assignments/roster.h"
#include "assignments/variants.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "core/folder_lock.h"
#include "core/parallel.h"
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
  std::string assignment;  // an assignment file: each submission graded as its student's variant
  std::string roster;
  std::string pick = "latest";      // with --roster: which of a student's submissions counts
  std::string feedback;             // overrides the assignment's feedback policy
  std::string now;                  // the time the due date is compared with (default: the clock)
  std::string gradescope_metadata;  // submission_metadata.json: who uploaded the submission
  unsigned jobs = 0;                // threads that grade (0: one per core)
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

// The submission (a folder, or a submitted file's folder) that the folder `out` is or is inside:
// writing there could overwrite submissions before they are read.
std::optional<std::string> out_among_submissions(const std::string& out,
                                                 const std::vector<std::string>& submissions) {
  std::error_code ec;
  auto o = std::filesystem::weakly_canonical(out, ec);
  if (ec) return std::nullopt;
  for (const auto& s : submissions) {
    auto p = std::filesystem::weakly_canonical(s, ec);
    if (ec) continue;
    if (!std::filesystem::is_directory(p, ec)) p = p.parent_path();
    auto rel = o.lexically_relative(p);
    if (!rel.empty() && *rel.begin() != "..") return s;
  }
  return std::nullopt;
}

std::string lower_case(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

int run_grade(const GradeCliOptions& o) {
  const GradeFormat* format = find_grade_format(o.format);
  if (!format) {
    fmt::print(stderr, "raygrade grade: unknown format '{}' ({})\n", o.format,
               grade_format_names());
    return kExitBadInput;
  }
  bool platform_book = format->layout == GradeLayout::kClassGradebook;
  bool gradebook = format->layout == GradeLayout::kGradebook || platform_book;
  if (platform_book && o.roster.empty()) {
    fmt::print(stderr,
               "raygrade grade: --format {} needs --assignment and --roster (a row per roster "
               "student)\n",
               o.format);
    return kExitBadInput;
  }
  std::optional<PickPolicy> pick = parse_pick_policy(o.pick);
  if (!pick) {
    fmt::print(stderr, "raygrade grade: unknown --pick '{}' (latest, best, first)\n", o.pick);
    return kExitBadInput;
  }
  std::vector<StudentIdentity> roster;
  // What grades one file, and the problems in gradebook order: the bank's, or an assignment's.
  std::function<SubmissionGrade(const std::string&)> grade_one;
  std::vector<std::string> ids;
  std::vector<Diagnostic> setup_errors;
  Bank bank;
  std::unique_ptr<Assignment> assignment;
  std::unique_ptr<AssignmentSpec> spec;
  std::unique_ptr<AssignmentBank> spec_bank;
  std::unique_ptr<AssignmentGrader> spec_grader;
  std::unique_ptr<AssignmentGrader> worked_grader;  // full feedback, for Gradescope
  if (o.assignment.empty()) {
    if (!o.roster.empty() || !o.feedback.empty() || !o.now.empty() ||
        !o.gradescope_metadata.empty()) {
      fmt::print(stderr,
                 "raygrade grade: --roster, --feedback, --now and --gradescope-metadata go with "
                 "--assignment\n");
      return kExitBadInput;
    }
    bank = load_bank(o.problems);
    setup_errors = bank.errors;
    assignment = std::make_unique<Assignment>(bank.problems, AssignmentOptions{o.answered_only});
    setup_errors.insert(setup_errors.end(), assignment->errors().begin(),
                        assignment->errors().end());
    for (const auto& gr : assignment->graders()) ids.push_back(gr.problem().id);
    grade_one = [&](const std::string& f) { return assignment->grade_file(f); };
  } else {
    AssignmentGradeOptions options;
    std::optional<std::int64_t> submitted;  // Gradescope's time of the submission
    try {
      spec = std::make_unique<AssignmentSpec>(load_assignment(o.assignment));
      if (!o.roster.empty()) roster = options.roster = load_roster(o.roster);
      if (!o.gradescope_metadata.empty()) {
        GradescopeMetadata m = read_gradescope_metadata(o.gradescope_metadata);
        options.uploaders = std::move(m.users);
        submitted = m.submitted;
        // Gradescope's due date, with the student's extension, is the one students were given.
        if (m.due) spec->due = m.due;
      }
    } catch (const Error& e) {
      fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
      return kExitBadInput;
    }
    if (!o.feedback.empty()) {
      options.feedback = parse_feedback_policy(o.feedback);
      if (!options.feedback) {
        fmt::print(stderr, "raygrade grade: unknown feedback policy '{}' (score, mistakes, full)\n",
                   o.feedback);
        return kExitBadInput;
      }
    }
    // The time the feedback policy is taken at: --now, else Gradescope's time of the
    // submission, else the clock.
    auto now =
        !o.now.empty() ? parse_time(o.now)
        : submitted
            ? submitted
            : std::optional<std::int64_t>(std::chrono::duration_cast<std::chrono::seconds>(
                                              std::chrono::system_clock::now().time_since_epoch())
                                              .count());
    if (!now) {
      fmt::print(stderr,
                 "raygrade grade: --now '{}' is not a date and time (2026-12-04T23:59:00Z)\n",
                 o.now);
      return kExitBadInput;
    }
    options.now = *now;
    spec_bank = std::make_unique<AssignmentBank>(load_assignment_bank(*spec));
    setup_errors = spec_bank->errors;
    if (spec_bank->problems.size() != spec->problems.size()) {
      for (const auto& e : setup_errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
      return kExitBadInput;
    }
    spec_grader = std::make_unique<AssignmentGrader>(*spec, spec_bank->problems, options);
    ids = spec_grader->problem_ids();
    grade_one = [&](const std::string& f) { return spec_grader->grade_file(f); };
    if (format->full_feedback_too && !options.feedback && spec->due && options.now <= *spec->due) {
      // The feedback the policy allows after the due date too, which Gradescope shows once it
      // has passed: never more than that policy (an override holds at all times).
      options.now = *spec->due + 1;
      worked_grader = std::make_unique<AssignmentGrader>(*spec, spec_bank->problems, options);
    }
  }
  for (const auto& e : setup_errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  std::vector<Diagnostic> errors;
  std::vector<std::string> files = submission_files(o.submissions, errors);
  for (const auto& e : errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  bool single = files.size() == 1 && errors.empty();
  if (format->needs_out && !single && o.out.empty()) {
    fmt::print(stderr, "raygrade grade: --format {} with several submissions needs --out DIR\n",
               o.format);
    return kExitBadInput;
  }
  if (!o.out.empty()) {
    if (auto s = out_among_submissions(o.out, o.submissions)) {
      fmt::print(stderr,
                 "raygrade grade: --out {} is inside the submissions ({}), whose files it could "
                 "overwrite; choose a folder outside them\n",
                 printable(o.out), printable(*s));
      return kExitBadInput;
    }
  }
  std::optional<FolderLock> lock;
  if (!o.out.empty()) {
    std::filesystem::create_directories(o.out);
    // One grader per folder at a time; then what a killed one left half-written can go.
    lock.emplace(o.out, "raygrade grade");
    for (const auto& name : remove_stale_temporaries(o.out))
      fmt::print(stderr, "raygrade grade: removed {}, left by an interrupted run\n",
                 printable(name));
  }
  std::set<std::string> names = {"index", "gradebook"};  // the folder's own files
  std::vector<FeedbackPage> pages;
  // The gradebook on standard output goes a row at a time; a file is written whole at the end.
  std::ostringstream csv_file;
  // With a roster, the gradebook has one row per roster student, written at the end.
  std::optional<RosterGradebook> class_book;
  if (gradebook && !roster.empty()) class_book.emplace(roster, ids, *pick);
  if (gradebook && !class_book) (o.out.empty() ? std::cout : csv_file) << gradebook_csv_header(ids);
  JsonArrayStream json_out(std::cout);
  Progress progress(files.size());
  std::size_t rejected = 0, internal = 0, resource = 0;
  // The files of each student (by the key their variant is drawn for), to find the doubles.
  std::map<std::string, std::vector<std::string>> by_student;
  auto spec_key_of = [&](const SubmissionGrade& g) {
    return spec && g.gradable && !g.identity.empty() ? student_key(g.identity) : std::string();
  };
  // What a thread makes of one file; the main thread writes them out in the files' order.
  struct Graded {
    SubmissionGrade grade;
    std::string text;  // the gradebook row, the submission's JSON, or the file or page rendered
  };
  bool json_stream = format->layout == GradeLayout::kJsonArray && o.out.empty();
  auto grade_at = [&](std::size_t i) {
    auto start = std::chrono::steady_clock::now();
    Graded r{grade_one(files[i]), {}};
    std::optional<SubmissionGrade> worked;
    if (worked_grader) worked = worked_grader->grade_file(files[i]);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (gradebook)
      r.text = gradebook_csv_row(r.grade, ids);
    else if (json_stream)
      r.text = json_text(submission_json(r.grade));
    else
      r.text = format->render(r.grade, seconds, worked ? &*worked : nullptr);
    return r;
  };
  // A window of files at a time, so that memory stays bounded whatever the batch's size.
  unsigned jobs = o.jobs > 0 ? o.jobs : default_jobs();
  std::size_t window = 64 * std::size_t{jobs};
  for (std::size_t begin = 0; begin < files.size(); begin += window) {
    std::size_t count = std::min(window, files.size() - begin);
    auto graded =
        parallel_map<Graded>(count, jobs, [&](std::size_t k) { return grade_at(begin + k); });
    for (std::size_t k = 0; k < count; ++k) {
      const SubmissionGrade& g = graded[k].grade;
      if (!g.gradable) {
        ++rejected;
        internal += g.fault && g.fault->code == "internal";
        resource += g.fault && g.fault->code == "resource";
        if (!single || gradebook) fmt::print(stderr, "{}\n", format_diagnostic(*g.fault));
      }
      for (const auto& d : g.findings) fmt::print(stderr, "{}\n", format_diagnostic(d));
      if (class_book) {
        class_book->add(g);
      } else if (gradebook) {
        (o.out.empty() ? std::cout : csv_file) << graded[k].text;
      } else if (!o.out.empty()) {
        // Named by the student's id where there is one (a name can be anything, in any
        // script), compared in lower case as macOS's and Windows's file systems compare.
        std::string base = single && format->results_file ? "results"
                           : !g.identity.id.empty()       ? safe_file_name(g.identity.id)
                                                          : safe_file_name(g.student);
        std::string name = base;
        for (int n = 2; !names.insert(lower_case(name)).second; ++n)
          name = fmt::format("{}-{}", base, n);
        if (format->extension == ".html")
          pages.push_back(
              {name + ".html", g.student, g.identity.id, g.gradable, g.score, g.max_score});
        // Each file appears whole or not at all (rename); the batch reaches the disk in one
        // flush at the end instead of one per file.
        write_file_atomically(
            std::filesystem::path(o.out) / (name + std::string(format->extension)), graded[k].text,
            false);
      } else if (json_stream) {
        json_out.add(graded[k].text);
      } else {
        std::cout << graded[k].text;
      }
      if (!class_book && !spec_key_of(g).empty()) by_student[spec_key_of(g)].push_back(g.file);
      progress.step(begin + k + 1);
    }
  }
  if (class_book) {
    (o.out.empty() ? std::cout : csv_file)
        << (platform_book ? class_book->platform_csv(format->name,
                                                     spec->title.empty() ? spec->id : spec->title)
                          : class_book->csv());
    for (const auto& c : class_book->choices())
      fmt::print(stderr, "raygrade grade: {}\n", printable(c));
  }
  if (!pages.empty())
    write_file_atomically(std::filesystem::path(o.out) / "index.html", feedback_index_html(pages),
                          false);
  if (gradebook && !o.out.empty())
    write_file_atomically(
        std::filesystem::path(o.out) / ("gradebook" + std::string(format->extension)),
        csv_file.str(), false);
  // Two files of one student are both graded, and never silently.
  for (const auto& [key, of] : by_student) {
    if (of.size() < 2) continue;
    std::string list;
    for (const auto& f : of) list += fmt::format("{}{}", list.empty() ? "" : ", ", printable(f));
    fmt::print(stderr,
               "raygrade grade: warning: student '{}' has {} submissions, each graded: {}\n",
               printable(key), of.size(), list);
  }
  if (json_stream) json_out.finish();
  std::cout.flush();
  if (!o.out.empty()) {
    flush_folder(o.out);
    fmt::print(stderr, "Graded {} submissions into {}{}.\n", files.size() - rejected, o.out,
               rejected ? fmt::format(" ({} rejected)", rejected) : "");
  }
  bool bad = rejected || !errors.empty() || !setup_errors.empty();
  return internal ? kExitInternal : resource ? kExitResource : bad ? kExitBadInput : kExitOk;
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
  auto* problems =
      sub.add_option("--problems", o->problems, "the bank: a file or folder (repeat for more)")
          ->allow_extra_args(false)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub.add_option("submissions", o->submissions, "submission files or folders")->required();
  std::string formats;
  for (const auto& f : grade_formats()) formats += fmt::format("\n  {:<13} {}", f.name, f.summary);
  sub.add_option("--format", o->format, "one of (default: text):" + formats);
  sub.add_option("--out", o->out, "a folder for one file per student (or gradebook.csv)");
  sub.add_flag("--answered-only", o->answered_only,
               "count only the problems each submission answers");
  sub.add_option("--assignment", o->assignment,
                 "an assignment file: each submission is graded as the variant of its student");
  sub.add_option("--roster", o->roster,
                 "with --assignment: a roster CSV (id, name, email); every student must be on it");
  sub.add_option("--pick", o->pick,
                 "with --roster, for the gradebook: which of a student's several submissions "
                 "counts: latest (by its \"submitted\" time, then the file's), best or first")
      ->capture_default_str();
  sub.add_option("--feedback", o->feedback,
                 "with --assignment: score, mistakes or full, whatever the assignment says");
  sub.add_option("--gradescope-metadata", o->gradescope_metadata,
                 "with --assignment: Gradescope's submission_metadata.json; the student a "
                 "submission names must be the account that uploaded it");
  sub.add_option("-j,--jobs", o->jobs,
                 "threads that grade at once (default: one per core); the output is the same");
  sub.add_option("--now", o->now,
                 "with --assignment: the time compared with the due date (default: now)");
  return [o, problems] {
    if (problems->count() > 0 && !o->assignment.empty()) {
      fmt::print(stderr,
                 "raygrade grade: --problems does not go with --assignment (the "
                 "assignment names its bank)\n");
      return static_cast<int>(kExitBadInput);
    }
    return run_grade(*o);
  };
}

}  // namespace raygrade::cli
