// What `raygrade solve` writes: the answers as JSON (optionally with the steps, or an
// assignment's statements), or the worked solutions rendered; shared by the command and the
// WebAssembly build.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "problems/problem.h"

namespace raygrade {

struct SolveOutputOptions {
  std::string format = "json";  // json, or a worked solution's format (md, html, txt)
  std::string method;           // a method name, "all", or empty for the problem's own
  int precision = -1;           // decimals shown; -1 for the problem's own
  bool steps = false;           // with json: the derivation steps too
  bool assignment = false;      // the problems are an assignment's: titles, statements, values
};

// The text `raygrade solve` prints for `bank`. A problem that cannot be solved is left out and
// its diagnostic (with the problem's file and path) is added to `bank.errors` and `failures`.
std::string solve_output(Bank& bank, const SolveOutputOptions& o,
                         std::vector<Diagnostic>& failures);

}  // namespace raygrade
