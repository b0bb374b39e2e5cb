// What every platform's export is made of and shares: its input, its package, its row of the
// list of platforms (LmsExport), the assignment and its bank as shipped, and a static raygrade
// to ship (docs/assignments.md). Each platform's own export is in assignments/platforms/.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assignments/assignment.h"
#include "core/zip.h"
#include "grading/submission.h"

namespace raygrade {

// Whether a file is an ELF executable linked statically (it asks for no program interpreter).
bool is_static_executable(const std::filesystem::path& path);

// A statically linked raygrade near the running one: the running binary itself when it is
// static, else build/static/grader/raygrade of the same build tree.
std::optional<std::filesystem::path> find_static_raygrade(const std::filesystem::path& running);

// A file's bytes. Throws Error naming the file when it cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

// The assignment as shipped to a platform: bank/*.json (the files of its bank, renamed when two
// share a name) and assignment.json (the assignment as written, with "bank": "bank").
std::vector<ZipEntry> assignment_files(const AssignmentSpec& spec, const Bank& bank);

// What an export is made from.
struct LmsExportInput {
  const AssignmentSpec* spec = nullptr;
  const AssignmentBank* bank = nullptr;
  std::filesystem::path binary;  // the static raygrade to ship; empty when the platform takes none
  std::string roster;            // a roster CSV, for the platforms that take one
  std::filesystem::path grader_js;  // raygrade.js, for the platforms that take it
  std::string version;              // the platform's format version (LmsExport::versions)
  int sets = 0;  // quizzes: how many sets of numbers (0: the default, 20); a roster sets them
};

// One export: the files to write, as paths under the --out folder, and what to tell the
// instructor to do with them.
struct LmsPackage {
  std::vector<ZipEntry> files;
  std::string next_step;
};

// One platform's export: what `raygrade export NAME` takes and makes. A platform declares it
// (platforms/platform.h); `raygrade export`, its options, its help and its errors take every
// platform's from the list of platforms.
struct LmsExport {
  std::string_view name;   // on the command line: the platform's kName
  std::string_view title;  // in sentences: the platform's kTitle
  std::string_view summary;
  bool takes_roster = false;
  std::string_view roster_help;  // what --roster is to this platform, for --help
  bool ships_binary = false;     // the package carries a static raygrade (LmsExportInput::binary)
  // Throws Error when a file cannot be read or the input is faulty; `out` is the folder the
  // files go to, for the sentence that says so.
  LmsPackage (*make)(const LmsExportInput& in, const std::string& out) = nullptr;
  // The package carries the practice page, which grades with raygrade.js in the student's
  // browser (LmsExportInput::grader_js).
  bool takes_grader_js = false;
  std::string_view grader_js_help;
  // The most sets of numbers a question may draw from (--sets); 0: it takes no --sets.
  int max_sets = 0;
  std::string_view sets_help;
  // The versions of the platform's format it writes, the first the default, and the option
  // that chooses one ("" when there is one format).
  std::vector<std::string> versions;
  std::string_view version_option;
  std::string_view version_help;
};

// Writes the entries under `folder` (executables with mode 0755).
void write_entries(const std::filesystem::path& folder, const std::vector<ZipEntry>& entries);

}  // namespace raygrade
