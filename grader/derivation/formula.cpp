// The typed-formula parser: recursive descent with a depth limit, emitting a postfix program.
#include "derivation/formula.h"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

#include "json/cursor.h"

namespace raygrade {

using FOp = Formula::Op;

void SymbolTable::add(const std::string& name, const std::vector<std::string>& aliases) {
  int slot = static_cast<int>(names_.size());
  names_.push_back(name);
  slots_[name] = slot;
  for (const auto& a : aliases) slots_.emplace(a, slot);
}

int SymbolTable::find(std::string_view name) const {
  auto it = slots_.find(name);
  return it == slots_.end() ? -1 : it->second;
}

double Formula::evaluate(const std::vector<double>& values) const {
  constexpr int kInline = 32;
  double inline_stack[kInline];
  std::vector<double> heap;
  double* s = inline_stack;
  if (stack_size > kInline) {
    heap.resize(static_cast<std::size_t>(stack_size));
    s = heap.data();
  }
  int top = 0;  // number of values on the stack
  for (const auto& in : program) {
    switch (in.op) {
      case FOp::kNumber: s[top++] = in.number; break;
      case FOp::kSymbol:
        s[top++] = in.slot < static_cast<int>(values.size())
                       ? values[static_cast<std::size_t>(in.slot)]
                       : std::numeric_limits<double>::quiet_NaN();
        break;
      case FOp::kAdd:
        --top;
        s[top - 1] += s[top];
        break;
      case FOp::kSub:
        --top;
        s[top - 1] -= s[top];
        break;
      case FOp::kMul:
        --top;
        s[top - 1] *= s[top];
        break;
      case FOp::kDiv:
        --top;
        s[top - 1] /= s[top];
        break;
      case FOp::kPow:
        --top;
        s[top - 1] = std::pow(s[top - 1], s[top]);
        break;
      case FOp::kNeg: s[top - 1] = -s[top - 1]; break;
      case FOp::kSqrt: s[top - 1] = std::sqrt(s[top - 1]); break;
      case FOp::kAbs: s[top - 1] = std::abs(s[top - 1]); break;
      case FOp::kSin: s[top - 1] = std::sin(s[top - 1]); break;
      case FOp::kCos: s[top - 1] = std::cos(s[top - 1]); break;
      case FOp::kTan: s[top - 1] = std::tan(s[top - 1]); break;
      case FOp::kExp: s[top - 1] = std::exp(s[top - 1]); break;
      case FOp::kLog: s[top - 1] = std::log(s[top - 1]); break;
      case FOp::kAsin: s[top - 1] = std::asin(s[top - 1]); break;
      case FOp::kAcos: s[top - 1] = std::acos(s[top - 1]); break;
      case FOp::kAtan: s[top - 1] = std::atan(s[top - 1]); break;
      case FOp::kAtan2:
        --top;
        s[top - 1] = std::atan2(s[top - 1], s[top]);
        break;
    }
  }
  return top == 1 ? s[0] : std::numeric_limits<double>::quiet_NaN();
}

namespace {

// A decimal number as the whole of `text`, correctly rounded; false when it is not one or is
// beyond the doubles (to ±∞ or to 0). strtod in the C locale, not std::from_chars, whose
// floating-point overloads Emscripten's libc++ lacks.
bool read_double(std::string_view text, double& v) {
  std::string copy(text);
  char* end = nullptr;
  errno = 0;
  v = std::strtod(copy.c_str(), &end);
  if (copy.empty() || end != copy.c_str() + copy.size()) return false;
  return !(errno == ERANGE && (std::isinf(v) || v == 0));
}

// Characters beyond ASCII that students paste from worked solutions and slides.
struct Glyph {
  std::string_view utf8;
  char ascii;  // '*', '-', '/', '2' (for ²), '3' (for ³), 'r' (for √), 'p' (for π)
};
constexpr Glyph kGlyphs[] = {{"\u2212", '-'}, {"\u00b7", '*'}, {"\u22c5", '*'},
                             {"\u00d7", '*'}, {"\u00f7", '/'}, {"\u00b2", '2'},
                             {"\u00b3", '3'}, {"\u221a", 'r'}, {"\u03c0", 'p'}};

struct Function {
  std::string_view name;
  FOp op;
};
constexpr Function kFunctions[] = {
    {"sqrt", FOp::kSqrt}, {"abs", FOp::kAbs},   {"sin", FOp::kSin},   {"cos", FOp::kCos},
    {"tan", FOp::kTan},   {"exp", FOp::kExp},   {"ln", FOp::kLog},    {"log", FOp::kLog},
    {"asin", FOp::kAsin}, {"acos", FOp::kAcos}, {"atan", FOp::kAtan}, {"atan2", FOp::kAtan2}};

// Degrees: "30deg", "30 deg" or "30°" is 30·π/180 (the trigonometric functions take radians).
constexpr std::string_view kDegreeSign = "\u00b0";
constexpr double kRadiansPerDegree = std::numbers::pi / 180;

class Parser {
 public:
  Parser(std::string_view text, const SymbolTable* symbols) : text_(text), symbols_(symbols) {}

