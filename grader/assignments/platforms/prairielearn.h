// PrairieLearn: a course's questions (`raygrade export prairielearn`), each graded by raygrade
// from its server.py (prairielearn_server.py, embedded when the build is configured).
// docs/assignments.md, "PrairieLearn".
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "assignments/platforms/platform.h"

namespace raygrade {

// A PrairieLearn course fragment: questions/<assignment>/<problem>/ with info.json, question.html
// (one input per value the student types), server.py (prairielearn_server.py) and
// raygrade.json (what server.py needs: the ids, the blank answer and where each input goes),
// and serverFilesCourse/raygrade/ with raygrade (`binary`'s bytes) and
// <assignment>/assignment.json with its bank. `problems` are the assignment's, in its order.
std::vector<ZipEntry> prairielearn_course(const AssignmentSpec& spec,
                                          const std::vector<const Problem*>& problems,
                                          const Bank& bank, const std::filesystem::path& binary);

// PrairieLearn's external grader results.json: gradable, score in [0, 1], message, output
// and one test per problem (name, description, points, max_points, message, output).
nlohmann::json prairielearn_json(const SubmissionGrade& g);

struct PrairieLearn {
  static constexpr std::string_view kName = "prairielearn";
  static constexpr std::string_view kTitle = "PrairieLearn";
  static LmsExport lms_export();
  static GradeFormat results_format();
};

}  // namespace raygrade
