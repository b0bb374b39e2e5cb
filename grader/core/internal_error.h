// InternalError: an invariant of raygrade itself that failed, never a fault of the input.
#pragma once

#include <stdexcept>
#include <string>

namespace raygrade {

// Thrown where the library finds itself wrong (a grader that would take credit without saying
// why, a mistake id missing from the catalogue): a bug to report, not bad input. Error, the one
// error type of bad input, never carries one. Derived from std::logic_error, so that what
// catches a bug of the standard library's kind (std::out_of_range, ...) catches it too; the
// CLI reports it with exit code 3 and `raygrade grade` sets the submission aside with fault
// code `internal` ("the file is not at fault").
class InternalError : public std::logic_error {
 public:
  explicit InternalError(const std::string& what) : std::logic_error(what) {}
};

}  // namespace raygrade
