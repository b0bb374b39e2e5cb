// raygrade grade: grade submissions against a bank, in the form an LMS or a person reads. The
// platforms' gradebook layouts, bulk downloads, worksheets and upload metadata, and their
// options, come from the list of platforms (assignments/platforms/platforms.h).
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

#include "assignments/bulk_submissions.h"
#include "assignments/gradebook.h"
#include "assignments/grading.h"
#include "assignments/platforms/platforms.h"
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
  std::string pick;      // with --roster: which of a student's submissions counts
  std::string feedback;  // overrides the assignment's feedback policy
  std::string now;       // the time the due date is compared with (default: the clock)
  // A platform's metadata of an upload (who uploaded it), by the platform's option
  // (PlatformUploads::option).
  std::map<std::string_view, std::string> uploads;
  // A platform's worksheet, by the platform's option (PlatformWorksheet::option): filled in, or
  // the zip of feedback pages laid out for it, or what ties its bulk download to students.
  std::map<std::string_view, std::string> worksheets;
  // The platform's id of the grade column, by the layout's option (GradebookLayout::
  // column_option).
  std::map<std::string_view, std::optional<std::string>> column_ids;
  unsigned jobs = 0;  // threads that grade (0: one per core)

  // The one upload metadata or worksheet given (its platform and file), if any.
  std::pair<const PlatformEntry*, std::string> upload() const {
    for (const PlatformEntry& p : platform_table()) {
      if (p.uploads && !uploads.at(p.uploads->option).empty())
        return {&p, uploads.at(p.uploads->option)};
    }
    return {nullptr, ""};
  }
  std::pair<const PlatformEntry*, std::string> worksheet() const {
    for (const PlatformEntry& p : platform_table()) {
      if (p.worksheet && !worksheets.at(p.worksheet->option).empty())
        return {&p, worksheets.at(p.worksheet->option)};
    }
    return {nullptr, ""};
  }
  // The column id given, and its option (empty when none is given).
  std::pair<std::string_view, std::optional<std::string>> column_id() const {
    for (const auto& [option, id] : column_ids) {
      if (id) return {option, id};
    }
    return {"", std::nullopt};
  }
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
    // A platform's zip is read whole before anything is written: --out may be beside it
    // (however either is written), only not the zip itself.
    if (is_zip_path(s) && !std::filesystem::is_directory(p, ec)) {
      if (o == p) return s;
      continue;
    }
    if (!std::filesystem::is_directory(p, ec)) p = p.parent_path();
    auto rel = o.lexically_relative(p);
    if (!rel.empty() && *rel.begin() != "..") return s;
  }
  return std::nullopt;
}

// What grades one file, the problems in gradebook order, and what the setting-up found: from
// the bank, or from an assignment (each student's own variant).
struct GradeSetup {
  std::function<SubmissionGrade(const std::string&, std::optional<FileIdentity>)> grade_one;
  std::vector<std::string> ids;
  std::vector<Diagnostic> errors;
  std::vector<StudentIdentity> roster;
  RosterColumns platform_ids;  // the roster's columns of platforms' user ids
  std::string title;           // the assignment's title (or id), for a platform's gradebook
  bool per_student = false;    // graded as each student's variant: doubles are looked for
  Bank bank;
  std::unique_ptr<Assignment> assignment;
  std::unique_ptr<AssignmentSpec> spec;
  std::unique_ptr<AssignmentBank> spec_bank;
  std::unique_ptr<AssignmentGrader> spec_grader;
  const PlatformEntry* worksheet_platform = nullptr;  // whose worksheet was given, if any
  Worksheet worksheet;  // the platform's worksheet, read before grading
};

// A usage fault: printed, and the exit code for it.
int usage(std::string_view message) {
  fmt::print(stderr, "raygrade grade: {}\n", message);
  return kExitBadInput;
}

