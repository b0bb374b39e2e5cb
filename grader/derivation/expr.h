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

#include "core/internal_error.h"
#include "derivation/number_format.h"
#include "derivation/value.h"

namespace raygrade {

enum class Op {
  kNumber,  // a constant
  kVector,  // a constant vector
  kSymbol,  // a named quantity
  kAdd,
  kSub,
  kMul,  // scalar product, or scalar times vector (a verdict as a factor is 1 or 0)
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
  kCompare,        // a relation shown as "a < b", "a ≥ b"; evaluates to a verdict
  kTuple,          // a vector from three scalar formulas: ⟨a, b, c⟩
  kArccosDegrees,  // arccos(x) in degrees, x clamped to [−1, 1] (rounding may push it past)
  kArcsinDegrees,  // arcsin(x) in degrees, x clamped to [−1, 1]
  kCos,            // cos(x), x in radians
  kSin,            // sin(x), x in radians
  kRadians,        // an angle in degrees in radians, x·π/180: one conversion, shown so
  kTan,            // tan(x), x in radians
  kPow,            // a^b of scalars (a Phong exponent)
  kHadamard,       // a ⊙ b: two vectors (colours) multiplied component by component
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
  // kMul: shown without a sign (2√3). kCross: with numbers substituted, written out by
  // components (⟨a_y b_z − a_z b_y, …⟩) before the result.
  bool implicit = false;
  bool written_out = false;
  // kSymbol: args[0], when present, is how the symbol is shown (N · R rather than a letter).
  std::vector<E> args;
};

// A symbol. `display` is "t_ca" (subscript), "d^2" (superscript), or plain "L".
E sym(std::string name, std::string display = "");
// A symbol shown as a formula: the step "denominator" shown as N · R.
E sym(std::string name, const E& shown);
E vec(const Vec3d& v);
E operator+(const E& a, const E& b);
E operator-(const E& a, const E& b);
E operator*(const E& a, const E& b);
E operator/(const E& a, const E& b);
E operator-(const E& a);
E dot(const E& a, const E& b);
E cross(const E& a, const E& b);
// a × b, written out by components when its numbers are substituted.
E cross_written_out(const E& a, const E& b);
E tuple(const E& x, const E& y, const E& z);
E sqrt(const E& a);
// The angle whose cosine is `a`, in degrees: arccos(a).
E arccos_degrees(const E& a);
// The angle whose sine is `a`, in degrees: arcsin(a).
E arcsin_degrees(const E& a);
// The cosine, sine and tangent of an angle in radians.
E cos(const E& a);
E sin(const E& a);
E tan(const E& a);
// a raised to the power b.
E pow(const E& a, const E& b);
// a ⊙ b: the componentwise product of two colours.
E hadamard(const E& a, const E& b);
// The number π, shown as π (an angle in degrees times π/180 is the same angle in radians).
E pi();
// An angle in degrees in radians: a·π/180, as one operation (kRadians).
E radians(const E& a);
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
// A formula evaluated with values it cannot take: a vector where a number goes, a symbol with
// no value. In raygrade's own derivations that is a bug of raygrade (an InternalError: exit 3,
// and a batch sets the one submission aside); only the readings that rewrite a formula (a named
// mistake) or substitute a student's own values catch it, as "this reading does not apply".
class EvaluationFault : public InternalError {
 public:
  using InternalError::InternalError;
};

// Throws EvaluationFault on a formula its values do not fit.
Value evaluate(const E& e, const Env& env);

// How to show a symbol: as itself, or (when substituting) as its value.
struct RenderOptions {
  const Env* substitute = nullptr;  // when set, symbols with values print as numbers
  NumberFormat numbers;
  // Values (not formulas) with an exact form print as "9 − √3 ≈ 7.268".
  bool exact = false;
};

std::string to_latex(const E& e, const RenderOptions& o = {});
std::string to_mathml(const E& e, const RenderOptions& o = {});  // the inner MathML, no <math>
std::string to_text(const E& e, const RenderOptions& o = {});

// A value (the result of a step), with its exact form when `o.exact` is set.
std::string value_latex(const Value& v, const RenderOptions& o = {});
std::string value_mathml(const Value& v, const RenderOptions& o = {});
std::string value_text(const Value& v, const RenderOptions& o = {});

// A symbol shown alone (for the left side of "t_ca = ...").
inline std::string symbol_latex(const E& s) { return to_latex(s); }

}  // namespace raygrade
