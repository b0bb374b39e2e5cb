// The learning platforms raygrade works with: the list `Platforms`, one line per platform (each
// platform is its own file pair here, a type that platform.h's concept checks), and the table
// made from it. `raygrade export`, the gradebook layouts and bulk downloads of
// `raygrade grade`, the roster's platform columns and their options and help come from it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "assignments/platforms/blackboard.h"
#include "assignments/platforms/canvas.h"
#include "assignments/platforms/gradescope.h"
#include "assignments/platforms/moodle.h"
#include "assignments/platforms/platform.h"
#include "assignments/platforms/prairielearn.h"
#include "assignments/platforms/scorm.h"

namespace raygrade {

// The platforms, in the order of their help, errors and tables. One platform a line:
// clang-format off
using Platforms = PlatformList<
    Gradescope,
    PrairieLearn,
    Scorm,
    Canvas,
    Moodle,
    Blackboard>;
// clang-format on

const std::vector<PlatformEntry>& platform_table();
const PlatformEntry* find_platform(std::string_view name);

// The platforms' exports, in the list's order, and the one of `raygrade export NAME`.
const std::vector<LmsExport>& lms_exports();
const LmsExport* find_lms_export(std::string_view name);

// Every grade format of `raygrade grade --format`: raygrade's own (own_grade_formats()), then
// each platform's results format and gradebook layout, in the list's order; the one called
// `name` (nullptr when none is); their names, in that order, separated by ", ".
const std::vector<GradeFormat>& grade_formats();
const GradeFormat* find_grade_format(std::string_view name);
std::string grade_format_names();

// The platforms' gradebook layouts, in the list's order, and the one of `--format NAME`
// (nullptr when no platform's).
const std::vector<GradebookLayout>& gradebook_layouts();
const GradebookLayout* find_gradebook_layout(std::string_view format);

// The class in the gradebook layout `format`. Throws Error (bad input, code "unknown-format")
// when no platform's layout is called so.
std::string platform_gradebook(std::string_view format, const ClassRows& book,
                               const std::string& title, const std::string& column_id);

// The platforms' bulk-download namings, in the list's order.
const std::vector<BulkFormat>& bulk_formats();

// The roster's columns of platforms' user ids, in the list's order: from the platforms' types
// alone, so that reading a roster needs none of their code.
inline std::vector<std::string_view> roster_platform_columns() {
  return Platforms::roster_columns();
}

}  // namespace raygrade
