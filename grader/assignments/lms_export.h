// An assignment made ready for a learning platform: the Gradescope autograder (setup.sh,
// run_autograder, the assignment, its bank and a static raygrade), what run_autograder reads
// from Gradescope, and a PrairieLearn course's questions (docs/assignments.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "assignments/assignment.h"
#include "core/zip.h"
#include "grading/submission.h"

namespace raygrade {

// What raygrade reads of Gradescope's submission_metadata.json: the accounts that uploaded the
// submission ("users", each with "email" and "name"; Gradescope's numeric "id" is not the
// student's id and is not read) and its due date: a user's own "assignment": {"due_date"} (an
// extension) when present, else the assignment's "assignment": {"due_date"}. The other keys are
// Gradescope's and are not read. Throws Error naming the file and JSON path when "users" is
// missing, empty or malformed, or a date given is not one.
struct GradescopeMetadata {
  std::vector<StudentIdentity> users;
  std::optional<std::int64_t> due;  // seconds since 1970 UTC
};
GradescopeMetadata read_gradescope_metadata(const std::string& path);

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

// The files of the Gradescope autograder, as paths inside its zip: setup.sh, run_autograder,
// raygrade (`binary`'s bytes), assignment.json (the assignment with "bank": "bank") and
// bank/*.json (the files of its bank), and roster.csv when `roster` names one. An assignment
// whose numbers differ per student (has_per_student_numbers) needs the roster: it ties each
// uploading account (by email) to the id its numbers were drawn for. Throws Error when a file
// cannot be read, the roster is faulty, or a needed roster is missing.
std::vector<ZipEntry> gradescope_autograder(const AssignmentSpec& spec, const AssignmentBank& bank,
                                            const std::filesystem::path& binary,
                                            const std::string& roster);

// A PrairieLearn course fragment: questions/<assignment>/<problem>/ with info.json, question.html
// (one input per value the student types), server.py (prairielearn_server.py) and
// raygrade.json (what server.py needs: the ids, the blank answer and where each input goes),
// and serverFilesCourse/raygrade/ with raygrade (`binary`'s bytes) and
// <assignment>/assignment.json with its bank. `problems` are the assignment's, in its order.
std::vector<ZipEntry> prairielearn_course(const AssignmentSpec& spec,
                                          const std::vector<const Problem*>& problems,
                                          const Bank& bank, const std::filesystem::path& binary);

// What an export is made from.
struct LmsExportInput {
  const AssignmentSpec* spec = nullptr;
  const AssignmentBank* bank = nullptr;
  std::filesystem::path binary;  // the static raygrade to ship; empty when the platform takes none
  std::string roster;            // a roster CSV, for the platforms that take one
  std::filesystem::path grader_js;  // raygrade.js, for the platforms that take it
  std::string scorm_version;        // SCORM: "1.2" or "2004"
  int sets = 0;  // quizzes: how many sets of numbers (0: the default, 20); a roster sets them
};

// One export: the files to write, as paths under the --out folder, and what to tell the
// instructor to do with them.
struct LmsPackage {
  std::vector<ZipEntry> files;
  std::string next_step;
};

// One learning platform raygrade exports to: one row of lms_exports(). `raygrade export`, its
// help and its errors take the platforms from the table.
struct LmsExport {
  std::string_view name;   // on the command line: "gradescope"
  std::string_view title;  // in sentences: "Gradescope"
  std::string_view summary;
  bool takes_roster = false;
  bool ships_binary = true;  // the package carries a static raygrade (LmsExportInput::binary)
  // Throws Error when a file cannot be read or the input is faulty; `out` is the folder the
  // files go to, for the sentence that says so.
  LmsPackage (*make)(const LmsExportInput& in, const std::string& out);
  // The package carries the practice page, which grades with raygrade.js in the student's
  // browser (LmsExportInput::grader_js).
  bool takes_grader_js = false;
};
const std::vector<LmsExport>& lms_exports();
const LmsExport* find_lms_export(std::string_view name);

// The SCORM versions `raygrade export scorm` writes: "1.2" and "2004" (4th edition).
const std::vector<std::string>& scorm_versions();

// A SCORM package (docs/assignments.md, "SCORM"): imsmanifest.xml and index.html, the generic
// practice page of the assignment, which reports to the LMS. Throws Error when the assignment
// gives each student their own numbers (one package serves the whole class), or when
// raygrade.js or a file of the bank cannot be read.
LmsPackage scorm_package(const LmsExportInput& in, const std::string& out);

// Writes the entries under `folder` (executables with mode 0755).
void write_entries(const std::filesystem::path& folder, const std::vector<ZipEntry>& entries);

}  // namespace raygrade
