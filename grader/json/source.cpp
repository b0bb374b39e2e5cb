// Reading JSON files with limits, and mapping JSON pointers back to lines and columns.
#include "json/source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "core/escape.h"
#include "json/scan.h"

namespace raygrade {
namespace {

[[noreturn]] void fail(const std::string& file, std::string msg, int line = 0, int column = 0,
                       std::string code = "bad-json") {
  throw Error(
      Diagnostic{file, "", line, column, Severity::kError, std::move(msg), std::move(code)});
}

// nlohmann's parse error as a sentence without its prefix ("[json.exception.parse_error.101]
// parse error at line 1, column 2:") and with the text it quotes made printable: the quoted
// bytes may be the very ill-formed UTF-8 or control characters that made the parse fail.
std::string parse_error_message(std::string_view text, std::size_t offset,
                                const std::string& what) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return "the file is empty: expected a JSON object";
  }
  // The word the lexer stopped in ("nan" fails at the 'a', reading for "null").
  auto is_word = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '-'; };
  std::size_t begin = std::min(offset, text.size()), end = begin;
  while (begin > 0 && is_word(text[begin - 1])) --begin;
  while (end < text.size() && is_word(text[end])) ++end;
  std::string word(text.substr(begin, end - begin));
  std::string lower;
  for (char c : word) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (std::string_view w : {"nan", "-nan", "infinity", "-infinity", "inf", "-inf"}) {
    if (lower == w) {
      return fmt::format("invalid JSON: '{}' is not a number (JSON has no NaN or infinity)", word);
    }
  }
  // The lexer stops at the first ill-formed byte or at the opening quote of the string.
  if (what.find("ill-formed UTF-8") != std::string::npos) {
    return "invalid UTF-8 in a string: save the file as UTF-8";
  }
  if (what.find("control character") != std::string::npos) {
    return "invalid string: a control character must be written as an escape (\\n, \\t, "
           "\\u0000)";
  }
  std::string_view message = what;
  auto pos = message.find("syntax error");
  if (pos == std::string_view::npos) pos = message.find("parse error");
  if (pos != std::string_view::npos) message = message.substr(pos);
  return "invalid JSON: " + printable(message, 200);
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
  if (text.size() >= 2 &&
      ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF'))) {
    fail(name, "the file is UTF-16: save it as UTF-8", 1, 1, "bad-encoding");
  }
  auto report = [&](const TextFault& f) {
    auto [line, column] = line_column_of(text, f.offset);
    throw Error(Diagnostic{name, f.path, line, column, Severity::kError, f.message, f.code});
  };
  if (auto fault = check_limits(text, limits)) report(*fault);
  // nlohmann stops at a NUL byte as if the text ended there, so "{...}\0anything" would pass.
  // JSON has no raw NUL anywhere (inside a string it is written \u0000).
  if (auto nul = text.find('\0'); nul != std::string::npos) {
    auto [line, column] = line_column_of(text, nul);
    fail(name, "invalid JSON: a NUL byte (is this a text file?)", line, column);
  }
  auto file = std::make_shared<SourceFile>();
  try {
    try {
      file->root = nlohmann::json::parse(text);
    } catch (const nlohmann::json::out_of_range&) {
      // A number too large for a double (406): parse again with long doubles. This parse
      // goes on past the number, so it may yet meet a syntax error.
      file->root = narrow(WideJson::parse(text));
    }
  } catch (const nlohmann::json::parse_error& e) {
    std::size_t offset = e.byte > 0 ? std::min<std::size_t>(e.byte - 1, text.size()) : 0;
    auto [line, column] = line_column_of(text, offset);
    std::string_view what = e.what();
    // Ill-formed UTF-8, and a \u escape naming half a surrogate pair (no character at all).
    bool encoding = e.id == 101 && (what.find("UTF-8") != std::string_view::npos ||
                                    what.find("surrogate") != std::string_view::npos);
    std::string code = encoding ? "bad-encoding" : "bad-json";
    fail(name, parse_error_message(text, offset, e.what()), line, column, code);
  } catch (const nlohmann::json::out_of_range&) {
    // Beyond even a long double (1e5000): the error has no position, so find the number.
    if (auto fault = find_duplicate_or_overflow(text)) report(*fault);
    fail(name, "a number is out of range", 0, 0, "range");
  }
  if (auto fault = find_duplicate_or_overflow(text)) report(*fault);
  file->name = std::move(name);
  file->text = std::move(text);
  return file;
}

