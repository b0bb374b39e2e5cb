// Checks on raw JSON text that nlohmann's parser does not make: limits checked before parsing
// (nesting depth, string length, items in one array or object), and, on text that parses,
// duplicate keys (nlohmann keeps the last one silently) and numbers too large for a long double.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "json/source.h"

namespace raygrade {

// A fault found in JSON text: where (byte offset and JSON pointer, as far as known) and what.
struct TextFault {
  std::size_t offset = 0;
  std::string path;
  std::string message;
  std::string code;  // "limit", "duplicate-key" or "range"
};

// Nesting depth, string length and items per container against `limits`. Works on any text
// (it does not need valid JSON), in one pass without recursion.
std::optional<TextFault> check_limits(std::string_view text, const JsonLimits& limits);

// The first duplicate key or number that overflows a long double ("1e5000"), in document
// order. (Numbers beyond a double but within a long double, such as 1e400, are parsed to
// infinity and reported by Cursor::number with their path.) Meant for text that nlohmann
// accepted (or rejected only for an overflowing number);
// on other text it stops quietly at the first thing it does not understand.
std::optional<TextFault> find_duplicate_or_overflow(std::string_view text);

// The 1-based line and column of byte `offset`.
std::pair<int, int> line_column_of(std::string_view text, std::size_t offset);

}  // namespace raygrade
