// raygrade export: an assignment made ready for a learning platform, any of the list's
// (assignments/platforms/platforms.h): the platforms, their options, help and errors come from
// its rows.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <variant>

#include "assignments/platforms/platforms.h"
#include "cli/command.h"

namespace raygrade::cli {
namespace {

struct ExportOptions {
  std::string platform;
  std::string assignment;
  std::string out;
  std::string binary;
  std::string roster;     // for the platforms that take a roster (LmsExport::takes_roster)
  std::string grader_js;  // raygrade.js, for those that grade in the browser
  // The version of a platform's format, by the option that chooses it (LmsExport::versions).
  std::map<std::string_view, std::string> versions;
  int sets = 0;  // how many sets of numbers, for those that draw sets (LmsExport::max_sets)
};

// The names of the platforms whose export `has` says yes of: "canvas, moodle".
template <class Has>
std::string platform_names(Has has) {
  std::vector<std::string_view> names;
  for (const LmsExport& e : lms_exports()) {
    if (has(e)) names.push_back(e.name);
  }
  return fmt::format("{}", fmt::join(names, ", "));
}

// An option given that the platform does not take: the message that says so.
std::optional<std::string> option_not_taken(const ExportOptions& o, const LmsExport& platform) {
  if (!o.roster.empty() && !platform.takes_roster)
    return fmt::format("{} takes no --roster", platform.name);
  if (!o.grader_js.empty() && !platform.takes_grader_js)
    return fmt::format("{} takes no --grader-js (it runs no grader in the browser)", platform.name);
  if (o.sets != 0 && platform.max_sets == 0)
    return fmt::format("{} takes no --sets", platform.name);
  for (const LmsExport& other : lms_exports()) {
    auto given = o.versions.find(other.version_option);
    if (given == o.versions.end() || given->second.empty()) continue;
    if (other.version_option != platform.version_option)
      return fmt::format("{} takes no {} (the {} version)", platform.name, other.version_option,
                         other.title);
  }
  return std::nullopt;
}

// The raygrade the package ships, or the exit code of a fault (said on standard error). Empty
// for a platform that ships none.
std::variant<std::filesystem::path, int> binary_to_ship(const ExportOptions& o,
                                                        const LmsExport& platform) {
  if (!platform.ships_binary) {
    if (o.binary.empty()) return std::filesystem::path();
    fmt::print(stderr, "raygrade export: {} takes no --binary (it runs no raygrade)\n",
               platform.name);
    return kExitBadInput;
  }
  if (!o.binary.empty()) {
    if (!is_static_executable(o.binary)) {
      fmt::print(stderr,
                 "raygrade export: warning: {} is not a statically linked executable; it may "
                 "not run on {}'s servers\n",
                 o.binary, platform.title);
    }
    return std::filesystem::path(o.binary);
  }
  std::error_code ec;
  auto running = std::filesystem::read_symlink("/proc/self/exe", ec);
  auto found = ec ? std::nullopt : find_static_raygrade(running);
  if (!found) {
    fmt::print(stderr,
               "raygrade export: no statically linked raygrade found (this one, {}, links "
               "shared libraries that {}'s servers may lack). Build it with `cmake --preset "
               "static && cmake --build --preset static`, or give --binary PATH.\n",
               running.string(), platform.title);
    return kExitBadInput;
  }
  return *found;
}

// The check of --grader-js for a platform that grades in the browser: the exit code of a fault.
std::optional<int> check_grader_js(const ExportOptions& o, const LmsExport& platform) {
  if (!platform.takes_grader_js) return std::nullopt;
  // Checked first, so that a missing raygrade.js is named before the assignment is read.
  std::error_code ec;
  if (o.grader_js.empty()) {
    fmt::print(stderr,
               "raygrade export: {} needs --grader-js FILE, the web build's raygrade.js "
               "(scripts/build-web.sh builds build/web/web/raygrade.js)\n",
               platform.name);
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
  return std::nullopt;
}

int run_export(const ExportOptions& o) {
  const LmsExport* platform = find_lms_export(o.platform);
  if (!platform) {
    fmt::print(stderr, "raygrade export: unknown platform '{}' ({})\n", o.platform,
               platform_names([](const LmsExport&) { return true; }));
    return kExitBadInput;
  }
  if (auto fault = option_not_taken(o, *platform)) {
    fmt::print(stderr, "raygrade export: {}\n", *fault);
    return kExitBadInput;
  }
  if (auto failed = check_grader_js(o, *platform)) return *failed;
  auto binary = binary_to_ship(o, *platform);
  if (const int* failed = std::get_if<int>(&binary)) return *failed;
  std::string version;
  if (!platform->versions.empty()) {
    auto given = o.versions.find(platform->version_option);
    version = given != o.versions.end() && !given->second.empty() ? given->second
                                                                  : platform->versions.front();
  }
  try {
    AssignmentSpec spec = load_assignment(o.assignment);
    AssignmentBank bank = load_assignment_bank(spec);
    if (!bank.errors.empty()) {
      for (const auto& e : bank.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
      return kExitBadInput;
    }
    LmsPackage package = platform->make({&spec, &bank, std::get<std::filesystem::path>(binary),
                                         o.roster, o.grader_js, version, o.sets},
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

// The help of an option some platforms take: each one's own words ("gradescope: the roster
// CSV ...; canvas: one set of numbers per roster student").
template <class Help>
std::string per_platform_help(Help help) {
  std::string out;
  for (const LmsExport& e : lms_exports()) {
    std::string_view h = help(e);
    if (!h.empty()) out += fmt::format("{}{}: {}", out.empty() ? "" : "; ", e.name, h);
  }
  return out;
}

}  // namespace

Runner setup_export(CLI::App& sub) {
  auto o = std::make_shared<ExportOptions>();
  sub.add_option("platform", o->platform,
                 "the platform: " + platform_names([](const LmsExport&) { return true; }))
      ->required();
  sub.add_option("assignment", o->assignment, "the assignment file")->required();
  sub.add_option("--out", o->out, "the folder to write into")->required();
  sub.add_option("--binary", o->binary,
                 "the raygrade to ship (default: a static one next to this build)");
  sub.add_option("--roster", o->roster, per_platform_help([](const LmsExport& e) {
                   return e.takes_roster ? e.roster_help : std::string_view();
                 }));
  sub.add_option("--grader-js", o->grader_js, per_platform_help([](const LmsExport& e) {
                   return e.takes_grader_js ? e.grader_js_help : std::string_view();
                 }));
  for (const LmsExport& e : lms_exports()) {
    if (e.versions.empty() || e.version_option.empty()) continue;
    sub.add_option(std::string(e.version_option), o->versions[e.version_option],
                   fmt::format("{}: {}", e.name, e.version_help))
        ->check(CLI::IsMember(e.versions));
  }
  int most_sets = 0;
  std::string limits;
  for (const LmsExport& e : lms_exports()) {
    if (e.max_sets == 0) continue;
    most_sets = std::max(most_sets, e.max_sets);
    limits += fmt::format("{}{} {}", limits.empty() ? "" : ", ", e.title, e.max_sets);
  }
  sub.add_option(
         "--sets", o->sets,
         fmt::format("{}: how many sets of numbers each question draws from (default 20; "
                     "at most: {}); with --roster, one per student",
                     platform_names([](const LmsExport& e) { return e.max_sets > 0; }), limits))
      ->check(CLI::Range(1, most_sets));
  return [o] { return run_export(*o); };
}

}  // namespace raygrade::cli
