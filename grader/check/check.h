// The bank check: every file read, every problem solved and judged, every fault reported
// with its place. The library returns a report; the command prints it.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"

namespace raygrade {

struct CheckOptions {
  // The folder of worked solutions; empty to skip the check that every problem has one
  // (unless `solutions_search` names places to look).
  std::string solutions_dir;
  // When `solutions_dir` is empty: folders that may hold the worked solutions, the first that
  // exists is used and a note says which (see solution_folder_candidates).
  std::vector<std::string> solutions_search;
  // When false, a missing solutions folder is a warning (a bank without solutions yet);
  // when true (the folder was named explicitly) it is an error.
  bool solutions_required = false;
  // Run the conditioning check (perturbing every printed input).
  bool conditioning = true;
};

// The findings about one problem, or about a file that holds no readable problem.
struct ProblemResult {
  std::string name;  // the problem's id, or the file when no problem could be read from it
  std::string id;    // empty when unknown
  std::string kind;
  std::string file;
  std::string path;  // JSON pointer of the problem in its file
  int line = 0;
  int column = 0;
  bool solved = false;  // read and solved: the other checks ran
  double seconds = 0;   // the time its checks took (JUnit's `time`)
  std::vector<Diagnostic> diagnostics;

  int count(Severity s) const;
};

struct CheckReport {
  std::vector<std::string> files;
  std::vector<ProblemResult> problems;
  // Findings about the bank as a whole rather than one problem (a missing solutions folder).
  std::vector<Diagnostic> general;
  bool unreadable = false;  // some file or folder could not be read at all

  int count(Severity s) const;
  // Everything the check found, in bank order.
  std::vector<Diagnostic> diagnostics() const;
};

// Checks every problem of the files and folders `paths` (as load_bank reads them).
CheckReport check_bank(const std::vector<std::string>& paths, const CheckOptions& options);

// Where the worked solutions of a bank may be, in order: for each path given, the folder
// `solutions` inside it (a folder) and beside it (a folder, or the folder holding a file); then
// `solutions` in the working folder. `raygrade generate --out DIR` writes DIR/problems and
// DIR/solutions, so both `check DIR` and `check DIR/problems` find them.
std::vector<std::string> solution_folder_candidates(const std::vector<std::string>& paths);

// Every diagnostic code the check can report, with a one-line meaning, for docs and tests.
struct DiagnosticCode {
  const char* code;
  const char* meaning;
};
const std::vector<DiagnosticCode>& check_codes();

}  // namespace raygrade
