// Formatting of diagnostics.
#include "core/error.h"

#include "core/escape.h"

namespace raygrade {

const char* to_string(Severity s) {
  switch (s) {
    case Severity::kError: return "error";
    case Severity::kWarning: return "warning";
    case Severity::kNote: return "note";
  }
  return "error";
}

// File names and messages may quote what a student wrote: printable() keeps terminal escape
// sequences and ill-formed UTF-8 out of what is printed.
std::string format_diagnostic(const Diagnostic& d) {
  std::string out = d.file.empty() ? "<input>" : printable(d.file);
  if (d.line > 0) {
    out += fmt::format(":{}", d.line);
    if (d.column > 0) out += fmt::format(":{}", d.column);
  }
  out += ": ";
  if (!d.path.empty()) out += printable(d.path) + ": ";
  out += to_string(d.severity);
  out += ": ";
  out += printable(d.message);
  return out;
}

Error::Error(Diagnostic d) : std::runtime_error(format_diagnostic(d)), diagnostic_(std::move(d)) {}

}  // namespace raygrade
