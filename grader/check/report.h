// The bank check's report as text for a terminal, as JSON, and as JUnit XML for CI servers.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "check/check.h"

namespace raygrade {

// One line per diagnostic ("file:line:column: /json/path: error: message [code]"), then a
// summary line.
std::string check_report_text(const CheckReport& report);

// {"summary": {...}, "problems": [{"name", "id", "file", "path", "kind", "status",
// "diagnostics": [...]}]}.
nlohmann::json check_report_json(const CheckReport& report);

// JUnit XML: <testsuites> with one <testsuite> per file and one <testcase> per problem; a
// problem with errors has a <failure> (an <error> when its file cannot be read); warnings go
// to the testcase's <system-out>.
std::string check_report_junit(const CheckReport& report);

}  // namespace raygrade
