// Gradescope: its autograder, and what run_autograder reads from it.
#include "assignments/platforms/gradescope.h"

#include <fmt/format.h>

#include "assignments/roster.h"
#include "assignments/variants.h"
#include "grading/outputs.h"
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

// A date of submission_metadata.json, or nothing when it is absent or null.
std::optional<std::int64_t> metadata_time(const Cursor& object, const char* key) {
  auto at = object.find(key);
  if (!at || at->json().is_null()) return std::nullopt;
  auto t = parse_time(at->string());
  if (!t) at->fail("a date and time, like 2026-12-04T23:59:00.000000-08:00", "invalid");
  return t;
}

}  // namespace

UploadMetadata read_gradescope_metadata(const std::string& path) {
  Cursor root(load_json_file(path));
  if (!root.is_object()) root.fail("submission_metadata.json is a JSON object", "type");
  UploadMetadata m;
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

}  // namespace

LmsExport Gradescope::lms_export() {
  LmsExport e;
  e.summary =
      "the autograder zip of a programming assignment (setup.sh, run_autograder, raygrade, the "
      "assignment and its bank)";
  e.takes_roster = true;
  e.ships_binary = true;
  e.roster_help =
      "the roster CSV the handouts were written from (id, name, email); needed when each "
      "student has their own numbers";
  e.make = &gradescope_package;
  return e;
}

PlatformUploads Gradescope::uploads() {
  return {"--gradescope-metadata",
          "Gradescope's submission_metadata.json; the student a submission names must be the "
          "account that uploaded it",
          &read_gradescope_metadata};
}

nlohmann::json gradescope_json(const SubmissionGrade& g, double execution_seconds) {
  nlohmann::json tests = nlohmann::json::array();
  for (const GradeResult& r : g.results) {
    std::string output = joined_lines(feedback_lines(r));
    tests.push_back({{"name", result_test_name(r)},
                     {"score", r.score},
                     {"max_score", r.max_score},
                     {"status", r.score >= r.max_score ? "passed" : "failed"},
                     {"output", output},
                     {"output_format", "text"},
                     {"visibility", "visible"}});
  }
  return {{"score", g.gradable ? g.score : 0.0},
          {"execution_time", execution_seconds},
          {"output", grade_summary(g)},
          {"output_format", "text"},
          {"visibility", "visible"},
          {"tests", tests}};
}

namespace {

std::string gradescope_format(const SubmissionGrade& g, double seconds) {
  return json_text(gradescope_json(g, seconds)) + "\n";
}

}  // namespace

GradeFormat Gradescope::results_format() {
  return {"gradescope",
          "Gradescope's autograder results.json",
          ".json",
          GradeLayout::kDocument,
          true,
          true,
          &gradescope_format};
}

}  // namespace raygrade
