// A class's integrity at the edges of a batch: output folders that would overwrite the
// submissions, links swapped in after the folder walk, rosters in a legacy encoding, handout
// folders that collide on other file systems, two files of one student, and the machine's
// limits (a full disk, no threads), each run as a TA would run raygrade.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "assignments/roster.h"
#include "core/error.h"
#include "grading/submission.h"
#include "run_binary.h"
#include "test_util.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_raygrade;
using testing::run_shell;
using testing::TempDir;
using testing::write_text;

using testing::kSource;
const std::string kExample = kSource + "/assignments/homework-rays.json";

// A sphere answered right (the ray along +x meets the unit sphere at (2, 0, 0) at t = 1 and 3).
constexpr const char* kIntegrityBank = R"({"problems": [{"id": "sphere-1", "kind": "intersect",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}}]})";
constexpr const char* kAnswer =
    R"({"student": "Ada", "answers": {"sphere-1": {"hits": [{"t": 1}, {"t": 3}]}}})";

TEST(Integrity, AnOutputFolderAmongTheSubmissionsIsRefused) {
  TempDir dir("out-inside");
  write_text(dir.path() / "bank.json", kIntegrityBank);
  fs::create_directories(dir.path() / "subs");
  write_text(dir.path() / "subs" / "Ada.json", kAnswer);
  for (const std::string out : {"subs", "subs/pages", "subs/."}) {
    auto r = run_raygrade("grade --problems bank.json subs --format json --out " + out, dir.path());
    EXPECT_EQ(r.exit_code, 2) << out;
    EXPECT_NE(r.err.find("inside the submissions"), std::string::npos) << out << ": " << r.err;
    // The submission is as it was, and nothing was written beside it.
    EXPECT_EQ(read_text(dir.path() / "subs" / "Ada.json"), kAnswer) << out;
    std::size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir.path() / "subs"))
      files += e.is_regular_file();
    EXPECT_EQ(files, 1u) << out;
  }
  // A file given alone: its own folder is the submissions'.
  auto r =
      run_raygrade("grade --problems bank.json subs/Ada.json --format json --out subs", dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  // Beside them is fine.
  r = run_raygrade("grade --problems bank.json subs --format json --out graded", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.path() / "graded" / "Ada.json"));
}

TEST(Integrity, ALinkSwappedInAfterTheWalkIsNotRead) {
  TempDir dir("swap");
  write_text(dir.path() / "bank.json", kIntegrityBank);
  fs::create_directories(dir.path() / "subs");
  write_text(dir.path() / "subs" / "Ada.json", kAnswer);
  // Another student's file outside the submissions, which a swap would make read as Ada's.
  write_text(dir.path() / "other.json", kAnswer);
  std::vector<Diagnostic> errors;
  std::vector<std::string> files = submission_files({(dir.path() / "subs").string()}, errors);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_TRUE(errors.empty());
  // The check is done; now the file becomes a link to the one outside.
  fs::remove(dir.path() / "subs" / "Ada.json");
  fs::create_symlink(dir.path() / "other.json", dir.path() / "subs" / "Ada.json");
  Bank bank = load_bank({(dir.path() / "bank.json").string()});
  Assignment assignment(bank.problems);
  SubmissionGrade g = assignment.grade_file(files[0]);
  EXPECT_FALSE(g.gradable);
  ASSERT_TRUE(g.fault);
  EXPECT_NE(g.fault->message.find("symbolic link"), std::string::npos) << g.fault->message;
  // A link that was there when the folder was walked, and leads inside it, is still graded.
  fs::remove(dir.path() / "subs" / "Ada.json");
  write_text(dir.path() / "subs" / "real.json", kAnswer);
  fs::create_symlink(dir.path() / "subs" / "real.json", dir.path() / "subs" / "link.json");
  files = submission_files({(dir.path() / "subs").string()}, errors);
  ASSERT_EQ(files.size(), 2u);
  for (const auto& f : files) EXPECT_TRUE(assignment.grade_file(f).gradable) << f;
}

