// raygrade export: an assignment made ready for a learning platform (Gradescope, PrairieLearn).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "assignments/lms_export.h"
#include "cli/command.h"

namespace raygrade::cli {
namespace {

struct ExportOptions {
  std::string platform;
  std::string assignment;
  std::string out;
  std::string binary;
  std::string roster;     // Gradescope: the class roster, which ties accounts to student ids
  std::string grader_js;  // SCORM: raygrade.js, which grades in the student's browser
  std::string scorm;      // SCORM: the version, "1.2" or "2004"
  int sets = 0;           // Canvas and Moodle: how many sets of numbers
};

// The platforms' names, for help and errors: "gradescope, prairielearn".
std::string platform_names() {
  std::vector<std::string> names;
  for (const LmsExport& e : lms_exports()) names.emplace_back(e.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

int run_export(const ExportOptions& o) {
  const LmsExport* platform = find_lms_export(o.platform);
  if (!platform) {
    fmt::print(stderr, "raygrade export: unknown platform '{}' ({})\n", o.platform,
               platform_names());
    return kExitBadInput;
  }
  if (!o.roster.empty() && !platform->takes_roster) {
    fmt::print(stderr, "raygrade export: {} takes no --roster\n", platform->name);
    return kExitBadInput;
  }
  if (!o.grader_js.empty() && !platform->takes_grader_js) {
    fmt::print(stderr,
               "raygrade export: {} takes no --grader-js (it runs no grader in the browser)\n",
               platform->name);
    return kExitBadInput;
  }
  if (o.sets != 0 && platform->name != "canvas" && platform->name != "moodle") {
    fmt::print(stderr, "raygrade export: {} takes no --sets\n", platform->name);
    return kExitBadInput;
  }
  if (!o.scorm.empty() && platform->name != "scorm") {
    fmt::print(stderr, "raygrade export: {} takes no --scorm (the SCORM version)\n",
               platform->name);
    return kExitBadInput;
  }
  if (platform->takes_grader_js) {
    // Checked first, so that a missing raygrade.js is named before the assignment is read.
    std::error_code ec;
    if (o.grader_js.empty()) {
      fmt::print(stderr,
                 "raygrade export: {} needs --grader-js FILE, the web build's raygrade.js "
                 "(scripts/build-web.sh builds build/web/web/raygrade.js)\n",
                 platform->name);
      return kExitBadInput;
    }
    if (!std::filesystem::is_regular_file(o.grader_js, ec)) {
      fmt::print(stderr,
                 "raygrade export: {}: {} (--grader-js; scripts/build-web.sh builds "
                 "build/web/web/raygrade.js)\n",
                 o.grader_js,
                 std::filesystem::exists(o.grader_js, ec) ? "not a file" : "no such file");
      return kExitBadInput;
    }
  }
  std::filesystem::path binary;
  if (!platform->ships_binary) {
    if (!o.binary.empty()) {
      fmt::print(stderr, "raygrade export: {} takes no --binary (it runs no raygrade)\n",
                 platform->name);
      return kExitBadInput;
    }
  } else if (!o.binary.empty()) {
    binary = o.binary;
    if (!is_static_executable(binary)) {
      fmt::print(stderr,
                 "raygrade export: warning: {} is not a statically linked executable; it may "
                 "not run on {}'s servers\n",
                 o.binary, platform->title);
    }
  } else {
    std::error_code ec;
    auto running = std::filesystem::read_symlink("/proc/self/exe", ec);
    auto found = ec ? std::nullopt : find_static_raygrade(running);
    if (!found) {
      fmt::print(stderr,
                 "raygrade export: no statically linked raygrade found (this one, {}, links "
                 "shared libraries that {}'s servers may lack). Build it with `cmake --preset "
                 "static && cmake --build --preset static`, or give --binary PATH.\n",
                 running.string(), platform->title);
      return kExitBadInput;
    }
    binary = *found;
  }
  try {
    AssignmentSpec spec = load_assignment(o.assignment);
    AssignmentBank bank = load_assignment_bank(spec);
    if (!bank.errors.empty()) {
      for (const auto& e : bank.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
      return kExitBadInput;
    }
    LmsPackage package = platform->make(
        {&spec, &bank, binary, o.roster, o.grader_js, o.scorm.empty() ? "1.2" : o.scorm, o.sets},
        o.out);
    write_entries(o.out, package.files);
    fmt::print(stderr, "{}\n", package.next_step);
  } catch (const Error& e) {
    fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    fmt::print(stderr, "raygrade export: {}\n", e.what());
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

Runner setup_export(CLI::App& sub) {
  auto o = std::make_shared<ExportOptions>();
  sub.add_option("platform", o->platform, "the platform: " + platform_names())->required();
  sub.add_option("assignment", o->assignment, "the assignment file")->required();
  sub.add_option("--out", o->out, "the folder to write into")->required();
  sub.add_option("--binary", o->binary,
                 "the raygrade to ship (default: a static one next to this build)");
  sub.add_option("--roster", o->roster,
                 "gradescope: the roster CSV the handouts were written from (id, name, email); "
                 "needed when each student has their own numbers");
  sub.add_option("--grader-js", o->grader_js,
                 "scorm: raygrade.js of the web build (scripts/build-web.sh), which grades the "
                 "practice page in the student's browser");
  sub.add_option("--scorm", o->scorm, "scorm: the SCORM version (default 1.2; 2004 is 4th edition)")
      ->check(CLI::IsMember(scorm_versions()));
  sub.add_option("--sets", o->sets,
                 "canvas, moodle: how many sets of numbers each question draws from (default 20; "
                 "Canvas takes at most 200, Moodle 100); with --roster, one per student")
      ->check(CLI::Range(1, 200));
  return [o] { return run_export(*o); };
}

}  // namespace raygrade::cli
