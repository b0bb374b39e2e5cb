// Offsets of the problems of a bank file, and locating a path from one of them.
#include "check/spans.h"

#include "json/source.h"

namespace raygrade {
namespace {

// Moves `i` past the string that starts at text[i] == '"'.
void skip_string(std::string_view text, std::size_t& i) {
  for (++i; i < text.size(); ++i) {
    if (text[i] == '\\') {
      ++i;
    } else if (text[i] == '"') {
      ++i;
      return;
    }
  }
}

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

std::vector<TextPlace> problem_places(std::string_view text) {
  std::vector<TextPlace> out;
  std::size_t i = 0;
  int line = 1;
  std::size_t line_start = 0;  // JSON strings hold no raw newline: lines end outside them
  auto place = [&](std::size_t at) {
    return TextPlace{at, line, static_cast<int>(at - line_start) + 1};
  };
  int depth = 0;
  bool in_problems = false;  // inside the top-level "problems" array
  std::string_view last_key;
  while (i < text.size()) {
    char c = text[i];
    if (c == '"') {
      std::size_t start = i;
      skip_string(text, i);
      if (depth == 1) {
        std::size_t j = i;
        while (j < text.size() && is_space(text[j])) ++j;
        if (j < text.size() && text[j] == ':') last_key = text.substr(start + 1, i - start - 2);
      } else if (in_problems && depth == 2) {
        out.push_back(place(start));
      }
      continue;
    }
    if (c == '{' || c == '[') {
      if (in_problems && depth == 2) out.push_back(place(i));
      ++depth;
      if (depth == 2 && c == '[' && last_key == "problems") in_problems = true;
    } else if (c == '}' || c == ']') {
      --depth;
      if (depth == 1) in_problems = false;
    } else if (in_problems && depth == 2 && !is_space(c) && c != ',') {
      out.push_back(place(i));  // a number, true, false or null as an element
      while (i < text.size() && text[i] != ',' && text[i] != ']' && !is_space(text[i])) ++i;
      continue;
    }
    if (c == '\n') {
      ++line;
      line_start = i + 1;
    }
    ++i;
  }
  return out;
}

std::pair<int, int> locate_from(std::string_view text, const TextPlace& start,
                                std::string_view relative_path) {
  auto [line, column] = locate(text.substr(start.offset), relative_path);
  if (line == 0) return {0, 0};
  return {start.line + line - 1, line == 1 ? start.column + column - 1 : column};
}

}  // namespace raygrade
