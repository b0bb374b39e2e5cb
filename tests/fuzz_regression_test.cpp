// Replays every fuzz seed (fuzz/corpus/<target>/) and every input that once crashed a fuzz
// target (tests/fixtures/fuzz/<target>/) through the target's entry point. Under the asan
// preset a memory error or undefined behaviour fails the run; in any build an exception other
// than raygrade::Error escapes and fails the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz_entry_points.h"
#include "test_util.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs_in(const fs::path& folder) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    if (e.is_regular_file()) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

using testing::read_all;

TEST(FuzzRegression, EveryTargetHasSeeds) {
  for (const auto& t : fuzz::targets()) {
    EXPECT_FALSE(inputs_in(fs::path(RAYGRADE_SOURCE_DIR) / "fuzz/corpus" / t.name).empty())
        << t.name;
  }
}

TEST(FuzzRegression, SeedsAndPastCrashesRunCleanly) {
  std::size_t replayed = 0;
  for (const auto& t : fuzz::targets()) {
    for (const char* folder : {"fuzz/corpus", "tests/fixtures/fuzz"}) {
      for (const auto& input : inputs_in(fs::path(RAYGRADE_SOURCE_DIR) / folder / t.name)) {
        SCOPED_TRACE(input.string());
        EXPECT_NO_THROW(t.run(read_all(input)));
        ++replayed;
      }
    }
  }
  EXPECT_GT(replayed, 0u);
}

}  // namespace
}  // namespace raygrade