// Not the file but a folder the walk has listed, swapped for a link to a folder elsewhere
// (issue 47): O_NOFOLLOW guards only the last component, so the file opened is compared with
// the one the walk listed (device and inode), and another is refused.
TEST(Integrity, AFolderSwappedForALinkAfterTheWalkIsNotRead) {
  TempDir dir("swap-folder");
  write_text(dir.path() / "bank.json", kIntegrityBank);
  fs::create_directories(dir.path() / "subs" / "week1");
  write_text(dir.path() / "subs" / "week1" / "Ada.json", kAnswer);
  write_text(dir.path() / "subs" / "Bob.json", kAnswer);
  fs::create_directories(dir.path() / "elsewhere");
  write_text(dir.path() / "elsewhere" / "Ada.json", kAnswer);
  std::vector<Diagnostic> errors;
  std::vector<std::optional<FileIdentity>> seen;
  std::vector<std::string> files =
      submission_files({(dir.path() / "subs").string()}, errors, &seen);
  ASSERT_EQ(files.size(), 2u);
  ASSERT_EQ(seen.size(), 2u);
  ASSERT_TRUE(seen[0] && seen[1]);
  EXPECT_TRUE(errors.empty());
  // The walk is done; now the folder week1 becomes a link to a folder outside the submissions.
  fs::rename(dir.path() / "subs" / "week1", dir.path() / "week1-moved");
  fs::create_directory_symlink(dir.path() / "elsewhere", dir.path() / "subs" / "week1");
  Bank bank = load_bank({(dir.path() / "bank.json").string()});
  Assignment assignment(bank.problems);
  std::size_t ada = files[0].find("Ada.json") != std::string::npos ? 0 : 1;
  SubmissionGrade g = assignment.grade_file(files[ada], seen[ada]);
  EXPECT_FALSE(g.gradable);
  ASSERT_TRUE(g.fault);
  EXPECT_EQ(g.fault->code, "unreadable");
  EXPECT_NE(g.fault->message.find("not the file the submissions were listed with"),
            std::string::npos)
      << g.fault->message;
  // The file beside it is the one listed, and is graded; a file edited in place is too.
  write_text(dir.path() / "subs" / "Bob.json", kAnswer);
  EXPECT_TRUE(assignment.grade_file(files[1 - ada], seen[1 - ada]).gradable);
}

