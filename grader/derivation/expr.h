// E: a small expression tree for the formulas of derivation steps. The same tree is
// evaluated (to get the step's value), rendered as LaTeX, MathML and plain text, and
// rendered again with the numbers substituted for the symbols.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "derivation/number_format.h"
#include "derivation/value.h"

namespace raygrade {

enum class Op {
  kNumber,  // a constant
  kVector,  // a constant vector
  kSymbol,  // a named quantity
  kAdd,
  kSub,
  kMul,  // scalar product, or scalar times vector
  kDiv,  // shown as a fraction
  kDot,
  kCross,
  kNeg,
  kSqrt,
  kSquare,  // x²
  kAbs,     // |x| of a scalar
  kNorm,    // ‖v‖ of a vector
  kMin,
  kMax,
  kCompare,  // a relation shown as "a < b", "a ≥ b"; evaluates to a verdict
};

struct ExprNode;

class E {
 public:
  E() = default;
  E(double v);  // NOLINT: numbers in formulas read naturally
  E(int v);     // NOLINT
  explicit E(std::shared_ptr<const ExprNode> n) : node_(std::move(n)) {}

  const ExprNode& node() const { return *node_; }
  bool empty() const { return !node_; }

 private:
  std::shared_ptr<const ExprNode> node_;
};

struct ExprNode {
  Op op = Op::kNumber;
  double number = 0;
  Vec3d vector{};
  // For symbols: `name` is the key in the environment (the step name students use, "t_ca");
  // `base`, `sub` and `sup` are how it is shown (t with subscript "ca"; d with superscript 2).
  std::string name, base, sub, sup;
  std::string relation;  // for kCompare: "<", "<=", ">", ">=", "=", "!="
  std::vector<E> args;
};

// A symbol. `display` is "t_ca" (subscript), "d^2" (superscript), or plain "L".
E sym(std::string name, std::string display = "");
E vec(const Vec3d& v);
E operator+(const E& a, const E& b);
E operator-(const E& a, const E& b);
E operator*(const E& a, const E& b);
E operator/(const E& a, const E& b);
E operator-(const E& a);
E dot(const E& a, const E& b);
E cross(const E& a, const E& b);
E sqrt(const E& a);
E square(const E& a);
E abs(const E& a);
E norm(const E& a);
E min(std::vector<E> args);
E max(std::vector<E> args);
E compare(const E& a, std::string relation, const E& b);

// Values of symbols by name.
using Env = std::map<std::string, Value, std::less<>>;

// Evaluates a formula; symbols come from `env`. Throws Error on a type mismatch or an unknown
// symbol (a defect in the derivation code, never in user input).
Value evaluate(const E& e, const Env& env);

// How to show a symbol: as itself, or (when substituting) as its value.
struct RenderOptions {
  const Env* substitute = nullptr;  // when set, symbols with values print as numbers
  NumberFormat numbers;
};

std::string to_latex(const E& e, const RenderOptions& o = {});
std::string to_mathml(const E& e, const RenderOptions& o = {});  // the inner MathML, no <math>
std::string to_text(const E& e, const RenderOptions& o = {});

// A symbol shown alone (for the left side of "t_ca = ...").
inline std::string symbol_latex(const E& s) { return to_latex(s); }

}  // namespace raygrade
