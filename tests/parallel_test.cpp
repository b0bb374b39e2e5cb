// parallel_map: every item once, the results in order, the first failure rethrown.
#include "core/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

namespace raygrade {
namespace {

TEST(ParallelMap, ResultsInOrderWhateverTheThreads) {
  for (unsigned jobs : {0u, 1u, 2u, 3u, 16u}) {
    std::atomic<int> calls{0};
    auto squares = parallel_map<long>(1000, jobs, [&](std::size_t i) {
      ++calls;
      return static_cast<long>(i * i);
    });
    ASSERT_EQ(squares.size(), 1000u);
    EXPECT_EQ(calls.load(), 1000) << "each item exactly once, " << jobs << " threads";
    for (std::size_t i = 0; i < squares.size(); ++i) EXPECT_EQ(squares[i], long(i * i));
  }
  EXPECT_TRUE(parallel_map<int>(0, 4, [](std::size_t) { return 1; }).empty());
}

TEST(ParallelMap, RunsOnSeveralThreads) {
  std::mutex m;
  std::set<std::thread::id> seen;
  std::atomic<int> waiting{0};
  parallel_map<int>(2, 2, [&](std::size_t) {
    {
      std::lock_guard lock(m);
      seen.insert(std::this_thread::get_id());
    }
    // Both items are taken at once, by two threads: each waits until the other has started.
    // On one thread the wait would never end; it gives up after 10 s and the test fails.
    ++waiting;
    auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (waiting.load() < 2 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::yield();
    return 0;
  });
  EXPECT_EQ(seen.size(), 2u);
}

TEST(ParallelMap, TheFirstFailureInOrderIsRethrownAfterAllWork) {
  std::atomic<int> calls{0};
  try {
    parallel_map<int>(100, 3, [&](std::size_t i) {
      ++calls;
      if (i == 70 || i == 30) throw std::runtime_error("item " + std::to_string(i));
      return 0;
    });
    FAIL() << "nothing thrown";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "item 30");
  }
  EXPECT_EQ(calls.load(), 100) << "the other items are still done";
}

}  // namespace
}  // namespace raygrade