std::shared_ptr<const SourceFile> load_json_file(const std::string& path,
                                                 const JsonLimits& limits) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever. Only a
  // regular file is read; fstat on the open descriptor, so the file cannot be swapped between
  // the check and the read.
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC |
                                    (limits.no_follow ? O_NOFOLLOW : 0));
  if (fd < 0 && errno == ELOOP && limits.no_follow) {
    fail(path, "not read: the file became a symbolic link after the submissions were listed", 0, 0,
         "unreadable");
  }
  if (fd < 0) {
    fail(path, fmt::format("cannot open the file: {}", std::strerror(errno)), 0, 0, "unreadable");
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    fail(path, fmt::format("cannot read the file: {}", std::strerror(errno)), 0, 0, "unreadable");
  }
  if (!S_ISREG(st.st_mode)) fail(path, "not a regular file", 0, 0, "unreadable");
  if (limits.expected && *limits.expected != FileIdentity{static_cast<std::uint64_t>(st.st_dev),
                                                          static_cast<std::uint64_t>(st.st_ino)}) {
    fail(path,
         "not read: this is not the file the submissions were listed with (a folder on its path "
         "was replaced after the listing, by a symbolic link say)",
         0, 0, "unreadable");
  }
  auto size = static_cast<std::size_t>(st.st_size);
  if (size > limits.max_bytes) {
    fail(path, fmt::format("file is {} bytes, over the limit of {} bytes", size, limits.max_bytes),
         0, 0, "limit");
  }
  std::string text(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    ssize_t n = ::read(fd, text.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      fail(path, fmt::format("cannot read the file: {}", std::strerror(errno)), 0, 0, "unreadable");
    }
    if (n == 0) break;  // the file shrank while it was read
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return parse_json_text(path, std::move(text), limits);
}

namespace {

// A minimal scanner over JSON text that walks to the value at a pointer.
class Locator {
 public:
  // `elements`, when given, keeps the offsets of the elements of every array walked, by the
  // offset of its '[', so that a second walk through the same array jumps to its element.
  explicit Locator(std::string_view text,
                   std::unordered_map<std::size_t, std::vector<std::size_t>>* elements = nullptr)
      : text_(text), elements_(elements) {}

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
  // At '"': the string's contents, escapes decoded ("\u0074" is "t"), so that a key spelled
  // with escapes is found under the name a JSON pointer gives it.
  std::string read_string() {
    std::size_t start = pos_++;
    bool escaped = false;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      if (text_[pos_] == '\\') {
        escaped = true;
        ++pos_;
      }
      ++pos_;
    }
    ++pos_;
    std::string_view raw = text_.substr(start, std::min(pos_, text_.size()) - start);
    if (!escaped) return std::string(raw.substr(1, raw.size() >= 2 ? raw.size() - 2 : 0));
    auto decoded = nlohmann::json::parse(raw, nullptr, false);
    return decoded.is_string() ? decoded.get<std::string>() : std::string();
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
      if (c < '0' || c > '9' || index > text_.size()) return false;
      index = index * 10 + static_cast<std::size_t>(c - '0');
    }
    if (elements_) {
      auto [it, fresh] = elements_->try_emplace(pos_);
      if (fresh) it->second = element_offsets();
      if (index >= it->second.size()) return false;
      pos_ = it->second[index];
      return true;
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
  // At '[': where each element of the array starts.
  std::vector<std::size_t> element_offsets() {
    std::vector<std::size_t> out;
    ++pos_;
    skip_ws();
    while (pos_ < text_.size() && text_[pos_] != ']') {
      out.push_back(pos_);
      skip_value();
      if (pos_ >= text_.size() || text_[pos_] != ',') break;
      ++pos_;
      skip_ws();
    }
    return out;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::unordered_map<std::size_t, std::vector<std::size_t>>* elements_;
};

// The tokens of a JSON pointer ("/a~1b/0" is "a/b", "0").
std::vector<std::string> pointer_tokens(std::string_view path) {
  std::vector<std::string> tokens;
  if (path.empty()) return tokens;
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
  return tokens;
}

}  // namespace

std::pair<int, int> locate(std::string_view text, std::string_view path) {
  Locator loc(text);
  auto offset = loc.find(pointer_tokens(path));
  if (offset == std::string_view::npos) return {0, 0};
  return line_column_of(text, offset);
}

struct LocateIndex {
  std::vector<std::size_t> line_starts;  // empty until the first call
  std::unordered_map<std::size_t, std::vector<std::size_t>> elements;
};

std::pair<int, int> SourceFile::locate(std::string_view path) const {
  std::lock_guard lock(index_mutex_);
  if (!index_) index_ = std::make_shared<LocateIndex>();
  Locator loc(text, &index_->elements);
  auto offset = loc.find(pointer_tokens(path));
  if (offset == std::string_view::npos) return {0, 0};
  auto& starts = index_->line_starts;
  if (starts.empty()) {
    starts.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') starts.push_back(i + 1);
    }
  }
  auto line = std::upper_bound(starts.begin(), starts.end(), offset) - starts.begin();
  return {static_cast<int>(line), static_cast<int>(offset - starts[line - 1]) + 1};
}

}  // namespace raygrade
