// Faults of a batch beyond its files' contents: text that would act on a terminal, folders
// that cannot be read, entries that are not regular files, symbolic links, temporary files of
// a killed run, and two graders on one output folder. Each runs the real raygrade binary.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "run_binary.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_text;
using testing::run_shell;
using testing::TempDir;
using testing::write_text;

const fs::path kProblems = fs::path(RAYGRADE_SOURCE_DIR) / "tests/fixtures/hostile/problems.json";

// A right answer to both problems of the hostile bank: the ray along +x meets the unit sphere
// at (2, 0, 0) at t = 1 and 3, and the plane x = 2 at t = 2.
const char* kRightAnswers =
    R"({"sphere-1": {"hits": [{"t": 1, "point": [1, 0, 0]}, {"t": 3, "point": [3, 0, 0]}]},
        "plane-1": {"hits": [{"t": 2, "point": [2, 0, 0]}]}})";

std::string submission(const std::string& student_json) {
  return R"({"student": )" + student_json + R"(, "answers": )" + kRightAnswers + "}";
}

// True when `text` holds a byte a terminal acts on: C0 controls other than tab and newline
// (ESC, BEL, NUL, carriage return), DEL, or a C1 control in UTF-8 (C2 80 to C2 9F).
bool has_terminal_control(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7F) return true;
    if (c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) < 0xA0)
      return true;
  }
  return false;
}

class BatchFaults : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(subs_); }

  testing::RunResult grade(const std::string& args, const fs::path& bank = kProblems) {
    // `timeout`: a regression that blocks on a FIFO fails the test instead of hanging it.
    return run_shell(
        "timeout 60 '" RAYGRADE_BINARY "' grade --problems '" + bank.string() + "' " + args,
        dir_.path());
  }

  TempDir dir_{"batch-faults"};
  fs::path subs_ = dir_.path() / "submissions";
};