TEST(Integrity, ALegacyEncodedRosterNamesItsLineAndByteAndWritesNothing) {
  TempDir dir("latin1");
  // "Zoë" in Windows-1252: ë is the single byte EB, at byte 8 of line 3.
  write_text(dir.path() / "roster.csv", "id,name\ns001,Ada\ns002,Zo\xEB\n");
  auto r =
      run_raygrade("handout '" + kExample + "' --roster roster.csv --out handouts", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("roster.csv:3:8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0xEB"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("UTF-8"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "handouts"));
}

TEST(Integrity, HandoutFoldersNeverCollideAndTheIndexNamesThemAsWritten) {
  TempDir dir("folders");
  // Ids that differ in case only collide on macOS's and Windows's file systems; one is the
  // index's own name; one starts with a character a spreadsheet reads as a formula.
  write_text(dir.path() / "roster.csv", "id\nS1\ns1\nhandouts.csv\nHANDOUTS.CSV\n-s2\n");
  auto r = run_raygrade("handout '" + kExample + "' --roster roster.csv --out out", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string index = read_text(dir.path() / "out" / "handouts.csv");
  std::set<std::string> folded;
  std::size_t rows = 0;
  std::size_t at = index.find('\n') + 1;
  while (at < index.size()) {
    std::size_t end = index.find('\n', at);
    std::string row = index.substr(at, end - at);
    at = end + 1;
    std::string folder = row.substr(row.rfind(',') + 1);
    ++rows;
    EXPECT_TRUE(fs::is_directory(dir.path() / "out" / folder)) << folder << " in " << index;
    std::string lower = folder;
    for (auto& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_NE(lower, "handouts.csv");
    EXPECT_TRUE(folded.insert(lower).second) << folder << " collides in " << index;
  }
  EXPECT_EQ(rows, 5u);
}

TEST(Integrity, TwoFilesOfOneStudentAreBothGradedAndNamed) {
  TempDir dir("twice");
  write_text(dir.path() / "roster.csv", "id,name\ns001,Ada\ns002,Alan\n");
  fs::create_directories(dir.path() / "subs");
  write_text(dir.path() / "subs" / "first.json", R"({"student": {"id": "s001"}, "answers": {}})");
  write_text(dir.path() / "subs" / "second.json", R"({"student": "Ada", "answers": {}})");
  auto r = run_raygrade("grade --assignment '" + kExample +
                            "' --roster roster.csv subs --format csv --now 2026-12-01T00:00:00Z",
                        dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // The class gradebook counts one and lists the other (--pick latest: the files' times).
  EXPECT_NE(r.err.find("student 's001': graded: latest of 2 submissions"), std::string::npos)
      << r.err;
  // Without a roster (and so without a class gradebook) both rows stay, and the double is said.
  write_text(dir.path() / "subs" / "second.json", R"({"student": {"id": "s001"}, "answers": {}})");
  r = run_raygrade(
      "grade --assignment '" + kExample + "' subs --format csv --now 2026-12-01T00:00:00Z",
      dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("student 's001' has 2 submissions, each graded"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("first.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("second.json"), std::string::npos) << r.err;
}

TEST(Integrity, AFullDiskIsAResourceFailureNotBadInput) {
  TempDir dir("full");
  write_text(dir.path() / "bank.json", kIntegrityBank);
  fs::create_directories(dir.path() / "subs");
  write_text(dir.path() / "subs" / "Ada.json", kAnswer);
  // Files may not grow past 200 bytes (a page is larger): each write fails as on a full disk
  // (EFBIG; the signal that would end the process is ignored, as a shell's trap leaves it for
  // the program). Its messages go to a pipe, which no such limit stops.
  auto r = run_shell("{ trap '' XFSZ; prlimit --fsize=200 '" RAYGRADE_BINARY
                     "' grade --problems bank.json subs --format html --out pages 2>&1; }",
                     dir.path());
  EXPECT_EQ(r.exit_code, 4) << r.out;
  EXPECT_NE(r.out.find("cannot write"), std::string::npos) << r.out;
  // No page is left half-written.
  if (fs::exists(dir.path() / "pages")) {
    for (const auto& e : fs::directory_iterator(dir.path() / "pages"))
      EXPECT_NE(e.path().extension(), ".html") << e.path();
  }
}

bool can_run_as_nobody() {
  return std::system("setpriv --reuid=nobody --regid=nogroup --clear-groups true 2>/dev/null") == 0;
}

TEST(Integrity, ThreadsThatCannotStartCostNoSubmission) {
  if (!can_run_as_nobody()) GTEST_SKIP() << "setpriv cannot switch to the user nobody";
  TempDir dir("threads");
  fs::permissions(dir.path(), fs::perms::all);
  write_text(dir.path() / "bank.json", kIntegrityBank);
  fs::create_directories(dir.path() / "subs");
  for (int i = 0; i < 8; ++i)
    write_text(dir.path() / "subs" / ("s" + std::to_string(i) + ".json"), kAnswer);
  // The user nobody may have one process: this one, and no thread besides (nor the thread
  // LeakSanitizer starts at exit under the sanitizers, so its check is off here).
  auto r = run_shell(
      "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" "
      "setpriv --reuid=nobody --regid=nogroup --clear-groups prlimit --nproc=1 '" RAYGRADE_BINARY
      "' grade --problems bank.json subs --format csv -j 4",
      dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::size_t rows = 0;
  for (char c : r.out) rows += c == '\n';
  EXPECT_EQ(rows, 9u) << r.out;  // the header and eight students
  EXPECT_EQ(r.out.find(",0,"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace raygrade
