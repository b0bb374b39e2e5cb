// Formula: what a student types for a number or a formula ("7.27", "1/3", "9 - sqrt(3)",
// "2*(px*vx + py*vy)"), parsed safely into a small program and evaluated.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace raygrade {

// Limits on typed input. A real answer is a few dozen characters and nests two or three deep.
constexpr std::size_t kMaxFormulaLength = 1000;  // characters (bytes of UTF-8)
// Nested parentheses (and functions) a typed number may have; the parser counts grammar levels,
// two per pair of parentheses (an expression inside a primary) and two for the outermost.
constexpr int kMaxFormulaParentheses = 20;
constexpr int kMaxFormulaDepth = 2 * kMaxFormulaParentheses + 2;

// Symbols a formula may use: each name (and its aliases) maps to a slot in the values.
class SymbolTable {
 public:
  // Adds a symbol; `aliases` are other spellings students use ("p_x" for "px").
  void add(const std::string& name, const std::vector<std::string>& aliases = {});
  int find(std::string_view name) const;  // -1 when unknown
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::vector<std::string> names_;
  std::map<std::string, int, std::less<>> slots_;
};

// A parsed formula: a postfix program over a small stack.
struct Formula {
  enum class Op : unsigned char {
    kNumber,
    kSymbol,
    kAdd,
    kSub,
    kMul,
    kDiv,
    kPow,
    kNeg,
    kSqrt,
    kAbs,
    kSin,
    kCos,
    kTan,
    kExp,
    kLog,
    kAsin,
    kAcos,
    kAtan,
    kAtan2,  // atan2(y, x): two operands
  };
  struct Instruction {
    Op op;
    int slot = 0;  // for kSymbol
    double number = 0;
  };
  std::vector<Instruction> program;
  int stack_size = 0;
  bool uses_symbols = false;

  // The value with `values[slot]` for each symbol. NaN for an undefined result.
  double evaluate(const std::vector<double>& values = {}) const;
};

// The digits a student typed, for significant-figure and decimal-place checks.
struct TypedDigits {
  bool literal = false;  // a plain decimal number ("7.27", "-0.50", "1.5e-3")
  int decimals = 0;      // digits after the point, corrected for an exponent
  int significant = 0;   // significant digits
};

struct FormulaParse {
  bool ok = false;
  Formula formula;
  TypedDigits digits;
  std::size_t column = 0;   // 1-based character where the fault is (when !ok)
  std::string message;      // the fault in words (when !ok)
  bool over_limit = false;  // the fault is a limit (kMaxFormulaLength or kMaxFormulaDepth)
};

// Parses `text`. Without `symbols`, only numbers, + − * / ^, parentheses, sqrt and the like,
// and pi are allowed. Never throws; faults are reported with the character they are at.
FormulaParse parse_formula(std::string_view text, const SymbolTable* symbols = nullptr);

// The functions a formula may call by name ("sqrt", "sin", ...), for pages that read typed
// numbers as the grader does.
std::vector<std::string> formula_function_names();

// The digits of a plain decimal literal as typed; `literal` is false for anything else.
TypedDigits typed_digits(std::string_view text);

}  // namespace raygrade