// A name that retitles the terminal (ESC ] 0 ; ... BEL), clears it (ESC [ 2 J), and does the
// same with the C1 control U+009B (CSI); a problem title with an escape sequence; a typed
// answer with one. None reaches standard output raw in text, CSV or JSON.
TEST_F(BatchFaults, TerminalControlsNeverReachStandardOutput) {
  json bank = json::parse(read_text(kProblems));
  bank["problems"][0]["title"] = "Sphere\x1b[31m red\x07";
  fs::path bank_path = dir_.path() / "bank.json";
  write_text(bank_path, bank.dump());
  write_text(subs_ / "eve.json",
             submission(R"({"name": "Eve\u001b]0;owned\u0007\u009b2J\u007f", "id": "s1"})"));
  write_text(
      subs_ / "mallory.json",
      R"({"student": "Mallory\u001b[2J", "answers": {"plane-1": {"hits": [{"t": "2\u001b[2J", "point": [2, 0, 0]}]}}})");
  for (std::string format : {"text", "csv", "json"}) {
    auto r = grade("'" + subs_.string() + "' --format " + format, bank_path);
    EXPECT_NE(r.out.find("Eve"), std::string::npos) << format << ": " << r.out;
    EXPECT_FALSE(has_terminal_control(r.out)) << format << ":\n" << r.out;
    EXPECT_FALSE(has_terminal_control(r.err)) << format << ":\n" << r.err;
  }
  // JSON keeps every character, escaped: parsed back, the name is the name.
  auto r = grade("'" + (subs_ / "eve.json").string() + "' --format json", bank_path);
  json j = json::parse(r.out);
  EXPECT_EQ(j["submissions"][0]["student"],
            "Eve\x1b]0;owned\x07\xc2\x9b"
            "2J\x7f");
}

// A cell starting with NUL or a line feed before a formula: written out, never a formula.
TEST_F(BatchFaults, GradebookCellsStartingWithNulOrLineFeedAreNeutral) {
  write_text(subs_ / "nul.json", submission(R"x("\u0000=HYPERLINK(\"http://x\")")x"));
  write_text(subs_ / "lf.json", submission(R"("\n=1+1")"));
  auto r = grade("'" + subs_.string() + "' --format csv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find('\0'), std::string::npos);
  EXPECT_NE(r.out.find("\n\\x0A=1+1,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n\"\\x00=HYPERLINK(\"\"http://x\"\")\","), std::string::npos) << r.out;
  // Three lines: the header and one per student, no line broken inside a cell.
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3);
}

// Runs `command` as the unprivileged user nobody (root reads a mode-000 folder regardless).
// Returns false when privileges cannot be dropped here.
bool can_run_as_nobody() {
  return std::system("setpriv --reuid=nobody --regid=nogroup --clear-groups true 2>/dev/null") == 0;
}

// A mode-000 subfolder, read by an unprivileged user: reported, exit 2, the rest graded.
TEST_F(BatchFaults, UnreadableSubfolderIsReportedAndTheRestGraded) {
  if (!can_run_as_nobody()) GTEST_SKIP() << "setpriv cannot switch to the user nobody";
  fs::permissions(dir_.path(), fs::perms::owner_all | fs::perms::group_read |
                                   fs::perms::group_exec | fs::perms::others_read |
                                   fs::perms::others_exec);
  write_text(subs_ / "a.json", submission(R"("Ada")"));
  fs::create_directories(subs_ / "locked");
  write_text(subs_ / "locked" / "b.json", submission(R"("Bob")"));
  write_text(subs_ / "z.json", submission(R"("Zoe")"));
  fs::permissions(subs_ / "locked", fs::perms::none);
  auto r = run_shell("setpriv --reuid=nobody --regid=nogroup --clear-groups '" RAYGRADE_BINARY
                     "' grade --problems '" +
                         kProblems.string() + "' '" + subs_.string() + "' --format csv",
                     dir_.path());
  fs::permissions(subs_ / "locked", fs::perms::owner_all);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find((subs_ / "locked").string() +
                       ": error: cannot read the folder: Permission denied"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("\nAda,"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nZoe,"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("Bob"), std::string::npos) << r.out;
}

// In a folder: a FIFO, a dangling link, a link to a folder, a link leading outside the folder
// and one to a file inside it. Only regular files inside are graded; every other entry is
// named on standard error with why; nothing blocks.
TEST_F(BatchFaults, SpecialEntriesAreSkippedAndReported) {
  write_text(subs_ / "a.json", submission(R"("Ada")"));
  ASSERT_EQ(::mkfifo((subs_ / "pipe.json").c_str(), 0644), 0);
  fs::create_symlink("missing.json", subs_ / "gone.json");
  fs::create_directories(dir_.path() / "elsewhere");
  write_text(dir_.path() / "elsewhere" / "x.json", submission(R"("Xavier")"));
  fs::create_symlink(dir_.path() / "elsewhere" / "x.json", subs_ / "outside.json");
  fs::create_symlink("/dev/null", subs_ / "null.json");
  fs::create_directories(subs_ / "inner");
  fs::create_symlink("inner", subs_ / "folder-link");
  write_text(subs_ / "inner" / "c.json", submission(R"("Cy")"));
  fs::create_symlink("inner/c.json", subs_ / "inside.json");
  auto r = grade("'" + subs_.string() + "' --format csv");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  for (const char* line : {"pipe.json: error: skipped: a FIFO (named pipe), not a regular file",
                           "gone.json: error: skipped: a symbolic link to nothing",
                           "outside.json: error: skipped: a symbolic link leading outside",
                           "null.json: error: skipped: a symbolic link leading outside",
                           "folder-link: error: skipped: a symbolic link to a folder"}) {
    EXPECT_NE(r.err.find(line), std::string::npos) << line << "\n" << r.err;
  }
  EXPECT_NE(r.out.find("\nAda,"), std::string::npos) << r.out;
  // Cy twice: inner/c.json and the link to it inside the folder.
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 4) << r.out;
  EXPECT_EQ(r.out.find("Xavier"), std::string::npos) << r.out;
}

// A FIFO named on the command line (a shell glob passes it) is reported, not opened blocking.
TEST_F(BatchFaults, NamedFifoDoesNotHang) {
  write_text(subs_ / "a.json", submission(R"("Ada")"));
  ASSERT_EQ(::mkfifo((subs_ / "pipe.json").c_str(), 0644), 0);
  auto r = run_shell("timeout 60 '" RAYGRADE_BINARY "' grade --problems '" + kProblems.string() +
                         "' '" + (subs_ / "a.json").string() + "' '" +
                         (subs_ / "pipe.json").string() + "' --format csv",
                     dir_.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("pipe.json: error: skipped: a FIFO (named pipe), not a regular file"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("\nAda,"), std::string::npos) << r.out;
}

// What a run killed mid-write left (".NAME.tmp-XXXXXX") is removed by the next run on the
// folder; a file that only looks similar stays.
TEST_F(BatchFaults, TemporaryFilesOfAKilledRunAreRemoved) {
  write_text(subs_ / "a.json", submission(R"({"name": "Ada", "id": "s001"})"));
  fs::path out = dir_.path() / "out";
  fs::create_directories(out);
  write_text(out / ".s001.html.tmp-Ab12Cd", "<html><body>half a pa");
  write_text(out / ".gradebook.csv.tmp-zzzzzz", "student,fi");
  write_text(out / "notes.tmp-Ab12Cd", "mine");
  auto r = grade("'" + subs_.string() + "' --format html --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / ".s001.html.tmp-Ab12Cd"));
  EXPECT_FALSE(fs::exists(out / ".gradebook.csv.tmp-zzzzzz"));
  EXPECT_TRUE(fs::exists(out / "notes.tmp-Ab12Cd"));
  EXPECT_TRUE(fs::exists(out / "s001.html"));  // pages are named after the student's id
  EXPECT_NE(r.err.find("removed .s001.html.tmp-Ab12Cd"), std::string::npos) << r.err;
}

// A second grader on a folder another one holds stops at once, naming the holder, and writes
// nothing there.
TEST_F(BatchFaults, SecondGraderOnOneFolderIsRefused) {
  write_text(subs_ / "a.json", submission(R"({"name": "Ada", "id": "s001"})"));
  fs::path out = dir_.path() / "out";
  fs::create_directories(out);
  int fd = ::open((out / ".raygrade.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  std::string holder = "raygrade grade, process 4242 on grading-host, since 2026-01-01T00:00:00Z";
  ASSERT_EQ(::write(fd, holder.data(), holder.size()), static_cast<ssize_t>(holder.size()));
  auto r = grade("'" + subs_.string() + "' --format html --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the folder is in use by another raygrade (" + holder + ")"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out / "s001.html"));
  ::close(fd);
  // Released (as when its holder ends, however it ends), the folder is free again.
  r = grade("'" + subs_.string() + "' --format html --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "s001.html"));
  // A run that ends normally leaves no lock file behind.
  EXPECT_FALSE(fs::exists(out / ".raygrade.lock"));
}

// A batch of pages is made durable with one flush of the file system at the end, not one
// fsync per page: counted in the system calls the grader makes (strace).
TEST_F(BatchFaults, BatchIsFlushedOnceNotOncePerFile) {
  if (std::system("strace -o /dev/null true 2>/dev/null") != 0) GTEST_SKIP() << "no strace";
  for (int i = 0; i < 5; ++i) {
    write_text(subs_ / ("s" + std::to_string(i) + ".json"),
               submission(R"("S)" + std::to_string(i) + R"(")"));
  }
  fs::path out = dir_.path() / "out";
  fs::path trace = dir_.path() / "trace.txt";
  // LeakSanitizer cannot run under ptrace: in the sanitizer build the traced grader runs
  // without it (the other tests check for leaks).
  auto r =
      run_shell("ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" strace -f -o '" +
                    trace.string() +
                    "' -e trace=fsync,fdatasync,syncfs,sync,sync_file_range '" RAYGRADE_BINARY
                    "' grade --problems '" +
                    kProblems.string() + "' '" + subs_.string() + "' --format html --out '" +
                    out.string() + "'",
                dir_.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::string calls = read_text(trace);
  auto count = [&](const std::string& name) {
    std::size_t n = 0;
    for (std::size_t at = 0; (at = calls.find(" " + name + "(", at)) != std::string::npos; ++at)
      ++n;
    return n;
  };
  EXPECT_EQ(count("fsync") + count("fdatasync"), 0u) << calls;
  EXPECT_EQ(count("syncfs"), 1u) << calls;
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(fs::exists(out / ("S" + std::to_string(i) + ".html")));
}

// JSON on standard output is one document, whatever the batch's size, empty included.
TEST_F(BatchFaults, StreamedJsonIsOneDocument) {
  auto empty = grade("'" + subs_.string() + "' --format json");
  EXPECT_EQ(json::parse(empty.out), json::parse(R"({"submissions": []})"));
  write_text(subs_ / "a.json", submission(R"("Ada")"));
  write_text(subs_ / "b.json", R"({"student": "Bob", "answers": [1]})");
  write_text(subs_ / "c.json", submission(R"("Cy")"));
  auto r = grade("'" + subs_.string() + "' --format json");
  EXPECT_EQ(r.exit_code, 2);
  json j = json::parse(r.out);
  ASSERT_EQ(j.size(), 1u);
  ASSERT_EQ(j["submissions"].size(), 3u);
  EXPECT_EQ(j["submissions"][0]["student"], "Ada");
  EXPECT_EQ(j["submissions"][0]["score"], j["submissions"][0]["max_score"]);
  EXPECT_EQ(j["submissions"][1]["gradable"], false);
  EXPECT_EQ(j["submissions"][2]["student"], "Cy");
}

}  // namespace
}  // namespace raygrade