  FormulaParse run() {
    FormulaParse out;
    if (text_.size() > kMaxFormulaLength) {
      fail(kMaxFormulaLength,
           fmt::format("the answer is too long (more than {} characters)", kMaxFormulaLength));
      out.over_limit = true;
    } else if (std::size_t at = first_control(); at != std::string_view::npos) {
      // Controls are never part of a formula (and U+0001 to U+0004 are the parser's own
      // markers for the glyphs √, ², ³ and π, which typed raw must not read as those glyphs).
      fail(at, fmt::format("a control character (U+{:04X}) is not part of a formula",
                           static_cast<unsigned char>(text_[at])));
    } else {
      skip_space();
      if (pos_ == text_.size()) {
        fail(pos_, "the answer is empty");
      } else {
        expression(0);
        skip_space();
        if (!failed_ && pos_ < text_.size()) {
          fail(pos_, fmt::format("unexpected '{}'", current_glyph()));
        }
      }
    }
    if (failed_) {
      out.over_limit = out.over_limit || too_deep_;
      out.column = column_of(error_at_);
      out.message = fmt::format("{} at character {}", error_, out.column);
      return out;
    }
    out.ok = true;
    out.formula = std::move(f_);
    out.digits = typed_digits(text_);
    return out;
  }

 private:
  // --- characters
  // The first C0 control (a tab apart) or DEL, or npos.
  std::size_t first_control() const {
    for (std::size_t i = 0; i < text_.size(); ++i) {
      unsigned char c = static_cast<unsigned char>(text_[i]);
      if ((c < 0x20 && c != '\t') || c == 0x7F) return i;
    }
    return std::string_view::npos;
  }
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  // The next character, with the pasted glyphs mapped to ASCII (0 at the end).
  char peek(std::size_t* width = nullptr) const {
    if (pos_ >= text_.size()) return 0;
    for (const auto& g : kGlyphs) {
      if (text_.substr(pos_, g.utf8.size()) == g.utf8) {
        if (width) *width = g.utf8.size();
        // ², ³, √ and π are told apart from the ASCII characters by a leading marker.
        return g.ascii == '2'   ? '\x02'
               : g.ascii == '3' ? '\x03'
               : g.ascii == 'r' ? '\x01'
               : g.ascii == 'p' ? '\x04'
                                : g.ascii;
      }
    }
    if (width) *width = 1;
    return text_[pos_];
  }
  void advance() {
    std::size_t w = 1;
    peek(&w);
    pos_ += w;
  }
  std::string current_glyph() const {
    if (pos_ >= text_.size()) return "end";
    std::size_t w = 1;
    unsigned char c = static_cast<unsigned char>(text_[pos_]);
    if (c >= 0xF0)
      w = 4;
    else if (c >= 0xE0)
      w = 3;
    else if (c >= 0xC0)
      w = 2;
    return std::string(text_.substr(pos_, w));
  }
  std::size_t column_of(std::size_t byte) const {
    std::size_t col = 1;
    for (std::size_t i = 0; i < byte && i < text_.size(); ++i) {
      if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++col;
    }
    return col;
  }
  void fail(std::size_t at, std::string message) {
    if (failed_) return;
    failed_ = true;
    error_at_ = at;
    error_ = std::move(message);
  }

  // --- emitting
  void emit(FOp op, double number = 0, int slot = 0) {
    f_.program.push_back({op, slot, number});
    if (op == FOp::kNumber || op == FOp::kSymbol) {
      f_.stack_size = std::max(f_.stack_size, ++depth_of_stack_);
    } else if (op == FOp::kAdd || op == FOp::kSub || op == FOp::kMul || op == FOp::kDiv ||
               op == FOp::kPow || op == FOp::kAtan2) {
      --depth_of_stack_;
    }
  }

