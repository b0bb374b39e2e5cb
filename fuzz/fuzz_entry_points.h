// The entry points the fuzz targets drive, shared with the regression tests that replay the
// corpora and every input that ever crashed one of them.
#pragma once

#include <string_view>
#include <vector>

namespace raygrade::fuzz {

// Feeds `input` to one reader of untrusted input. A raygrade::Error is the expected outcome
// of bad input and is swallowed; anything else (another exception, a crash, a sanitizer
// report) is a bug.
using EntryPoint = void (*)(std::string_view input);

struct Target {
  std::string_view name;  // as in fuzz/corpus/<name>/ and `scripts/fuzz.sh <name>`
  EntryPoint run;
};

const std::vector<Target>& targets();

}  // namespace raygrade::fuzz
