// Checks on raw JSON text: limits before parsing, duplicate keys and overflowing numbers after.
#include "json/scan.h"

#include <cmath>
#include <cstdlib>
#include <set>
#include <vector>

#include "core/escape.h"
#include "json/cursor.h"

namespace raygrade {

std::pair<int, int> line_column_of(std::string_view text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

std::optional<TextFault> check_limits(std::string_view text, const JsonLimits& limits) {
  // items[d] counts the commas seen in the open container at depth d + 1.
  std::vector<std::size_t> items;
  bool in_string = false;
  std::size_t string_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
        if (i - string_start - 1 > limits.max_string) {
          return TextFault{
              string_start, "",
              fmt::format("string longer than the limit of {} bytes", limits.max_string), "limit"};
        }
      }
    } else if (c == '"') {
      in_string = true;
      string_start = i;
    } else if (c == '[' || c == '{') {
      if (static_cast<int>(items.size()) >= limits.max_depth) {
        return TextFault{
            i, "", fmt::format("nesting deeper than the limit of {} levels", limits.max_depth),
            "limit"};
      }
      items.push_back(0);
    } else if (c == ']' || c == '}') {
      if (!items.empty()) items.pop_back();
    } else if (c == ',' && !items.empty()) {
      if (++items.back() >= limits.max_items) {
        return TextFault{
            i, "",
            fmt::format("more than the limit of {} items in one array or object", limits.max_items),
            "limit"};
      }
    }
  }
  return std::nullopt;
}

namespace {

// A walk over JSON text that keeps the JSON pointer of where it is and the keys of every open
// object. It needs no recursion: one frame per open container.
class FaultFinder {
 public:
  explicit FaultFinder(std::string_view text) : text_(text) {}

  std::optional<TextFault> run() {
    while (pos_ < text_.size()) {
      char c = text_[pos_];
      if (c == '{' || c == '[') {
        frames_.push_back(Frame{c == '{', c == '{', 0, "", {}});
        ++pos_;
      } else if (c == '}' || c == ']') {
        if (frames_.empty()) return std::nullopt;
        frames_.pop_back();
        ++pos_;
      } else if (c == ',') {
        if (frames_.empty()) return std::nullopt;
        Frame& f = frames_.back();
        if (f.object) {
          f.expect_key = true;
        } else {
          ++f.index;
        }
        ++pos_;
      } else if (c == '"') {
        std::size_t start = pos_;
        auto s = read_string();
        if (!s) return std::nullopt;
        if (!frames_.empty() && frames_.back().object && frames_.back().expect_key) {
          Frame& f = frames_.back();
          f.expect_key = false;
          f.key = *s;
          if (!f.keys.insert(*s).second) {
            return TextFault{
                start, path(),
                fmt::format("duplicate key '{}' (JSON keeps only one of them)", printable(*s, 60)),
                "duplicate-key"};
          }
        }
      } else if (c == '-' || (c >= '0' && c <= '9')) {
        std::size_t start = pos_;
        while (pos_ < text_.size() &&
               std::string_view("0123456789+-.eE").find(text_[pos_]) != std::string_view::npos) {
          ++pos_;
        }
        std::string number(text_.substr(start, pos_ - start));
        if (std::isinf(std::strtold(number.c_str(), nullptr))) {
          return TextFault{start, path(),
                           fmt::format("number out of range: {} is beyond even a long double "
                                       "(about ±1.2e4932)",
                                       printable(number, 40)),
                           "range"};
        }
      } else {
        ++pos_;
      }
    }
    return std::nullopt;
  }

 private:
  struct Frame {
    bool object;
    bool expect_key;
    std::size_t index;
    std::string key;
    std::set<std::string> keys;
  };

  // At '"': the decoded string, with the position after its closing quote.
  std::optional<std::string> read_string() {
    std::size_t start = pos_++;
    bool escaped = false;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      if (text_[pos_] == '\\') {
        escaped = true;
        ++pos_;
      }
      ++pos_;
    }
    if (pos_ >= text_.size()) return std::nullopt;
    ++pos_;
    std::string_view raw = text_.substr(start, pos_ - start);
    if (!escaped) return std::string(raw.substr(1, raw.size() - 2));
    // Escapes ("\u0061" is "a"): let nlohmann decode the one string.
    auto decoded = nlohmann::json::parse(raw, nullptr, false);
    if (!decoded.is_string()) return std::nullopt;
    return decoded.get<std::string>();
  }

  // The JSON pointer of the value being read.
  std::string path() const {
    std::string out;
    for (const auto& f : frames_) {
      out += '/';
      out += f.object ? pointer_token(f.key) : std::to_string(f.index);
    }
    return out;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::vector<Frame> frames_;
};

}  // namespace

std::optional<TextFault> find_duplicate_or_overflow(std::string_view text) {
  return FaultFinder(text).run();
}

}  // namespace raygrade