  bool enter(int depth) {
    if (depth > kMaxFormulaDepth) {
      if (!failed_) too_deep_ = true;
      fail(pos_,
           fmt::format("the answer nests more than {} parentheses deep", kMaxFormulaParentheses));
      return false;
    }
    return !failed_;
  }

  // --- grammar
  void expression(int depth) {
    if (!enter(depth)) return;
    term(depth);
    for (;;) {
      skip_space();
      char c = peek();
      if (failed_ || (c != '+' && c != '-')) return;
      advance();
      term(depth);
      emit(c == '+' ? FOp::kAdd : FOp::kSub);
    }
  }

  bool starts_primary(char c) const {
    return c == '(' || c == '\x01' || c == '\x04' || std::isalpha(static_cast<unsigned char>(c)) ||
           c == '_';
  }

  void term(int depth) {
    unary(depth);
    for (;;) {
      skip_space();
      char c = peek();
      if (failed_) return;
      if (c == '*' || c == '/') {
        advance();
        unary(depth);
        emit(c == '*' ? FOp::kMul : FOp::kDiv);
      } else if (starts_primary(c)) {  // implicit product: 2sqrt(3), 2(px + 1), 2 px
        unary(depth);
        emit(FOp::kMul);
      } else {
        return;
      }
    }
  }

  void unary(int depth) {
    if (!enter(depth + 1)) return;
    skip_space();
    char c = peek();
    if (c == '-' || c == '+') {
      advance();
      unary(depth + 1);
      if (c == '-') emit(FOp::kNeg);
      return;
    }
    power(depth + 1);
  }

  void power(int depth) {
    postfix(depth);
    skip_space();
    if (failed_) return;
    bool caret = peek() == '^', stars = text_.substr(pos_, 2) == "**";
    if (caret || stars) {
      pos_ += caret ? 1 : 2;
      unary(depth + 1);  // right-associative; 2^-1 is allowed
      emit(FOp::kPow);
    }
  }

  // "deg" or "°" after a value, with optional spaces between; true when one was read.
  bool degrees() {
    std::size_t at = pos_;
    while (at < text_.size() && (text_[at] == ' ' || text_[at] == '\t')) ++at;
    std::string_view rest = text_.substr(at);
    std::size_t width = 0;
    if (rest.starts_with(kDegreeSign)) {
      width = kDegreeSign.size();
    } else if (rest.starts_with("deg") &&
               (rest.size() == 3 ||
                !(std::isalnum(static_cast<unsigned char>(rest[3])) || rest[3] == '_'))) {
      width = 3;
    }
    if (width == 0) return false;
    pos_ = at + width;
    emit(FOp::kNumber, kRadiansPerDegree);
    emit(FOp::kMul);
    return true;
  }

  void postfix(int depth) {
    primary(depth);
    for (;;) {
      if (!failed_ && degrees()) continue;
      char c = peek();
      if (failed_ || (c != '\x02' && c != '\x03')) return;
      advance();
      emit(FOp::kNumber, c == '\x02' ? 2 : 3);
      emit(FOp::kPow);
    }
  }

  void primary(int depth) {
    if (!enter(depth + 1)) return;
    skip_space();
    char c = peek();
    std::size_t start = pos_;
    if (c == 0) {
      fail(pos_, "the answer ends too early");
    } else if (c == '(') {
      advance();
      expression(depth + 1);
      skip_space();
      close_parenthesis();
    } else if (c == '\x01') {  // √x or √(x)
      advance();
      postfix(depth + 1);
      emit(FOp::kSqrt);
    } else if (c == '\x04') {
      advance();
      emit(FOp::kNumber, std::numbers::pi);
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      number();
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
        ++pos_;
      }
      identifier(text_.substr(start, pos_ - start), start, depth);
    } else {
      fail(pos_, fmt::format("unexpected '{}'", current_glyph()));
    }
  }

  void number() {
    std::size_t start = pos_;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t e = pos_ + 1;
      if (e < text_.size() && (text_[e] == '+' || text_[e] == '-')) ++e;
      if (e < text_.size() && std::isdigit(static_cast<unsigned char>(text_[e]))) {
        pos_ = e;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      }
    }
    double v = 0;
    if (!read_double(text_.substr(start, pos_ - start), v)) {
      fail(start, fmt::format("'{}' is not a number", text_.substr(start, pos_ - start)));
      return;
    }
    if (pos_ < text_.size() && text_[pos_] == '.') {
      fail(pos_, "a second decimal point");
      return;
    }
    emit(FOp::kNumber, v);
  }

