// raygrade tables: the docs' reference tables (primitives, kinds, formats), from the code's.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "assignments/platforms/platforms.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "reports/reference_tables.h"

namespace raygrade::cli {
namespace {

struct TablesOptions {
  std::string docs = "docs";
  bool check = false;
};

int run_tables(const TablesOptions& o) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(o.docs)) {
    fmt::print(stderr, "raygrade tables: {} is not a folder\n", o.docs);
    return kExitBadInput;
  }
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(o.docs)) {
    if (e.is_regular_file() && e.path().extension() == ".md") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  int stale = 0;
  for (const auto& path : files) {
    std::optional<std::string> have = read_whole_file(path);
    if (!have) {
      fmt::print(stderr, "{}: cannot read the file\n", path.string());
      return kExitBadInput;
    }
    std::string text;
    try {
      text = with_reference_tables(*have, path.string(), grade_formats());
    } catch (const Error& e) {
      fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
      return kExitBadInput;
    }
    FileUpdate done = update_generated_file(path, text, o.check);
    if (done == FileUpdate::kUpToDate) continue;
    ++stale;
    if (done == FileUpdate::kStale) {
      fmt::print("stale: {}\n", path.string());
    } else {
      fmt::print("Wrote {}.\n", path.string());
    }
  }
  if (o.check && stale) {
    fmt::print("The reference tables are out of date: run `raygrade tables {}`.\n", o.docs);
    return kExitFailed;
  }
  if (!stale) fmt::print("The reference tables of {} are up to date.\n", o.docs);
  return kExitOk;
}

}  // namespace

Runner setup_tables(CLI::App& sub) {
  auto o = std::make_shared<TablesOptions>();
  sub.add_option("docs", o->docs, "the docs folder (default: docs)");
  sub.add_flag("--check", o->check, "change nothing; exit 1 naming the docs that are stale");
  return [o] { return run_tables(*o); };
}

}  // namespace raygrade::cli
