// Where each problem of a bank file starts in its text, so that a finding inside a problem is
// located by scanning that problem alone, not the whole file up to it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raygrade {

// Where a value starts: its byte offset, line and column (1-based).
struct TextPlace {
  std::size_t offset = 0;
  int line = 1;
  int column = 1;
};

// Where the elements of the top-level "problems" array start, in order; empty when the text
// has no such array. The text is valid JSON.
std::vector<TextPlace> problem_places(std::string_view text);

// The line and column of the value at `relative_path` inside the value that starts at
// `start`; {0, 0} when the path is not there.
std::pair<int, int> locate_from(std::string_view text, const TextPlace& start,
                                std::string_view relative_path);

}  // namespace raygrade
