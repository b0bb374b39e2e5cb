// Moodle: the quiz export (calculated questions in Moodle XML), the grade import layout
// csv-moodle, its grading worksheet filled in and the bulk feedback zip (--moodle-worksheet),
// and the naming of its "Download all submissions" zip (docs/assignments.md, "Moodle").
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "assignments/platforms/platform.h"
#include "assignments/quiz_export.h"

namespace raygrade {

// Moodle's XML file of calculated questions: a question draws from at most kMoodleMaxSets
// dataset items.
constexpr int kMoodleMaxSets = 100;
std::string moodle_xml(const Quiz& quiz);

struct Moodle {
  static constexpr std::string_view kName = "moodle";
  static constexpr std::string_view kTitle = "Moodle";
  static LmsExport lms_export();
  static GradebookLayout gradebook();
  static BulkFormat bulk();
  static PlatformWorksheet worksheet();
};

}  // namespace raygrade
