// Reading JSON files with limits, and mapping JSON pointers back to lines and columns.
#include "json/source.h"

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace raygrade {
namespace {

[[noreturn]] void fail(const std::string& file, std::string msg, int line = 0, int column = 0,
                       std::string code = "bad-json") {
  throw Error(
      Diagnostic{file, "", line, column, Severity::kError, std::move(msg), std::move(code)});
}

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

// Checks nesting depth and string lengths before nlohmann's recursive parser sees the text.
void prescan(const std::string& name, std::string_view text, const JsonLimits& limits) {
  int depth = 0;
  bool in_string = false;
  std::size_t string_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
        if (i - string_start > limits.max_string) {
          auto [l, col] = line_column_of(text, string_start);
          fail(name, fmt::format("string longer than the limit of {} bytes", limits.max_string), l,
               col, "limit");
        }
      }
    } else if (c == '"') {
      in_string = true;
      string_start = i;
    } else if (c == '[' || c == '{') {
      if (++depth > limits.max_depth) {
        auto [l, col] = line_column_of(text, i);
        fail(name, fmt::format("nesting deeper than the limit of {} levels", limits.max_depth), l,
             col, "limit");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// JSON with long double numbers: it parses literals such as 1e400 that overflow a double.
using WideJson = nlohmann::basic_json<std::map, std::vector, std::string, bool, std::int64_t,
                                      std::uint64_t, long double>;

// Copies a wide document into a plain one. Numbers beyond double's range become ±infinity,
// which the typed readers (Cursor::number) report with their JSON path, like any other
// non-finite number, instead of failing the whole file.
nlohmann::json narrow(const WideJson& w) {
  switch (w.type()) {
    case WideJson::value_t::object: {
      nlohmann::json out = nlohmann::json::object();
      for (const auto& [key, value] : w.items()) out[key] = narrow(value);
      return out;
    }
    case WideJson::value_t::array: {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& value : w) out.push_back(narrow(value));
      return out;
    }
    case WideJson::value_t::number_float: return static_cast<double>(w.get<long double>());
    case WideJson::value_t::number_integer: return w.get<std::int64_t>();
    case WideJson::value_t::number_unsigned: return w.get<std::uint64_t>();
    case WideJson::value_t::string: return w.get<std::string>();
    case WideJson::value_t::boolean: return w.get<bool>();
    default: return nullptr;
  }
}

}  // namespace

std::shared_ptr<const SourceFile> parse_json_text(std::string name, std::string text,
                                                  const JsonLimits& limits) {
  if (text.size() > limits.max_bytes) {
    fail(name,
         fmt::format("file is {} bytes, over the limit of {} bytes", text.size(), limits.max_bytes),
         0, 0, "limit");
  }
  prescan(name, text, limits);
  auto file = std::make_shared<SourceFile>();
  file->name = std::move(name);
  file->text = std::move(text);
  try {
    file->root = nlohmann::json::parse(file->text);
  } catch (const nlohmann::json::parse_error& e) {
    auto [line, column] = line_column_of(file->text, e.byte > 0 ? e.byte - 1 : 0);
    std::string what = e.what();
    // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line ..:";
    // keep the part after the last ": " that names the fault.
    auto pos = what.find("syntax error");
    if (pos == std::string::npos) pos = what.find("parse error");
    fail(file->name, "invalid JSON: " + what.substr(pos == std::string::npos ? 0 : pos), line,
         column);
  } catch (const nlohmann::json::out_of_range&) {
    // A number too large for a double (406): parse again with long doubles.
    try {
      file->root = narrow(WideJson::parse(file->text));
    } catch (const WideJson::exception& e) {
      fail(file->name, fmt::format("invalid JSON: {}", e.what()), 0, 0, "range");
    }
  }
  return file;
}

std::shared_ptr<const SourceFile> load_json_file(const std::string& path,
                                                 const JsonLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the file", 0, 0, "unreadable");
  in.seekg(0, std::ios::end);
  auto size = in.tellg();
  if (size < 0) fail(path, "cannot read the file", 0, 0, "unreadable");
  if (static_cast<std::size_t>(size) > limits.max_bytes) {
    fail(path,
         fmt::format("file is {} bytes, over the limit of {} bytes", static_cast<std::size_t>(size),
                     limits.max_bytes),
         0, 0, "limit");
  }
  in.seekg(0);
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), size);
  if (!in) fail(path, "cannot read the file", 0, 0, "unreadable");
  return parse_json_text(path, std::move(text), limits);
}

