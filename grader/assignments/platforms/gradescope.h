// Gradescope: the autograder of a programming assignment (`raygrade export gradescope`: setup.sh,
// run_autograder, the assignment, its bank and a static raygrade) and what run_autograder reads
// from Gradescope (submission_metadata.json) and writes for it (results.json). docs/assignments.md,
// "Gradescope".
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

// Gradescope's autograder results.json: score, execution_time, output, output_format,
// visibility and one test per problem (name, score, max_score, status, output, output_format,
// visibility). Every output is plain text ("output_format": "text"), never read as HTML or
// Markdown. Every test is "visible": Gradescope hides a student's total score while any test
// waits for a later time (after_due_date, after_published), so the feedback a policy allows
// later comes from grading again then (docs/assignments.md).
nlohmann::json gradescope_json(const SubmissionGrade& g, double execution_seconds);

// PrairieLearn's external grader results.json: gradable, score in [0, 1], message, output
// and one test per problem (name, description, points, max_points, message, output).

struct Gradescope {
  static constexpr std::string_view kName = "gradescope";
  static constexpr std::string_view kTitle = "Gradescope";
  static LmsExport lms_export();
  static PlatformUploads uploads();
  static GradeFormat results_format();
};

}  // namespace raygrade
