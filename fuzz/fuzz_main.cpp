// The libFuzzer entry of one fuzz target, chosen at build time by RAYGRADE_FUZZ_TARGET.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz_entry_points.h"

namespace {

raygrade::fuzz::EntryPoint find_entry() {
  for (const auto& t : raygrade::fuzz::targets()) {
    if (t.name == std::string_view(RAYGRADE_FUZZ_TARGET)) return t.run;
  }
  std::abort();  // a name in fuzz/CMakeLists.txt without an entry point
}

const raygrade::fuzz::EntryPoint kEntry = find_entry();

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  kEntry(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
