// raygrade generate: seeded problem variants with nice numbers, and their worked solutions.
#include "generate/generate.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <iostream>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "json/cursor.h"
#include "reports/render.h"
#include "reports/solutions_folder.h"

namespace raygrade::cli {
namespace {

struct GenerateCliOptions {
  std::uint64_t seed = 1;
  int count = 10;
  std::vector<std::string> kinds;
  std::string outcome;
  std::string out;
  std::vector<std::string> formats = {"md"};
};

// The command that regenerates the output, quoted in every generated solution's first line.
// The folder is named FOLDER rather than the path given, so that the same seed written to two
// folders gives the same bytes and no file tells where it was written.
std::string command_line(const GenerateCliOptions& o) {
  std::string c = fmt::format("raygrade generate --seed {} -n {}", o.seed, o.count);
  if (!o.kinds.empty()) c += fmt::format(" --kind {}", fmt::join(o.kinds, ","));
  if (!o.outcome.empty()) c += " --outcome " + o.outcome;
  if (o.formats != std::vector<std::string>{"md"}) {
    c += fmt::format(" --solution-format {}", fmt::join(o.formats, ","));
  }
  return c + " --out FOLDER";
}

int write_bank(const GenerateCliOptions& o, const std::vector<GeneratedProblem>& generated) {
  namespace fs = std::filesystem;
  fs::path problems_dir = fs::path(o.out) / "problems";
  fs::create_directories(problems_dir);
  std::vector<Problem> problems;
  for (const auto& g : generated) {
    fs::path path = problems_dir / (safe_file_name(g.id) + ".json");
    std::string text = g.json.dump(2) + "\n";
    write_file_atomically(path, text);
    problems.push_back(read_problem(Cursor(parse_json_text(path.string(), text))));
  }
  std::vector<Format> formats;
  for (const auto& f : o.formats) formats.push_back(*parse_format(f));
  std::vector<Diagnostic> errors;
  std::string solutions_dir = (fs::path(o.out) / "solutions").string();
  FolderSync s = write_solution_folder(solutions_dir,
                                       solution_files(problems, formats, command_line(o), errors));
  for (const auto& e : errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  fmt::print("Wrote {} problems to {} and their worked solutions to {} ({} files written).\n",
             problems.size(), problems_dir.string(), solutions_dir, s.written.size());
  return errors.empty() ? kExitOk : kExitFailed;
}

int run_generate(const GenerateCliOptions& o) {
  GenerateOptions options;
  options.seed = o.seed;
  options.count = o.count;
  options.kinds = o.kinds;
  if (!o.outcome.empty()) options.outcome = parse_outcome(o.outcome);
  std::vector<GeneratedProblem> problems;
  try {
    problems = generate_problems(options);
  } catch (const Error& e) {
    fmt::print(stderr, "raygrade generate: {}\n", e.diagnostic().message);
    return kExitBadInput;
  }
  if (!o.out.empty()) return write_bank(o, problems);
  std::string text;
  try {
    text = bank_text(problems);
  } catch (const Error& e) {
    fmt::print(stderr, "raygrade generate: {}\n", e.diagnostic().message);
    return kExitBadInput;
  }
  std::cout << text;
  return kExitOk;
}

}  // namespace

Runner setup_generate(CLI::App& sub) {
  auto o = std::make_shared<GenerateCliOptions>();
  sub.add_option("--seed", o->seed, "the seed: the same seed gives the same bytes")->required();
  sub.add_option("-n,--count", o->count, "how many problems")->check(CLI::Range(1, 1000000));
  std::vector<std::string_view> kinds;
  for (const auto& g : generator_table()) kinds.push_back(g.name);
  std::string_view last = kinds.back();
  kinds.pop_back();
  sub.add_option("--kind", o->kinds,
                 fmt::format("{} or {} (repeat, or separate with commas; default: all, in turn)",
                             fmt::join(kinds, ", "), last))
      ->delimiter(',');
  sub.add_option("--outcome", o->outcome, "hit, miss, tangent, inside or behind (default: a mix)")
      ->check(CLI::IsMember({"hit", "miss", "tangent", "inside", "behind"}));
  sub.add_option("--out", o->out,
                 "a folder: writes OUT/problems/<id>.json and OUT/solutions/<id>.md (default: "
                 "the bank as JSON on standard output)");
  sub.add_option("--solution-format", o->formats,
                 "with --out: formats of the worked solutions (default: md)")
      ->check(CLI::IsMember(solution_format_names()))
      ->delimiter(',');
  return [o] { return run_generate(*o); };
}

}  // namespace raygrade::cli
