// Work spread over threads, its results kept in order.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace raygrade {

// The number of threads to use when none is asked for: the machine's cores, at least one.
inline unsigned default_jobs() { return std::max(1u, std::thread::hardware_concurrency()); }

// work(i) for every i in [0, count), on up to `jobs` threads (the calling thread is one of
// them), and the results in the order of i. What work(i) throws is rethrown here, after every
// thread has stopped: the exception of the smallest such i. `work` must be safe to call from
// several threads at once; Result must be default-constructible. When a thread cannot be
// started, the work is shared by those that could (at least the calling one).
template <typename Result, typename Work>
std::vector<Result> parallel_map(std::size_t count, unsigned jobs, const Work& work) {
  std::vector<Result> results(count);
  std::vector<std::exception_ptr> failures(count);
  std::atomic<std::size_t> next{0};
  auto run = [&] {
    for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) {
      try {
        results[i] = work(i);
      } catch (...) {
        failures[i] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> threads;
    std::size_t helpers = std::min<std::size_t>(std::max(1u, jobs), count);
    for (std::size_t t = 1; t < helpers; ++t) {
      // A thread that cannot start (a process limit, a container's pids limit) is not needed:
      // the threads already started, and this one, share the work.
      try {
        threads.emplace_back(run);
      } catch (const std::system_error&) {
        break;
      }
    }
    run();
  }  // the threads are joined here
  for (auto& f : failures) {
    if (f) std::rethrow_exception(f);
  }
  return results;
}

}  // namespace raygrade
