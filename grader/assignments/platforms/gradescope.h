// Gradescope: the autograder of a programming assignment (`raygrade export gradescope`: setup.sh,
// run_autograder, the assignment, its bank and a static raygrade) and what run_autograder reads
// from Gradescope (submission_metadata.json). docs/assignments.md, "Gradescope".
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "assignments/platforms/platform.h"

namespace raygrade {

// What raygrade reads of Gradescope's submission_metadata.json: the accounts that uploaded the
// submission ("users", each with "email" and "name"; Gradescope's numeric "id" is not the
// student's id and is not read) and its due date: a user's own "assignment": {"due_date"} (an
// extension) when present, else the assignment's "assignment": {"due_date"}. The other keys are
// Gradescope's and are not read. Throws Error naming the file and JSON path when "users" is
// missing, empty or malformed, or a date given is not one.
UploadMetadata read_gradescope_metadata(const std::string& path);

// The files of the Gradescope autograder, as paths inside its zip: setup.sh, run_autograder,
// raygrade (`binary`'s bytes), assignment.json (the assignment with "bank": "bank") and
// bank/*.json (the files of its bank), and roster.csv when `roster` names one. An assignment
// whose numbers differ per student (has_per_student_numbers) needs the roster: it ties each
// uploading account (by email) to the id its numbers were drawn for. Throws Error when a file
// cannot be read, the roster is faulty, or a needed roster is missing.
std::vector<ZipEntry> gradescope_autograder(const AssignmentSpec& spec, const AssignmentBank& bank,
                                            const std::filesystem::path& binary,
                                            const std::string& roster);

struct Gradescope {
  static constexpr std::string_view kName = "gradescope";
  static constexpr std::string_view kTitle = "Gradescope";
  static LmsExport lms_export();
  static PlatformUploads uploads();
};

}  // namespace raygrade
