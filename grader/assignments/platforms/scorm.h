// SCORM: the practice page as a package for any LMS that plays SCORM content (`raygrade export
// scorm`), graded in the student's browser and reporting to the LMS through scorm_page.js.
// docs/assignments.md, "SCORM".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "assignments/lms_export.h"

namespace raygrade {

// The SCORM versions `raygrade export scorm` writes: "1.2" and "2004" (4th edition).
const std::vector<std::string>& scorm_versions();

// A SCORM package (docs/assignments.md, "SCORM"): imsmanifest.xml and index.html, the generic
// practice page of the assignment, which reports to the LMS. Throws Error when the assignment
// gives each student their own numbers (one package serves the whole class), or when
// raygrade.js or a file of the bank cannot be read.
LmsPackage scorm_package(const LmsExportInput& in, const std::string& out);

struct Scorm {
  static constexpr std::string_view kName = "scorm";
  static constexpr std::string_view kTitle = "SCORM";
  static LmsExport lms_export();
};

}  // namespace raygrade
