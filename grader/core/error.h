// Diagnostic and Error: the one error type of the library, naming file, JSON path and fault.
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace raygrade {

enum class Severity { kError, kWarning, kNote };

const char* to_string(Severity s);

// Where a fault is and what it is. `path` is a JSON pointer ("/problems/3/ray/direction").
// `line` and `column` are 1-based, 0 when unknown.
struct Diagnostic {
  std::string file;
  std::string path;
  int line = 0;
  int column = 0;
  Severity severity = Severity::kError;
  std::string message;
  std::string code;  // a short stable name for the fault, e.g. "unknown-key"
};

// "file:line:column: /json/path: error: message" (the parts that are known).
std::string format_diagnostic(const Diagnostic& d);

// Thrown by loaders and solvers; the CLI catches it and reports the diagnostic.
class Error : public std::runtime_error {
 public:
  explicit Error(Diagnostic d);
  const Diagnostic& diagnostic() const { return diagnostic_; }

 private:
  Diagnostic diagnostic_;
};

}  // namespace raygrade

template <>
struct fmt::formatter<raygrade::Diagnostic> : fmt::formatter<std::string> {
  template <typename Ctx>
  auto format(const raygrade::Diagnostic& d, Ctx& ctx) const {
    return fmt::formatter<std::string>::format(raygrade::format_diagnostic(d), ctx);
  }
};
