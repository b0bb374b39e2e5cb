// raygrade export: an assignment made ready for a learning platform (Gradescope, PrairieLearn).
#include <fmt/format.h>

#include <filesystem>

#include "assignments/lms_export.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "core/zip.h"

namespace raygrade::cli {
namespace {

struct ExportOptions {
  std::string platform;
  std::string assignment;
  std::string out;
  std::string binary;
  std::string roster;  // Gradescope: the class roster, which ties accounts to student ids
};

int run_export(const ExportOptions& o) {
  bool gradescope = o.platform == "gradescope";
  if (!gradescope && o.platform != "prairielearn") {
    fmt::print(stderr, "raygrade export: unknown platform '{}' (gradescope, prairielearn)\n",
               o.platform);
    return kExitBadInput;
  }
  std::string platform = gradescope ? "Gradescope" : "PrairieLearn";
  std::filesystem::path binary;
  if (!o.binary.empty()) {
    binary = o.binary;
    if (!is_static_executable(binary)) {
      fmt::print(stderr,
                 "raygrade export: warning: {} is not a statically linked executable; it may "
                 "not run on {}'s servers\n",
                 o.binary, platform);
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
                 running.string(), platform);
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
    std::filesystem::path out(o.out);
    if (gradescope) {
      std::vector<ZipEntry> entries = gradescope_autograder(spec, bank.bank, binary, o.roster);
      write_entries(out / "autograder", entries);
      write_file_atomically(out / "autograder.zip", zip_archive(entries));
      fmt::print(stderr,
                 "Wrote {0}/autograder.zip (and the same files in {0}/autograder/): {1} "
                 "problems of {2}, raygrade from {3}. Upload the zip as the autograder of a "
                 "Gradescope programming assignment.\n",
                 o.out, spec.problems.size(), spec.id, binary.string());
    } else {
      write_entries(out, prairielearn_course(spec, bank.problems, bank.bank, binary));
      fmt::print(stderr,
                 "Wrote {0}/questions/{1}/ ({2} questions) and {0}/serverFilesCourse/raygrade/ "
                 "(raygrade from {3}). Copy both folders into the PrairieLearn course's "
                 "repository and list the questions in an assessment.\n",
                 o.out, safe_file_name(spec.id), spec.problems.size(), binary.string());
    }
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
  sub.add_option("platform", o->platform, "gradescope or prairielearn")->required();
  sub.add_option("assignment", o->assignment, "the assignment file")->required();
  sub.add_option("--out", o->out, "the folder to write into")->required();
  sub.add_option("--binary", o->binary,
                 "the raygrade to ship (default: a static one next to this build)");
  sub.add_option("--roster", o->roster,
                 "gradescope: the roster CSV the handouts were written from (id, name, email); "
                 "needed when each student has their own numbers");
  return [o] {
    if (!o->roster.empty() && o->platform != "gradescope") {
      fmt::print(stderr, "raygrade export: --roster goes with gradescope\n");
      return static_cast<int>(kExitBadInput);
    }
    return run_export(*o);
  };
}

}  // namespace raygrade::cli
