// raygrade schema: the problem schema, from the format's own parts and the list of primitives.
#include "problems/schema.h"

#include <fmt/format.h>

#include "cli/command.h"
#include "core/atomic_file.h"

namespace raygrade::cli {
namespace {

struct SchemaOptions {
  std::string out;
  bool check = false;
};

int run_schema(const SchemaOptions& o) {
  std::string text = problem_schema_text();
  if (o.check && o.out.empty()) {
    fmt::print(stderr, "raygrade schema: --check compares with a file: give it with --out\n");
    return kExitBadInput;
  }
  if (o.out.empty()) {
    fmt::print("{}", text);
    return kExitOk;
  }
  switch (update_generated_file(o.out, text, o.check)) {
    case FileUpdate::kStale:
      fmt::print("{} is out of date: run `raygrade schema --out {}`.\n", o.out, o.out);
      return kExitFailed;
    case FileUpdate::kWritten: fmt::print("Wrote {}.\n", o.out); break;
    case FileUpdate::kUpToDate: fmt::print("{} is up to date.\n", o.out); break;
  }
  return kExitOk;
}

}  // namespace

Runner setup_schema(CLI::App& sub) {
  auto o = std::make_shared<SchemaOptions>();
  sub.add_option("--out", o->out, "the file to write (default: print it)");
  sub.add_flag("--check", o->check, "change nothing; exit 1 when --out's file differs");
  return [o] { return run_schema(*o); };
}

}  // namespace raygrade::cli
