// Canvas: the quiz export (Classic Quizzes formula questions in a QTI 1.2 package), the
// gradebook import layout csv-canvas, and the naming of its "Download Submissions" zip
// (docs/assignments.md, "Canvas").
#pragma once

#include <string_view>
#include <vector>

#include "assignments/platforms/platform.h"
#include "assignments/quiz_export.h"

namespace raygrade {

// Canvas's QTI 1.2 package (imsmanifest.xml and the assessment): a question draws from at most
// kCanvasMaxSets sets.
constexpr int kCanvasMaxSets = 200;
std::vector<ZipEntry> canvas_qti_files(const Quiz& quiz);

struct Canvas {
  static constexpr std::string_view kName = "canvas";
  static constexpr std::string_view kTitle = "Canvas";
  // Each student's Canvas user ID (the "ID" column of Canvas's gradebook export), which ties the
  // files of its "Download Submissions" zip to roster students and fills the ID column of its
  // gradebook.
  static constexpr std::string_view kRosterColumn = "canvas_id";
  static LmsExport lms_export();
  static GradebookLayout gradebook();
  static BulkFormat bulk();
};

}  // namespace raygrade
