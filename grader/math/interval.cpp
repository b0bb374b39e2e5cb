// The per-thread count of undecided interval comparisons.
#include "math/interval.h"

namespace raygrade {

int& interval_undecided_count() {
  thread_local int count = 0;
  return count;
}

}  // namespace raygrade
