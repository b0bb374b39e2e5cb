// A small seeded random number generator whose output is the same on every platform and
// library: xoshiro256** seeded by SplitMix64, with its own integer distributions (the
// standard library's distributions differ between implementations).
#pragma once

#include <cstdint>
#include <vector>

namespace raygrade {

class Prng {
 public:
  explicit Prng(std::uint64_t seed);

  std::uint64_t next();
  // Uniform in [0, n), without modulo bias; n > 0.
  std::uint64_t below(std::uint64_t n);
  // Uniform integer in [lo, hi].
  int range(int lo, int hi);
  // +1 or -1.
  int sign();
  template <typename T>
  const T& pick(const std::vector<T>& items) {
    return items[below(items.size())];
  }

 private:
  std::uint64_t s_[4];
};

}  // namespace raygrade