std::optional<int> setup_from_bank(const GradeCliOptions& o, GradeSetup& s) {
  auto [uploader, metadata] = o.upload();
  if (!o.roster.empty() || !o.feedback.empty() || !o.now.empty() || uploader)
    return usage(fmt::format("--roster, --feedback, --now{} go with --assignment",
                             uploader ? fmt::format(" and {}", uploader->uploads->option) : ""));
  s.bank = load_bank(o.problems);
  s.errors = s.bank.errors;
  s.assignment = std::make_unique<Assignment>(s.bank.problems, AssignmentOptions{o.answered_only});
  s.errors.insert(s.errors.end(), s.assignment->errors().begin(), s.assignment->errors().end());
  for (const auto& gr : s.assignment->graders()) s.ids.push_back(gr.problem().id);
  s.grade_one = [a = s.assignment.get()](const std::string& f, std::optional<FileIdentity> seen) {
    return a->grade_file(f, seen);
  };
  return std::nullopt;
}

std::optional<int> setup_from_assignment(const GradeCliOptions& o, GradeSetup& s) {
  AssignmentGradeOptions options;
  try {
    s.spec = std::make_unique<AssignmentSpec>(load_assignment(o.assignment));
    if (!o.roster.empty()) s.roster = options.roster = load_roster(o.roster, &s.platform_ids);
    if (auto [platform, file] = o.worksheet(); platform) {
      s.worksheet_platform = platform;
      s.worksheet = {file, platform->worksheet->read(file)};
    }
    if (auto [platform, file] = o.upload(); platform) {
      UploadMetadata m = platform->uploads->read(file);
      options.uploaders = std::move(m.users);
      options.uploads_platform = platform->name;
      // The platform's due date, with the student's extension, is the one students were given.
      if (m.due) s.spec->due = m.due;
    }
  } catch (const Error& e) {
    fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
    return kExitBadInput;
  }
  if (!o.feedback.empty()) {
    options.feedback = parse_feedback_policy(o.feedback);
    if (!options.feedback)
      return usage(fmt::format("unknown feedback policy '{}' (score, mistakes, full)", o.feedback));
  }
  // The time the feedback policy is taken at: --now, else the clock. On Gradescope that is
  // when the upload is graded, so grading again after the due date gives the after_due policy.
  auto now =
      !o.now.empty()
          ? parse_time(o.now)
          : std::optional<std::int64_t>(std::chrono::duration_cast<std::chrono::seconds>(
                                            std::chrono::system_clock::now().time_since_epoch())
                                            .count());
  if (!now)
    return usage(fmt::format("--now '{}' is not a date and time (2026-12-04T23:59:00Z)", o.now));
  options.now = *now;
  s.spec_bank = std::make_unique<AssignmentBank>(load_assignment_bank(*s.spec));
  s.errors = s.spec_bank->errors;
  if (s.spec_bank->problems.size() != s.spec->problems.size()) {
    for (const auto& e : s.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
    return kExitBadInput;
  }
  s.spec_grader = std::make_unique<AssignmentGrader>(*s.spec, s.spec_bank->problems, options);
  s.ids = s.spec_grader->problem_ids();
  s.title = s.spec->title.empty() ? s.spec->id : s.spec->title;
  s.per_student = true;
  s.grade_one = [g = s.spec_grader.get()](const std::string& f, std::optional<FileIdentity> seen) {
    return g->grade_file(f, seen);
  };
  return std::nullopt;
}

// Each roster student's cell of the roster column of the platform whose gradebook layout
// `format` is ("" each when it reads none).
std::vector<std::string> platform_ids(const GradeSetup& setup, const GradeFormat& format) {
  for (const PlatformEntry& p : platform_table()) {
    if (!p.gradebook || p.gradebook->format != format.name) continue;
    auto it = setup.platform_ids.find(p.roster_column);
    if (it != setup.platform_ids.end()) return it->second;
  }
  return {};
}

// What a thread makes of one file; the main thread writes them out in the files' order.
struct Graded {
  SubmissionGrade grade;
  std::string text;  // the gradebook row, the submission's JSON, or the file or page rendered
};

// Where graded files go, in the files' order: standard output, one file each in --out, or a
// gradebook (a row per file, or with a roster a row per roster student, written at the end).
class GradeOutput {
 public:
  GradeOutput(const GradeCliOptions& o, const GradeFormat& format, const GradeSetup& setup,
              PickPolicy pick, bool single)
      : o_(o), format_(format), setup_(setup), single_(single), json_out_(std::cout) {
    platform_book_ = format.layout == GradeLayout::kClassGradebook;
    gradebook_ = format.layout == GradeLayout::kGradebook || platform_book_;
    json_stream_ = format.layout == GradeLayout::kJsonArray && o.out.empty();
    if (gradebook_ && !setup.roster.empty()) {
      class_book_.emplace(setup.roster, setup.ids, pick);
      class_book_->set_platform_ids(platform_ids(setup, format));
    }
    if (gradebook_ && !class_book_) csv() << gradebook_csv_header(setup.ids);
  }

  // The text a file's grade is written as (run on the grading threads).
  std::string render(const SubmissionGrade& g, double seconds) const {
    if (gradebook_) return gradebook_csv_row(g, setup_.ids);
    if (json_stream_) return json_text(submission_json(g));
    return format_.render(g, seconds);
  }

  void add(const Graded& graded) {
    const SubmissionGrade& g = graded.grade;
    if (!g.gradable) {
      ++rejected;
      internal += g.fault && g.fault->code == "internal";
      resource += g.fault && g.fault->code == "resource";
      if (!single_ || gradebook_) fmt::print(stderr, "{}\n", format_diagnostic(*g.fault));
    }
    for (const auto& d : g.findings) fmt::print(stderr, "{}\n", format_diagnostic(d));
    if (class_book_) {
      class_book_->add(g);
    } else if (gradebook_) {
      csv() << graded.text;
    } else if (!o_.out.empty()) {
      write_one(g, graded.text);
    } else if (json_stream_) {
      json_out_.add(graded.text);
    } else {
      std::cout << graded.text;
    }
    if (!class_book_ && setup_.per_student && g.gradable && !g.identity.empty())
      by_student_[student_key(g.identity)].push_back(g.file);
  }

  void finish() {
    if (class_book_) {
      if (setup_.worksheet_platform) {
        std::vector<std::string> notes;
        csv() << setup_.worksheet_platform->worksheet->fill(class_book_->class_rows(),
                                                            setup_.worksheet, notes);
        for (const auto& n : notes)
          fmt::print(stderr, "raygrade grade: warning: {}\n", printable(n));
      } else {
        csv() << (platform_book_ ? platform_gradebook(format_.name, class_book_->class_rows(),
                                                      setup_.title, column_id_)
                                 : class_book_->csv());
      }
      for (const auto& c : class_book_->choices())
        fmt::print(stderr, "raygrade grade: {}\n", printable(c));
    }
    std::filesystem::path out(o_.out);
    if (!pages_.empty())
      write_file_atomically(out / "index.html", feedback_index_html(pages_), false);
    if (format_.extension == ".html" && setup_.worksheet_platform) {
      const PlatformWorksheet& w = *setup_.worksheet_platform->worksheet;
      std::vector<std::string> notes;
      std::vector<ZipEntry> files =
          w.feedback(setup_.worksheet, setup_.roster, sheet_pages_, notes);
      for (const auto& n : notes) fmt::print(stderr, "raygrade grade: warning: {}\n", printable(n));
      write_file_atomically(out / std::string(w.feedback_zip), zip_archive(files), false);
    }
    if (gradebook_ && !o_.out.empty())
      write_file_atomically(out / ("gradebook" + std::string(format_.extension)), csv_file_.str(),
                            false);
    // Two files of one student are both graded, and never silently.
    for (const auto& [key, of] : by_student_) {
      if (of.size() < 2) continue;
      std::string list;
      for (const auto& f : of) list += fmt::format("{}{}", list.empty() ? "" : ", ", printable(f));
      fmt::print(stderr,
                 "raygrade grade: warning: student '{}' has {} submissions, each graded: {}\n",
                 printable(key), of.size(), list);
    }
    if (json_stream_) json_out_.finish();
    std::cout.flush();
  }

  std::size_t rejected = 0, internal = 0, resource = 0;

 private:
  // The gradebook on standard output goes a row at a time; a file is written whole at the end.
  std::ostream& csv() { return o_.out.empty() ? std::cout : csv_file_; }

  void write_one(const SubmissionGrade& g, const std::string& text) {
    // Named by the student's id where there is one (a name can be anything, in any script),
    // compared in lower case as macOS's and Windows's file systems compare.
    std::string name =
        single_ && format_.results_file
            ? "results"
            : unique_file_name(g.identity.id.empty() ? g.student : g.identity.id, names_);
    if (format_.extension == ".html") {
      pages_.push_back(
          {name + ".html", g.student, g.identity.id, g.gradable, g.score, g.max_score});
      if (setup_.worksheet_platform && g.gradable && !g.identity.id.empty())
        sheet_pages_.push_back({g.identity.id, name + ".html", text});
    }
    // Each file appears whole or not at all (rename); the batch reaches the disk in one flush
    // at the end instead of one per file.
    write_file_atomically(std::filesystem::path(o_.out) / (name + std::string(format_.extension)),
                          text, false);
  }

  const GradeCliOptions& o_;
  std::string column_id_ = o_.column_id().second.value_or("");
  const GradeFormat& format_;
  const GradeSetup& setup_;
  bool single_, platform_book_, gradebook_, json_stream_;
  std::set<std::string> names_ = {"index", "gradebook"};  // the folder's own files
  std::vector<FeedbackPage> pages_;
  std::vector<StudentPage> sheet_pages_;  // with a platform's worksheet: for its feedback zip
  std::ostringstream csv_file_;
  std::optional<RosterGradebook> class_book_;
  JsonArrayStream json_out_;
  // The files of each student (by the key their variant is drawn for), to find the doubles.
  std::map<std::string, std::vector<std::string>> by_student_;
};

// The --out folder: outside the submissions, locked, and cleared of what a killed run left.
std::optional<int> prepare_out(const GradeCliOptions& o, std::optional<FolderLock>& lock) {
  if (o.out.empty()) return std::nullopt;
  if (auto s = out_among_submissions(o.out, o.submissions))
    return usage(fmt::format(
        "--out {} is inside the submissions ({}), whose files it could overwrite; choose a "
        "folder outside them",
        printable(o.out), printable(*s)));
  std::filesystem::create_directories(o.out);
  // One grader per folder at a time; then what a killed one left half-written can go.
  lock.emplace(o.out, "raygrade grade");
  for (const auto& name : remove_stale_temporaries(o.out))
    fmt::print(stderr, "raygrade grade: removed {}, left by an interrupted run\n", printable(name));
  return std::nullopt;
}

// The files of the platforms' bulk-download zips among the submissions (docs/assignments.md):
// they need the assignment and its roster, which tie the platforms' ids to students. A zip that
// cannot be read is an error of its own; its fellows are still graded.
std::optional<int> read_bulk_zips(const GradeCliOptions& o, const GradeSetup& setup,
                                  std::vector<BulkSubmission>& bulk,
                                  std::vector<Diagnostic>& errors) {
  BulkInput roster{&setup.roster, &setup.platform_ids, {}};
  if (setup.worksheet_platform)
    roster.worksheets[setup.worksheet_platform->title] = &setup.worksheet;
  for (const auto& p : o.submissions) {
    if (!is_zip_path(p)) continue;
    if (!setup.per_student || setup.roster.empty())
      return usage(fmt::format(
          "{} is a platform's zip of submissions: grading it needs --assignment and --roster "
          "(the roster ties the platform's students to their ids)",
          printable(p)));
    try {
      std::vector<BulkSubmission> got = read_bulk_submissions(p, bulk_formats(), roster);
      for (auto& b : got) bulk.push_back(std::move(b));
    } catch (const Error& e) {
      errors.push_back(e.diagnostic());
    }
  }
  return std::nullopt;
}

// A file of a bulk zip graded, or its fault when it could not be tied to a student or read.
SubmissionGrade grade_bulk(const GradeSetup& setup, const BulkSubmission& b) {
  if (!b.fault)
    return setup.spec_grader->grade_handed_in(b.file, b.text, b.modified, *b.owner, b.platform);
  SubmissionGrade g;
  g.file = b.file;
  g.gradable = false;
  g.fault = b.fault;
  g.file_time = b.modified;
  if (b.claimed) g.claimed = *b.claimed;
  g.student = b.claimed && !b.claimed->name.empty() ? b.claimed->name : b.file;
  return g;
}

// The platforms' own options, each with what it goes with: the exit code of a fault.
std::optional<int> check_platform_options(const GradeCliOptions& o) {
  if (auto [platform, file] = o.worksheet(); platform) {
    std::string_view layout = platform->gradebook ? platform->gradebook->format : "";
    if (o.roster.empty() || !(o.format == layout || (o.format == "html" && !o.out.empty())))
      return usage(fmt::format(
          "{} goes with --roster, and --format {} (the worksheet filled in) or --format html "
          "--out DIR (a zip of feedback files for {})",
          platform->worksheet->option, layout, platform->title));
  }
  for (const GradebookLayout& g : gradebook_layouts()) {
    if (!g.column_option.empty() && o.column_ids.at(g.column_option) && o.format != g.format)
      return usage(fmt::format("{} goes with --format {}", g.column_option, g.format));
  }
  for (const auto& [option, id] : o.column_ids) {
    if (id && id->empty())
      return usage(
          fmt::format("{} is empty: give the platform's id of the column (digits)", option));
  }
  return std::nullopt;
}

int run_grade(const GradeCliOptions& o) {
  const GradeFormat* format = find_grade_format(o.format);
  if (!format)
    return usage(fmt::format("unknown format '{}' ({})", o.format, grade_format_names()));
  if (format->layout == GradeLayout::kClassGradebook && o.roster.empty())
    return usage(fmt::format(
        "--format {} needs --assignment and --roster (a row per roster student)", o.format));
  if (auto failed = check_platform_options(o)) return *failed;
  if (!o.pick.empty() && o.roster.empty())
    return usage("--pick chooses among a roster student's submissions: it needs --roster");
  std::optional<PickPolicy> pick = parse_pick_policy(o.pick.empty() ? "latest" : o.pick);
  if (!pick) return usage(fmt::format("unknown --pick '{}' (latest, best, first)", o.pick));
  GradeSetup setup;
  if (auto failed =
          o.assignment.empty() ? setup_from_bank(o, setup) : setup_from_assignment(o, setup))
    return *failed;
  for (const auto& e : setup.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  // A grade column the platform would misread is refused before anything is graded.
  if (format->layout == GradeLayout::kClassGradebook && !setup.worksheet_platform) {
    const GradebookLayout* layout = find_gradebook_layout(o.format);
    if (!layout)
      return usage(fmt::format("--format {} is no platform's gradebook layout", o.format));
    ColumnCheck column = layout->check(setup.title, o.column_id().second.value_or(""));
    if (!column.error.empty()) return usage(column.error);
    if (!column.warning.empty())
      fmt::print(stderr, "raygrade grade: warning: {}\n", column.warning);
  }
  std::vector<Diagnostic> errors;
  std::vector<BulkSubmission> bulk;
  if (auto failed = read_bulk_zips(o, setup, bulk, errors)) return *failed;
  std::vector<std::string> paths;
  for (const auto& p : o.submissions) {
    if (!is_zip_path(p)) paths.push_back(p);
  }
  std::vector<std::optional<FileIdentity>> seen;
  std::vector<std::string> files =
      paths.empty() ? std::vector<std::string>{} : submission_files(paths, errors, &seen);
  for (const auto& e : errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  std::size_t total = files.size() + bulk.size();
  bool single = total == 1 && errors.empty();
  if (format->needs_out && !single && o.out.empty())
    return usage(fmt::format("--format {} with several submissions needs --out DIR", o.format));
  std::optional<FolderLock> lock;
  if (auto failed = prepare_out(o, lock)) return *failed;
  GradeOutput output(o, *format, setup, *pick, single);
  auto grade_at = [&](std::size_t i) {
    auto start = std::chrono::steady_clock::now();
    Graded r{i < files.size() ? setup.grade_one(files[i], seen[i])
                              : grade_bulk(setup, bulk[i - files.size()]),
             {}};
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.text = output.render(r.grade, seconds);
    return r;
  };
  // A window of files at a time, so that memory stays bounded whatever the batch's size.
  Progress progress(total);
  unsigned jobs = o.jobs > 0 ? o.jobs : default_jobs();
  std::size_t window = 64 * std::size_t{jobs};
  for (std::size_t begin = 0; begin < total; begin += window) {
    std::size_t count = std::min(window, total - begin);
    auto graded =
        parallel_map<Graded>(count, jobs, [&](std::size_t k) { return grade_at(begin + k); });
    for (std::size_t k = 0; k < count; ++k) {
      output.add(graded[k]);
      progress.step(begin + k + 1);
    }
  }
  output.finish();
  if (!o.out.empty()) {
    flush_folder(o.out);
    fmt::print(stderr, "Graded {} submissions into {}{}.\n", total - output.rejected, o.out,
               output.rejected ? fmt::format(" ({} rejected)", output.rejected) : "");
  }
  bool bad = output.rejected || !errors.empty() || !setup.errors.empty();
  return output.internal   ? kExitInternal
         : output.resource ? kExitResource
         : bad             ? kExitBadInput
                           : kExitOk;
}

}  // namespace

int grade_sample_submissions(const Bank& bank, const std::string& folder) {
  if (!std::filesystem::is_directory(folder)) return kExitOk;
  Assignment assignment(bank.problems, AssignmentOptions{true});
  for (const auto& e : assignment.errors()) fmt::print(stderr, "{}\n", format_diagnostic(e));
  std::vector<Diagnostic> errors;
  std::size_t answers = 0, rejected = 0, mistakes = 0;
  double score = 0, max_score = 0;
  std::vector<std::optional<FileIdentity>> seen;
  std::vector<std::string> files = submission_files({folder}, errors, &seen);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string& f = files[i];
    SubmissionGrade g = assignment.grade_file(f, seen[i]);
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
  std::string bulk;
  for (const BulkFormat& f : bulk_formats())
    bulk += fmt::format("{}{}", bulk.empty() ? "" : " or ", f.title);
  sub.add_option("submissions", o->submissions,
                 fmt::format("submission files or folders, or the zip of a {} assignment's "
                             "\"download all submissions\" (with --assignment and --roster)",
                             bulk))
      ->required();
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
                 "counts: latest (the default: by its \"submitted\" time, then the file's), best "
                 "or first");
  sub.add_option("--feedback", o->feedback,
                 "with --assignment: score, mistakes or full, whatever the assignment says");
  for (const PlatformEntry& p : platform_table()) {
    if (p.uploads)
      sub.add_option(std::string(p.uploads->option), o->uploads[p.uploads->option],
                     fmt::format("with --assignment: {}", p.uploads->help));
    if (p.worksheet)
      sub.add_option(std::string(p.worksheet->option), o->worksheets[p.worksheet->option],
                     fmt::format("with --roster: {}", p.worksheet->help));
    if (p.gradebook && !p.gradebook->column_option.empty())
      sub.add_option(
          std::string(p.gradebook->column_option), o->column_ids[p.gradebook->column_option],
          fmt::format("with --format {}: {}", p.gradebook->format, p.gradebook->column_help));
  }
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
