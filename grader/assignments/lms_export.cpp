// The Gradescope autograder of an assignment.
#include "assignments/lms_export.h"

#include <elf.h>
#include <fmt/format.h>

#include <fstream>
#include <set>

#include "assignments/quiz_export.h"
#include "assignments/roster.h"
#include "assignments/variants.h"
#include "core/atomic_file.h"
#include "core/escape.h"
#include "json/cursor.h"
#include "json/source.h"

namespace raygrade {
namespace {

// Run once by Gradescope when it builds the autograder's image, in /autograder/source.
constexpr const char* kSetup = R"sh(#!/usr/bin/env bash
# raygrade is linked statically: nothing to install.
set -euo pipefail
cd "$(dirname "$0")"
chmod 755 raygrade run_autograder
./raygrade --version
)sh";

// Run by Gradescope for each submission. Whatever is uploaded, it writes results.json and
// exits 0: a file it cannot grade is a result with the reason and no points.
constexpr const char* kRunAutograder = R"sh(#!/usr/bin/env bash
# Grades one upload with raygrade: the one .json file in submission/, as the variant of the
# account that uploaded it (submission_metadata.json), found on the roster by its email.
# AUTOGRADER_ROOT (default /autograder) is where Gradescope's folders are. The feedback policy
# is the one in force when the upload is graded (a regrade after the due date gives the
# after_due policy); RAYGRADE_NOW, for trying the autograder out, sets that time instead.
set -u
root="${AUTOGRADER_ROOT:-/autograder}"
source="$root/source"
results="$root/results"
mkdir -p "$results"
rm -f "$results/results.json"

# A result with a message and no points; the message is plain text without quotes.
reject() {
  printf '{"score": 0, "output": "%s", "output_format": "text", "visibility": "visible", "tests": []}\n' \
    "$1" > "$results/results.json"
  echo "run_autograder: $1" >&2
  exit 0
}

# The answers: files ending in .json, less what an operating system adds to an archive
# (a Mac's __MACOSX/ folder and ._ files). Paths are kept relative to submission/, so that
# no message shows where the autograder keeps them.
files=()
if [ -d "$root/submission" ]; then
  while IFS= read -r -d '' f; do files+=("${f#./}"); done < <(cd "$root/submission" &&
    find . -type f -iname '*.json' -not -path '*/__MACOSX/*' -not -name '._*' -print0)
fi
if [ "${#files[@]}" -eq 0 ]; then
  reject "No answers file found. Upload one file ending in .json: the answers.json your handout page saves."
fi
if [ "${#files[@]}" -gt 1 ]; then
  reject "${#files[@]} files ending in .json were uploaded. Upload one: the answers.json your handout page saves."
fi

roster=()
[ -f "$source/roster.csv" ] && roster=(--roster "$source/roster.csv")
now=()
[ -n "${RAYGRADE_NOW:-}" ] && now=(--now "$RAYGRADE_NOW")
# raygrade's exit status 2 (the file was rejected) still leaves results.json with the reason.
(cd "$root/submission" && "$source/raygrade" grade --assignment "$source/assignment.json" \
  --format gradescope --gradescope-metadata "$root/submission_metadata.json" "${roster[@]}" \
  "${now[@]}" --out "$results" "${files[0]}")
status=$?
if [ ! -s "$results/results.json" ]; then
  reject "The autograder could not grade this upload (raygrade exited with status $status). Please tell your instructor."
fi
exit 0
)sh";

}  // namespace

std::string read_file_bytes(const std::filesystem::path& path) {
  std::optional<std::string> bytes = read_whole_file(path);
  if (!bytes) {
    Diagnostic d;
    d.file = path.string();
    d.message = "cannot read the file";
    d.code = "unreadable";
    throw Error(d);
  }
  return std::move(*bytes);
}

namespace {

// A date of submission_metadata.json, or nothing when it is absent or null.
std::optional<std::int64_t> metadata_time(const Cursor& object, const char* key) {
  auto at = object.find(key);
  if (!at || at->json().is_null()) return std::nullopt;
  auto t = parse_time(at->string());
  if (!t) at->fail("a date and time, like 2026-12-04T23:59:00.000000-08:00", "invalid");
  return t;
}

}  // namespace

GradescopeMetadata read_gradescope_metadata(const std::string& path) {
  Cursor root(load_json_file(path));
  if (!root.is_object()) root.fail("submission_metadata.json is a JSON object", "type");
  GradescopeMetadata m;
  if (auto a = root.find("assignment"); a && a->is_object()) m.due = metadata_time(*a, "due_date");
  std::optional<std::int64_t> extended;
  for (const auto& u : root.at("users").items()) {
    if (!u.is_object()) u.fail("a user is an object with email and name", "type");
    m.users.push_back(StudentIdentity{u.string_or("name", ""), "", u.at("email").string()});
    if (auto a = u.find("assignment"); a && a->is_object()) {
      if (auto d = metadata_time(*a, "due_date")) extended = std::max(extended.value_or(*d), *d);
    }
  }
  if (m.users.empty()) root.at("users").fail("no user uploaded this submission");
  if (extended) m.due = extended;
  return m;
}

bool is_static_executable(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  Elf64_Ehdr header{};
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return false;
  if (std::string_view(reinterpret_cast<const char*>(header.e_ident), 4) != ELFMAG ||
      header.e_ident[EI_CLASS] != ELFCLASS64 || header.e_phentsize != sizeof(Elf64_Phdr)) {
    return false;
  }
  for (int i = 0; i < header.e_phnum; ++i) {
    Elf64_Phdr ph{};
    in.seekg(static_cast<std::streamoff>(header.e_phoff + i * sizeof ph));
    if (!in.read(reinterpret_cast<char*>(&ph), sizeof ph)) return false;
    if (ph.p_type == PT_INTERP) return false;
  }
  return header.e_type == ET_EXEC || header.e_type == ET_DYN;
}