  // f(a, b): the two operands, then the operation.
  void two_arguments(int depth, FOp op) {
    advance();  // '('
    expression(depth + 1);
    skip_space();
    if (failed_) return;
    if (peek() != ',') {
      fail(pos_,
           fmt::format("expected ',' between the two arguments, found '{}'", current_glyph()));
      return;
    }
    advance();
    expression(depth + 1);
    skip_space();
    if (close_parenthesis()) emit(op);
  }

  // The ')' that closes a group or a function's arguments; false (and a fault) without it.
  bool close_parenthesis() {
    if (failed_) return false;
    if (peek() != ')') {
      fail(pos_, pos_ >= text_.size()
                     ? "missing ')'"
                     : fmt::format("expected ')' but found '{}'", current_glyph()));
      return false;
    }
    advance();
    return true;
  }

  void identifier(std::string_view name, std::size_t start, int depth) {
    skip_space();
    for (const auto& fn : kFunctions) {
      if (fn.name != name) continue;
      if (peek() != '(') {
        fail(pos_, fmt::format("expected '(' after {}", name));
        return;
      }
      if (fn.op == FOp::kAtan2) return two_arguments(depth + 1, fn.op);
      primary(depth + 1);
      emit(fn.op);
      return;
    }
    if (name == "pi") {
      emit(FOp::kNumber, std::numbers::pi);
      return;
    }
    int slot = symbols_ ? symbols_->find(name) : -1;
    if (slot >= 0) {
      f_.uses_symbols = true;
      emit(FOp::kSymbol, 0, slot);
      return;
    }
    std::vector<std::string> known;
    if (symbols_) known = symbols_->names();
    for (const auto& fn : kFunctions) known.emplace_back(fn.name);
    std::string hint = closest_match(name, known);
    if (!symbols_) {
      fail(start, fmt::format("unknown name '{}' (a number is expected{})", name,
                              hint.empty() ? "" : fmt::format("; did you mean '{}'?", hint)));
    } else {
      fail(start, fmt::format("unknown symbol '{}' ({}known: {})", name,
                              hint.empty() ? "" : fmt::format("did you mean '{}'? ", hint),
                              fmt::join(symbols_->names(), ", ")));
    }
  }

  std::string_view text_;
  const SymbolTable* symbols_;
  std::size_t pos_ = 0;
  Formula f_;
  int depth_of_stack_ = 0;
  bool failed_ = false;
  bool too_deep_ = false;  // the fault is the depth limit
  std::size_t error_at_ = 0;
  std::string error_;
};

}  // namespace

FormulaParse parse_formula(std::string_view text, const SymbolTable* symbols) {
  return Parser(text, symbols).run();
}

std::vector<std::string> formula_function_names() {
  std::vector<std::string> out;
  for (const auto& f : kFunctions) out.emplace_back(f.name);
  return out;
}

TypedDigits typed_digits(std::string_view text) {
  TypedDigits d;
  std::size_t i = 0, n = text.size();
  while (i < n && text[i] == ' ') ++i;
  while (n > i && text[n - 1] == ' ') --n;
  if (i < n && (text[i] == '-' || text[i] == '+')) ++i;
  int before = 0, after = 0, leading_zeros = 0, exponent = 0;
  bool seen_nonzero = false, point = false;
  for (; i < n; ++i) {
    char c = text[i];
    if (c == '.' && !point) {
      point = true;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      (point ? after : before)++;
      if (c != '0') seen_nonzero = true;
      if (!seen_nonzero) ++leading_zeros;
    } else {
      break;
    }
  }
  if (before + after == 0) return d;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    auto [end, ec] = std::from_chars(text.data() + i + 1 + (i + 1 < n && text[i + 1] == '+'),
                                     text.data() + n, exponent);
    if (ec != std::errc() || end != text.data() + n) return d;
    i = n;
  }
  if (i != n) return d;
  d.literal = true;
  d.decimals = after - exponent;
  d.significant = seen_nonzero ? before + after - leading_zeros : 0;
  return d;
}

}  // namespace raygrade
