// The reference tables of the docs, derived from the tables of the code: the primitives (from
// the list of primitives), the problem kinds, the solution formats and the grade formats. A
// doc holds a table between two markers, each at the start of its line, and `raygrade tables`
// rewrites what lies between them:
//
//   <!-- raygrade tables: primitives -->
//   ...
//   <!-- raygrade tables: end -->
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "grading/outputs.h"

namespace raygrade {

struct ReferenceTable {
  std::string name;      // "primitives", "kinds", "solution-formats", "grade-formats"
  std::string markdown;  // the table, ending with a newline
};

// The tables; the grade formats' is `grade_formats`' (the table of every grade format, raygrade's
// own and the platforms', which lives above the reports: assignments/platforms/platforms.h).
std::vector<ReferenceTable> reference_tables(const std::vector<GradeFormat>& grade_formats);

// `text` (the doc `file_name`) with every marked table written afresh. Throws Error naming the
// file and line for a marker of an unknown table, or one with no end marker.
std::string with_reference_tables(std::string_view text, const std::string& file_name,
                                  const std::vector<GradeFormat>& grade_formats);

}  // namespace raygrade
