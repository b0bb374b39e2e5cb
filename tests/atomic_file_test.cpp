// write_file_atomically: whole files or nothing, and no temporary files left behind;
// update_generated_file: a generated file checked or brought up to date.
#include "core/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "test_util.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;

// A fresh empty folder for one test, removed at the end.
class ScratchFolder {
 public:
  ScratchFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            fmt::format("raygrade-{}-{}-{}", info->test_suite_name(), info->name(), ::getpid());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchFolder() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(path_)) out.push_back(e.path().filename());
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  fs::path path_;
};

using testing::read_all;

TEST(AtomicFile, WritesTheBytes) {
  ScratchFolder dir;
  std::string bytes("{\"a\": 1}\n\0tail", 14);
  write_file_atomically(dir.path() / "results.json", bytes);
  EXPECT_EQ(read_all(dir.path() / "results.json"), bytes);
  EXPECT_EQ(dir.names(), std::vector<std::string>{"results.json"});  // no temporary file left
}

TEST(AtomicFile, ReplacesAnOldFileWhole) {
  ScratchFolder dir;
  write_file_atomically(dir.path() / "r.json", std::string(10000, 'x'));
  write_file_atomically(dir.path() / "r.json", "short");
  EXPECT_EQ(read_all(dir.path() / "r.json"), "short");
  EXPECT_EQ(dir.names(), std::vector<std::string>{"r.json"});
}

TEST(AtomicFile, WritesAnEmptyFile) {
  ScratchFolder dir;
  write_file_atomically(dir.path() / "empty.txt", "");
  EXPECT_TRUE(fs::exists(dir.path() / "empty.txt"));
  EXPECT_EQ(fs::file_size(dir.path() / "empty.txt"), 0u);
}

TEST(AtomicFile, FileIsReadableByOthers) {
  ScratchFolder dir;
  write_file_atomically(dir.path() / "r.json", "{}");
  auto perms = fs::status(dir.path() / "r.json").permissions();
  EXPECT_NE(perms & fs::perms::others_read, fs::perms::none);
}

TEST(AtomicFile, MissingFolderIsAnErrorNamingThePath) {
  ScratchFolder dir;
  fs::path target = dir.path() / "no-such-folder" / "r.json";
  try {
    write_file_atomically(target, "{}");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().file, target.string());
    EXPECT_EQ(e.diagnostic().code, "unwritable");
  }
  EXPECT_EQ(dir.names(), std::vector<std::string>{});
}

// Renaming over a non-empty folder fails after the bytes were written: the folder stays, and
// the temporary file is removed.
TEST(AtomicFile, FailedRenameLeavesTargetAndNoTemporaryFile) {
  ScratchFolder dir;
  fs::create_directories(dir.path() / "r.json" / "inside");
  EXPECT_THROW(write_file_atomically(dir.path() / "r.json", "{}"), Error);
  EXPECT_TRUE(fs::is_directory(dir.path() / "r.json" / "inside"));
  EXPECT_EQ(dir.names(), std::vector<std::string>{"r.json"});
}

// A generated file: checked, it is only reported stale (missing or changed by hand) and left
// as it is; brought up to date, it is written once and then found up to date.
TEST(AtomicFile, UpdateGeneratedFileChecksOrWrites) {
  ScratchFolder dir;
  fs::path p = dir.path() / "schema.json";
  EXPECT_EQ(update_generated_file(p, "new\n", true), FileUpdate::kStale);
  EXPECT_FALSE(fs::exists(p));
  EXPECT_EQ(update_generated_file(p, "new\n", false), FileUpdate::kWritten);
  EXPECT_EQ(read_all(p), "new\n");
  EXPECT_EQ(update_generated_file(p, "new\n", true), FileUpdate::kUpToDate);
  EXPECT_EQ(update_generated_file(p, "new\n", false), FileUpdate::kUpToDate);
  write_file_atomically(p, "edited by hand\n");
  EXPECT_EQ(update_generated_file(p, "new\n", true), FileUpdate::kStale);
  EXPECT_EQ(read_all(p), "edited by hand\n");
  EXPECT_EQ(update_generated_file(p, "new\n", false, false), FileUpdate::kWritten);
  EXPECT_EQ(read_all(p), "new\n");
  EXPECT_EQ(dir.names(), std::vector<std::string>{"schema.json"});
}

}  // namespace
}  // namespace raygrade
