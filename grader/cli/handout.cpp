// raygrade handout: each student's problems as a page with answer inputs, and a template.
#include "assignments/handout.h"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>

#include "assignments/roster.h"
#include "assignments/variants.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/escape.h"

namespace raygrade::cli {
namespace {

struct HandoutOptions {
  std::string assignment;
  std::string out;
  std::vector<std::string> students;
  std::string roster;
  bool practice = false;
  std::string grader_js = "build/web/web/raygrade.js";
};

void write_handout(const std::filesystem::path& folder, const Handout& h) {
  std::filesystem::create_directories(folder);
  write_file_atomically(folder / "index.html", h.html);
  write_file_atomically(folder / "answers-template.json", h.template_json.dump(2) + "\n");
}

int run_handout(const HandoutOptions& o) {
  AssignmentSpec spec;
  std::vector<StudentIdentity> students;
  try {
    spec = load_assignment(o.assignment);
    if (!o.roster.empty()) students = load_roster(o.roster);
  } catch (const Error& e) {
    fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
    return kExitBadInput;
  }
  if (!o.roster.empty() && !o.students.empty()) {
    fmt::print(stderr, "raygrade handout: give --student or --roster, not both\n");
    return kExitBadInput;
  }
  for (const auto& id : o.students) students.push_back(StudentIdentity{"", id, ""});
  std::optional<PracticeAssets> practice;
  if (o.practice) {
    std::ifstream in(o.grader_js, std::ios::binary);
    if (!in) {
      fmt::print(stderr,
                 "raygrade handout: cannot read {} (--grader-js; scripts/build-web.sh builds it)\n",
                 o.grader_js);
      return kExitBadInput;
    }
    std::string js((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      practice = practice_assets(spec, std::move(js));
    } catch (const Error& e) {
      fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
      return kExitBadInput;
    }
  }
  const PracticeAssets* assets = practice ? &*practice : nullptr;
  AssignmentBank bank = load_assignment_bank(spec);
  for (const auto& e : bank.errors) fmt::print(stderr, "{}\n", format_diagnostic(e));
  if (bank.problems.size() != spec.problems.size()) return kExitBadInput;
  std::filesystem::path out(o.out);
  int status = bank.errors.empty() ? kExitOk : kExitBadInput;
  if (students.empty()) {
    try {
      write_handout(out,
                    make_handout(spec, student_problems(spec, bank.problems, ""), nullptr, assets));
    } catch (const Error& e) {
      fmt::print(stderr, "{}\n", format_diagnostic(e.diagnostic()));
      return kExitBadInput;
    }
    fmt::print(stderr, "Wrote the handout of {} ({} problems, no variants) into {}.\n", spec.id,
               spec.problems.size(), o.out);
    return status;
  }
  std::string index = "id,name,email,folder\n";
  // Folder names compared in lower case: macOS's and Windows's file systems do not tell "S1"
  // from "s1" (and safe_file_name leaves no other letters). The index's own name is taken.
  std::set<std::string> folders = {"handouts.csv"};
  std::size_t written = 0;
  for (const auto& s : students) {
    std::string key = student_key(s);
    std::string folder = unique_file_name(key, folders);
    try {
      write_handout(out / folder,
                    make_handout(spec, student_problems(spec, bank.problems, key), &s, assets));
      index += fmt::format("{},{},{},{}\n", csv_cell(s.id), csv_cell(s.name), csv_cell(s.email),
                           csv_cell(folder));
      ++written;
    } catch (const Error& e) {
      Diagnostic d = e.diagnostic();
      d.message = fmt::format("{} (for student '{}')", d.message, key);
      fmt::print(stderr, "{}\n", format_diagnostic(d));
      status = kExitBadInput;
    }
  }
  std::filesystem::create_directories(out);
  write_file_atomically(out / "handouts.csv", index);
  fmt::print(stderr, "Wrote {} handouts of {} into {} (handouts.csv lists the folders).\n", written,
             spec.id, o.out);
  return status;
}

}  // namespace

Runner setup_handout(CLI::App& sub) {
  auto o = std::make_shared<HandoutOptions>();
  sub.add_option("assignment", o->assignment, "the assignment file")->required();
  sub.add_option("--out", o->out, "the folder to write into")->required();
  sub.add_option("--student", o->students, "a student's id (repeat for more)");
  sub.add_option("--roster", o->roster, "a roster CSV with the columns id, name, email");
  sub.add_flag("--practice", o->practice,
               "pages that grade in the browser: a Check button per problem, feedback, the worked "
               "solution after a few attempts (needs raygrade.js, docs/web.md)");
  sub.add_option("--grader-js", o->grader_js, "with --practice: raygrade.js")
      ->capture_default_str();
  return [o] { return run_handout(*o); };
}

}  // namespace raygrade::cli