namespace {

// A minimal scanner over JSON text that walks to the value at a pointer.
class Locator {
 public:
  explicit Locator(std::string_view text) : text_(text) {}

  // Returns the offset of the value at the tokens, or npos.
  std::size_t find(const std::vector<std::string>& tokens) {
    skip_ws();
    for (const auto& token : tokens) {
      if (pos_ >= text_.size()) return std::string_view::npos;
      if (text_[pos_] == '{') {
        if (!enter_object_member(token)) return std::string_view::npos;
      } else if (text_[pos_] == '[') {
        if (!enter_array_element(token)) return std::string_view::npos;
      } else {
        return std::string_view::npos;
      }
    }
    return pos_;
  }

 private:
  void skip_ws() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' ||
                                   text_[pos_] == '\r' || text_[pos_] == '\t')) {
      ++pos_;
    }
  }
  std::string read_string() {  // at '"'; returns the raw (unescaped-enough) contents
    std::string out;
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) {
        out += text_[pos_ + 1];
        pos_ += 2;
      } else {
        out += text_[pos_++];
      }
    }
    ++pos_;
    return out;
  }
  void skip_value() {
    skip_ws();
    if (pos_ >= text_.size()) return;
    char c = text_[pos_];
    if (c == '"') {
      read_string();
    } else if (c == '{' || c == '[') {
      int depth = 0;
      while (pos_ < text_.size()) {
        char d = text_[pos_];
        if (d == '"') {
          read_string();
          continue;
        }
        if (d == '{' || d == '[') ++depth;
        if (d == '}' || d == ']') {
          if (--depth == 0) {
            ++pos_;
            return;
          }
        }
        ++pos_;
      }
    } else {
      while (pos_ < text_.size() && text_[pos_] != ',' && text_[pos_] != '}' &&
             text_[pos_] != ']') {
        ++pos_;
      }
    }
    skip_ws();
  }
  bool enter_object_member(const std::string& key) {
    ++pos_;
    while (true) {
      skip_ws();
      if (pos_ >= text_.size() || text_[pos_] != '"') return false;
      std::string k = read_string();
      skip_ws();
      if (pos_ >= text_.size() || text_[pos_] != ':') return false;
      ++pos_;
      skip_ws();
      if (k == key) return true;
      skip_value();
      if (pos_ >= text_.size() || text_[pos_] != ',') return false;
      ++pos_;
    }
  }
  bool enter_array_element(const std::string& index_text) {
    std::size_t index = 0;
    for (char c : index_text) {
      if (c < '0' || c > '9') return false;
      index = index * 10 + static_cast<std::size_t>(c - '0');
    }
    ++pos_;
    skip_ws();
    for (std::size_t i = 0; i < index; ++i) {
      skip_value();
      if (pos_ >= text_.size() || text_[pos_] != ',') return false;
      ++pos_;
      skip_ws();
    }
    return pos_ < text_.size() && text_[pos_] != ']';
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

std::pair<int, int> locate(std::string_view text, std::string_view path) {
  std::vector<std::string> tokens;
  if (!path.empty()) {
    std::size_t start = 1;
    while (start <= path.size()) {
      auto end = path.find('/', start);
      if (end == std::string_view::npos) end = path.size();
      std::string token(path.substr(start, end - start));
      // JSON pointer escapes: ~1 is '/', ~0 is '~'.
      for (std::size_t p; (p = token.find("~1")) != std::string::npos;) token.replace(p, 2, "/");
      for (std::size_t p; (p = token.find("~0")) != std::string::npos;) token.replace(p, 2, "~");
      tokens.push_back(std::move(token));
      start = end + 1;
    }
  }
  Locator loc(text);
  auto offset = loc.find(tokens);
  if (offset == std::string_view::npos) return {0, 0};
  return line_column_of(text, offset);
}

}  // namespace raygrade