std::optional<std::filesystem::path> find_static_raygrade(const std::filesystem::path& running) {
  if (is_static_executable(running)) return running;
  // running is <build>/<preset>/grader/raygrade.
  auto candidate =
      running.parent_path().parent_path().parent_path() / "static" / "grader" / "raygrade";
  if (is_static_executable(candidate)) return candidate;
  return std::nullopt;
}

std::vector<ZipEntry> assignment_files(const AssignmentSpec& spec, const Bank& bank) {
  std::vector<ZipEntry> entries;
  std::set<std::string> names;
  for (const auto& f : bank.files) {
    std::filesystem::path p(f);
    std::string name = p.filename().string();
    for (int k = 2; !names.insert(name).second; ++k)
      name = fmt::format("{}-{}{}", p.stem().string(), k, p.extension().string());
    entries.push_back({"bank/" + name, read_file_bytes(p), false});
  }
  // The assignment as written, with its bank in bank/ (its $schema path would point nowhere).
  nlohmann::json a = load_json_file(spec.file)->root;
  a.erase("$schema");
  a["bank"] = "bank";
  entries.push_back({"assignment.json", a.dump(2) + "\n", false});
  return entries;
}

std::vector<ZipEntry> gradescope_autograder(const AssignmentSpec& spec, const AssignmentBank& bank,
                                            const std::filesystem::path& binary,
                                            const std::string& roster) {
  if (has_per_student_numbers(spec, bank.problems) && roster.empty()) {
    throw Error(Diagnostic{spec.file, "/variants", 0, 0, Severity::kError,
                           "each student has their own numbers: give --roster (the roster the "
                           "handouts were written from, with each student's email as Gradescope "
                           "knows it), so that the autograder grades each upload as the variant "
                           "of the account that uploaded it",
                           "no-roster"});
  }
  std::vector<ZipEntry> entries = {{"setup.sh", kSetup, true},
                                   {"run_autograder", kRunAutograder, true},
                                   {"raygrade", read_file_bytes(binary), true}};
  if (!roster.empty()) {
    load_roster(roster);  // read now, so that a faulty roster fails the export, not each upload
    entries.push_back({"roster.csv", read_file_bytes(roster), false});
  }
  for (auto& e : assignment_files(spec, bank.bank)) entries.push_back(std::move(e));
  return entries;
}

void write_entries(const std::filesystem::path& folder, const std::vector<ZipEntry>& entries) {
  for (const auto& e : entries) {
    std::filesystem::path p = folder / e.name;
    std::filesystem::create_directories(p.parent_path());
    write_file_atomically(p, e.bytes);
    using std::filesystem::perms;
    std::filesystem::permissions(
        p, e.executable
               ? perms::owner_all | perms::group_read | perms::group_exec | perms::others_read |
                     perms::others_exec
               : perms::owner_read | perms::owner_write | perms::group_read | perms::others_read);
  }
}

namespace {

LmsPackage gradescope_package(const LmsExportInput& in, const std::string& out) {
  std::vector<ZipEntry> entries = gradescope_autograder(*in.spec, *in.bank, in.binary, in.roster);
  LmsPackage p;
  for (const auto& e : entries) p.files.push_back({"autograder/" + e.name, e.bytes, e.executable});
  p.files.push_back({"autograder.zip", zip_archive(entries), false});
  p.next_step = fmt::format(
      "Wrote {0}/autograder.zip (and the same files in {0}/autograder/): {1} problems of {2}, "
      "raygrade from {3}. Upload the zip as the autograder of a Gradescope programming "
      "assignment.",
      out, in.spec->problems.size(), in.spec->id, in.binary.string());
  return p;
}

LmsPackage prairielearn_package(const LmsExportInput& in, const std::string& out) {
  LmsPackage p;
  p.files = prairielearn_course(*in.spec, in.bank->problems, in.bank->bank, in.binary);
  p.next_step = fmt::format(
      "Wrote {0}/questions/{1}/ ({2} questions) and {0}/serverFilesCourse/raygrade/ (raygrade "
      "from {3}). Copy both folders into the PrairieLearn course's repository and list the "
      "questions in an assessment.",
      out, safe_file_name(in.spec->id), in.spec->problems.size(), in.binary.string());
  return p;
}

}  // namespace

const std::vector<LmsExport>& lms_exports() {
  static const std::vector<LmsExport> table = {
      {"gradescope", "Gradescope",
       "the autograder zip of a programming assignment (setup.sh, run_autograder, raygrade, the "
       "assignment and its bank)",
       true, true, &gradescope_package},
      {"prairielearn", "PrairieLearn",
       "one question per problem, with raygrade in serverFilesCourse", false, true,
       &prairielearn_package},
      {"scorm", "SCORM",
       "the practice page as a SCORM package for any LMS (Moodle, Canvas, Blackboard): graded in "
       "the student's browser, the score sent to the LMS",
       false, false, &scorm_package, true},
      {"canvas", "Canvas",
       "a QTI 1.2 package of Classic Quizzes formula questions, one per number asked, with "
       "raygrade's variants and reference answers as the variable sets",
       true, false, &canvas_package},
      {"moodle", "Moodle",
       "Moodle XML: a calculated question per number asked, with raygrade's variants and "
       "reference answers as the dataset items, and the worked solution as general feedback",
       true, false, &moodle_package},
  };
  return table;
}

const LmsExport* find_lms_export(std::string_view name) {
  for (const LmsExport& e : lms_exports()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

}  // namespace raygrade
