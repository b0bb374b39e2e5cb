// Building, evaluating and rendering formula trees.
#include "derivation/expr.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "math/robust.h"

namespace raygrade {
namespace {

std::shared_ptr<ExprNode> make(Op op, std::vector<E> args = {}) {
  auto n = std::make_shared<ExprNode>();
  n->op = op;
  n->args = std::move(args);
  return n;
}

E wrap(std::shared_ptr<ExprNode> n) { return E(std::shared_ptr<const ExprNode>(std::move(n))); }

// Values a formula cannot take (expr.h, EvaluationFault).
[[noreturn]] void defect(const std::string& what) { throw EvaluationFault("derivation: " + what); }

}  // namespace

E::E(double v) {
  auto n = make(Op::kNumber);
  n->number = v;
  node_ = n;
}

E::E(int v) : E(static_cast<double>(v)) {}

E sym(std::string name, std::string display) {
  auto n = make(Op::kSymbol);
  if (display.empty()) display = name;
  auto sup = display.find('^');
  auto sub = display.find('_');
  std::size_t base_end = std::min(sup, sub);
  n->base = display.substr(0, base_end);
  if (sub != std::string::npos) {
    n->sub = display.substr(
        sub + 1, sup != std::string::npos && sup > sub ? sup - sub - 1 : std::string::npos);
  }
  if (sup != std::string::npos) {
    n->sup = display.substr(
        sup + 1, sub != std::string::npos && sub > sup ? sub - sup - 1 : std::string::npos);
  }
  n->name = std::move(name);
  return wrap(n);
}

E sym(std::string name, const E& shown) {
  auto n = make(Op::kSymbol, {shown});
  n->name = std::move(name);
  return wrap(n);
}

E vec(const Vec3d& v) {
  auto n = make(Op::kVector);
  n->vector = v;
  return wrap(n);
}

E operator+(const E& a, const E& b) { return wrap(make(Op::kAdd, {a, b})); }
E operator-(const E& a, const E& b) { return wrap(make(Op::kSub, {a, b})); }
E operator*(const E& a, const E& b) { return wrap(make(Op::kMul, {a, b})); }
E operator/(const E& a, const E& b) { return wrap(make(Op::kDiv, {a, b})); }
E operator-(const E& a) { return wrap(make(Op::kNeg, {a})); }
E dot(const E& a, const E& b) { return wrap(make(Op::kDot, {a, b})); }
E cross(const E& a, const E& b) { return wrap(make(Op::kCross, {a, b})); }
E cross_written_out(const E& a, const E& b) {
  auto n = make(Op::kCross, {a, b});
  n->written_out = true;
  return wrap(n);
}
E tuple(const E& x, const E& y, const E& z) { return wrap(make(Op::kTuple, {x, y, z})); }
E sqrt(const E& a) { return wrap(make(Op::kSqrt, {a})); }
E arccos_degrees(const E& a) { return wrap(make(Op::kArccosDegrees, {a})); }
E arcsin_degrees(const E& a) { return wrap(make(Op::kArcsinDegrees, {a})); }
E cos(const E& a) { return wrap(make(Op::kCos, {a})); }
E sin(const E& a) { return wrap(make(Op::kSin, {a})); }
E tan(const E& a) { return wrap(make(Op::kTan, {a})); }
E pow(const E& a, const E& b) { return wrap(make(Op::kPow, {a, b})); }
E hadamard(const E& a, const E& b) { return wrap(make(Op::kHadamard, {a, b})); }
E pi() {
  auto n = make(Op::kNumber);
  n->number = std::numbers::pi;
  n->base = "pi";
  return wrap(n);
}
E radians(const E& a) { return wrap(make(Op::kRadians, {a})); }
E square(const E& a) { return wrap(make(Op::kSquare, {a})); }
E abs(const E& a) { return wrap(make(Op::kAbs, {a})); }
E norm(const E& a) { return wrap(make(Op::kNorm, {a})); }
E min(std::vector<E> args) { return wrap(make(Op::kMin, std::move(args))); }
E max(std::vector<E> args) { return wrap(make(Op::kMax, std::move(args))); }
E compare(const E& a, std::string relation, const E& b) {
  auto n = make(Op::kCompare, {a, b});
  n->relation = std::move(relation);
  return wrap(n);
}

// --- Evaluation ---------------------------------------------------------------------------

Value evaluate(const E& e, const Env& env) {
  const ExprNode& n = e.node();
  auto arg = [&](std::size_t i) { return evaluate(n.args[i], env); };
  auto scalar = [&](const Value& v) {
    if (!v.is_scalar()) defect("expected a scalar");
    return v.scalar;
  };
  auto vector = [&](const Value& v) {
    if (!v.is_vector()) defect("expected a vector");
    return v.vector;
  };
  switch (n.op) {
    case Op::kNumber: return n.number;
    case Op::kVector: return n.vector;
    case Op::kSymbol: {
      auto it = env.find(n.name);
      if (it == env.end()) defect("unknown symbol '" + n.name + "'");
      return it->second;
    }
    case Op::kAdd:
    case Op::kSub: {
      Value a = arg(0), b = arg(1);
      double s = n.op == Op::kAdd ? 1 : -1;
      if (a.is_vector()) return a.vector + s * vector(b);
      return scalar(a) + s * scalar(b);
    }
    case Op::kMul: {
      Value a = arg(0), b = arg(1);
      // A verdict as a factor counts as 1 or 0 (Iverson's bracket).
      if (a.is_bool()) a = Value(a.truth ? 1.0 : 0.0);
      if (b.is_bool()) b = Value(b.truth ? 1.0 : 0.0);
      if (a.is_vector()) return a.vector * scalar(b);
      if (b.is_vector()) return scalar(a) * b.vector;
      return scalar(a) * scalar(b);
    }
    case Op::kDiv: {
      Value a = arg(0), b = arg(1);
      if (a.is_vector()) return a.vector / scalar(b);
      return scalar(a) / scalar(b);
    }
    case Op::kDot: return dot(vector(arg(0)), vector(arg(1)));
    case Op::kCross: return cross(vector(arg(0)), vector(arg(1)));
    case Op::kNeg: {
      Value a = arg(0);
      if (a.is_vector()) return -a.vector;
      return -scalar(a);
    }
    case Op::kSqrt: {
      double a = scalar(arg(0));
      return a < 0 ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(a);
    }
    case Op::kSquare: {
      Value a = arg(0);
      if (a.is_vector()) return dot(a.vector, a.vector);
      return scalar(a) * scalar(a);
    }
    case Op::kAbs: return std::abs(scalar(arg(0)));
    case Op::kArccosDegrees:
      return std::acos(std::clamp(scalar(arg(0)), -1.0, 1.0)) * (180 / std::numbers::pi);
    case Op::kArcsinDegrees:
      return std::asin(std::clamp(scalar(arg(0)), -1.0, 1.0)) * (180 / std::numbers::pi);
    case Op::kCos: return std::cos(scalar(arg(0)));
    case Op::kSin: return std::sin(scalar(arg(0)));
    case Op::kRadians: return scalar(arg(0)) * std::numbers::pi / 180;
    case Op::kTan: return std::tan(scalar(arg(0)));
    case Op::kPow: return std::pow(scalar(arg(0)), scalar(arg(1)));
    case Op::kHadamard: {
      Vec3d a = vector(arg(0)), b = vector(arg(1));
      return Vec3d{a.x * b.x, a.y * b.y, a.z * b.z};
    }
    case Op::kNorm: return length_at_any_scale(vector(arg(0)));
    case Op::kMin:
    case Op::kMax: {
      double best = scalar(arg(0));
      for (std::size_t i = 1; i < n.args.size(); ++i) {
        double v = scalar(arg(i));
        best = n.op == Op::kMin ? std::min(best, v) : std::max(best, v);
      }
      return best;
    }
    case Op::kCompare: {
      double a = scalar(arg(0)), b = scalar(arg(1));
      const std::string& r = n.relation;
      bool t = r == "<"    ? a < b
               : r == "<=" ? a <= b
               : r == ">"  ? a > b
               : r == ">=" ? a >= b
               : r == "="  ? a == b
                           : a != b;
      return Value::verdict(t);
    }
    case Op::kTuple: return Vec3d{scalar(arg(0)), scalar(arg(1)), scalar(arg(2))};
  }
  defect("unknown operation");
}

// --- Rendering ----------------------------------------------------------------------------

namespace {

// Binding strength, for deciding where parentheses go.
int precedence(const ExprNode& n, const RenderOptions& o) {
  switch (n.op) {
    case Op::kCompare: return 0;
    case Op::kAdd:
    case Op::kSub: return 1;
    case Op::kMul: return n.implicit ? 3 : 2;
    case Op::kDot:
    case Op::kCross:
    case Op::kHadamard: return 2;
    case Op::kNeg: return 3;
    case Op::kSquare:
    case Op::kPow: return 4;
    case Op::kNumber:
      if (!n.base.empty()) return 5;
      return prints_negative(n.number, o.numbers) ? 3 : 5;
    case Op::kSymbol:
      if (o.substitute) {
        auto it = o.substitute->find(n.name);
        if (it != o.substitute->end()) {
          return it->second.is_scalar() && prints_negative(it->second.scalar, o.numbers) ? 3 : 5;
        }
      }
      return n.args.empty() ? 5 : precedence(n.args[0].node(), o);
    default: return 5;
  }
}

// The pieces each output language spells differently.
struct Dialect {
  std::function<std::string(const std::string&)> number;
  std::function<std::string(const std::string&)> word;  // "undefined", "yes"
  std::function<std::string(const ExprNode&)> symbol;
  std::function<std::string(const std::string&, const std::string&, const std::string&)> vector;
  std::function<std::string(const std::string&)> op;  // an operator sign, by its text form
  std::function<std::string(const std::string&)> paren;
  std::function<std::string(const std::string&, const std::string&)> frac;
  std::function<std::string(const std::string&)> sqrt;
  std::function<std::string(const std::string&)> square;
  std::function<std::string(const std::string&)> abs;
  std::function<std::string(const std::string&)> norm;
  std::function<std::string(const std::string&, const std::string&)> call;   // min(a, b)
  std::function<std::string(const std::string&, const std::string&)> power;  // a^b
  std::string comma;
};

// `leading`: the formula is the first thing in its group, where a negative number needs no
// parentheses ("−3 · x" but "x + (−3)").
std::string render(const E& e, const Dialect& d, const RenderOptions& o, bool leading = true);

std::string render_number(double v, const Dialect& d, const RenderOptions& o, bool leading) {
  std::string s = format_number(v, o.numbers);
  if (std::isnan(v)) return d.word(s);
  // A negative value that prints as 0 (−1.4e-14) needs no parentheses: "1 − 0", not "1 − (0)".
  bool minus = prints_negative(v, o.numbers);
  s = d.number(s);
  return minus && !leading ? d.paren(s) : s;
}

std::string render_value(const Value& v, const Dialect& d, const RenderOptions& o, bool leading) {
  switch (v.kind) {
    case Value::Kind::kScalar: return render_number(v.scalar, d, o, leading);
    case Value::Kind::kVector:
      return d.vector(render_number(v.vector.x, d, o, true), render_number(v.vector.y, d, o, true),
                      render_number(v.vector.z, d, o, true));
    case Value::Kind::kBool: return d.word(v.truth ? "true" : "false");
    case Value::Kind::kNone: break;
  }
  return d.word("?");
}

std::string child(const E& c, int min_prec, const Dialect& d, const RenderOptions& o,
                  bool leading) {
  bool paren = precedence(c.node(), o) < min_prec;
  std::string s = render(c, d, o, paren || leading);
  return paren ? d.paren(s) : s;
}

const char* relation_text(const std::string& r) {
  if (r == "<=") return "≤";
  if (r == ">=") return "≥";
  if (r == "!=") return "≠";
  return r.c_str();
}

// a × b by components, with the numbers of a and b: ⟨a_y·b_z − a_z·b_y, …⟩.
std::optional<E> cross_components(const ExprNode& n, const RenderOptions& o) {
  if (!o.substitute) return std::nullopt;
  Value a, b;
  try {
    a = evaluate(n.args[0], *o.substitute);
    b = evaluate(n.args[1], *o.substitute);
  } catch (const EvaluationFault&) {
    return std::nullopt;
  }
  if (!a.is_vector() || !b.is_vector()) return std::nullopt;
  auto part = [&](int i, int j) {
    return E(a.vector[i]) * E(b.vector[j]) - E(a.vector[j]) * E(b.vector[i]);
  };
  return tuple(part(1, 2), part(2, 0), part(0, 1));
}

std::string render(const E& e, const Dialect& d, const RenderOptions& o, bool leading) {
  const ExprNode& n = e.node();
  switch (n.op) {
    case Op::kNumber:
      if (!n.base.empty()) return d.symbol(n);  // a named constant: π
      return render_number(n.number, d, o, leading);
    case Op::kVector: return render_value(Value(n.vector), d, o, leading);
    case Op::kSymbol:
      if (o.substitute) {
        auto it = o.substitute->find(n.name);
        if (it != o.substitute->end()) return render_value(it->second, d, o, leading);
      }
      if (!n.args.empty()) return render(n.args[0], d, o, leading);
      return d.symbol(n);
    case Op::kAdd:
      return child(n.args[0], 1, d, o, leading) + d.op("+") + child(n.args[1], 2, d, o, false);
    case Op::kSub:
      return child(n.args[0], 1, d, o, leading) + d.op("−") + child(n.args[1], 2, d, o, false);
    case Op::kMul:
      if (n.implicit) return child(n.args[0], 3, d, o, leading) + child(n.args[1], 4, d, o, false);
      return child(n.args[0], 2, d, o, leading) + d.op("·") + child(n.args[1], 3, d, o, false);
    case Op::kDot:
      return child(n.args[0], 3, d, o, leading) + d.op("·") + child(n.args[1], 3, d, o, false);
    case Op::kCross:
      if (n.written_out) {
        if (auto parts = cross_components(n, o)) return render(*parts, d, o, leading);
      }
      return child(n.args[0], 3, d, o, leading) + d.op("×") + child(n.args[1], 3, d, o, false);
    case Op::kDiv: return d.frac(render(n.args[0], d, o), render(n.args[1], d, o));
    case Op::kNeg: return d.op("-") + child(n.args[0], 4, d, o, false);
    case Op::kSqrt: return d.sqrt(render(n.args[0], d, o));
    case Op::kSquare: return d.square(child(n.args[0], 5, d, o, true));
    case Op::kAbs: return d.abs(render(n.args[0], d, o));
    case Op::kArccosDegrees: return d.call("arccos", render(n.args[0], d, o));
    case Op::kArcsinDegrees: return d.call("arcsin", render(n.args[0], d, o));
    case Op::kCos: return d.call("cos", render(n.args[0], d, o));
    case Op::kSin: return d.call("sin", render(n.args[0], d, o));
    case Op::kRadians: return render(n.args[0] * pi() / 180, d, o, leading);
    case Op::kTan: return d.call("tan", render(n.args[0], d, o));
    case Op::kHadamard:
      return child(n.args[0], 3, d, o, leading) + d.op("⊙") + child(n.args[1], 3, d, o, false);
    case Op::kPow: return d.power(child(n.args[0], 5, d, o, true), render(n.args[1], d, o));
    case Op::kNorm: return d.norm(render(n.args[0], d, o));
    case Op::kMin:
    case Op::kMax: {
      std::string inner;
      for (std::size_t i = 0; i < n.args.size(); ++i) {
        if (i) inner += d.comma;
        inner += render(n.args[i], d, o);
      }
      return d.call(n.op == Op::kMin ? "min" : "max", inner);
    }
    case Op::kCompare:
      return render(n.args[0], d, o) + d.op(relation_text(n.relation)) + render(n.args[1], d, o);
    case Op::kTuple:
      return d.vector(render(n.args[0], d, o), render(n.args[1], d, o), render(n.args[2], d, o));
  }
  return "";
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// LaTeX for a symbol part: single letters stay math italics, longer names are upright text.
std::string latex_part(const std::string& s) {
  if (s.size() <= 1) return s;
  if (s == "lambda" || s == "alpha" || s == "beta" || s == "gamma" || s == "theta" ||
      s == "Delta" || s == "eta" || s == "mu" || s == "pi") {
    return "\\" + s;
  }
  return "\\text{" + s + "}";
}

std::string text_part(const std::string& s) {
  static const std::map<std::string, std::string> greek = {
      {"lambda", "λ"}, {"alpha", "α"}, {"beta", "β"}, {"gamma", "γ"}, {"theta", "θ"},
      {"Delta", "Δ"},  {"eta", "η"},   {"mu", "μ"},   {"pi", "π"}};
  auto it = greek.find(s);
  return it == greek.end() ? s : it->second;
}

const std::string& latex_op(const std::string& t) {
  static const std::map<std::string, std::string> ops = {
      {"+", " + "},    {"−", " - "},        {"-", "-"},       {"·", " \\cdot "}, {"×", " \\times "},
      {"<", " < "},    {">", " > "},        {"≤", " \\le "},  {"≥", " \\ge "},   {"=", " = "},
      {"≠", " \\ne "}, {"≈", " \\approx "}, {"⊙", " \\odot "}};
  auto it = ops.find(t);
  return it == ops.end() ? t : it->second;
}

const Dialect& latex_dialect() {
  static const Dialect d{
      [](const std::string& s) {
        return s == "∞" ? std::string("\\infty") : s == "−∞" ? std::string("-\\infty") : s;
      },
      [](const std::string& s) { return "\\text{" + s + "}"; },
      [](const ExprNode& n) {
        std::string s = latex_part(n.base);
        if (!n.sub.empty()) s += "_{" + latex_part(n.sub) + "}";
        if (!n.sup.empty()) s += "^{" + n.sup + "}";
        return s;
      },
      [](const std::string& x, const std::string& y, const std::string& z) {
        return "\\langle " + x + ", " + y + ", " + z + " \\rangle";
      },
      [](const std::string& t) { return latex_op(t); },
      [](const std::string& s) { return "\\left(" + s + "\\right)"; },
      [](const std::string& a, const std::string& b) { return "\\frac{" + a + "}{" + b + "}"; },
      [](const std::string& a) { return "\\sqrt{" + a + "}"; },
      [](const std::string& a) { return "{" + a + "}^2"; },
      [](const std::string& a) { return "\\left|" + a + "\\right|"; },
      [](const std::string& a) { return "\\lVert " + a + " \\rVert"; },
      [](const std::string& f, const std::string& a) {
        return "\\" + f + "\\left(" + a + "\\right)";
      },
      [](const std::string& a, const std::string& b) { return "{" + a + "}^{" + b + "}"; },
      ", "};
  return d;
}

std::string mo(const std::string& s) { return "<mo>" + xml_escape(s) + "</mo>"; }
std::string mrow(const std::string& s) { return "<mrow>" + s + "</mrow>"; }

std::string mathml_part(const std::string& s) {
  std::string t = text_part(s);
  if (s.size() > 1 && t == s) return "<mi mathvariant=\"normal\">" + xml_escape(s) + "</mi>";
  return "<mi>" + xml_escape(t) + "</mi>";
}

const Dialect& mathml_dialect() {
  static const Dialect d{
      [](const std::string& s) {
        if (!s.empty() && (s[0] == '-' || s.rfind("−", 0) == 0)) {
          std::string rest = s[0] == '-' ? s.substr(1) : s.substr(3);
          return mrow(mo("−") + "<mn>" + xml_escape(rest) + "</mn>");
        }
        return "<mn>" + xml_escape(s) + "</mn>";
      },
      [](const std::string& s) { return "<mtext>" + xml_escape(s) + "</mtext>"; },
      [](const ExprNode& n) {
        std::string base = mathml_part(n.base);
        if (!n.sub.empty() && !n.sup.empty()) {
          return "<msubsup>" + base + mathml_part(n.sub) + "<mn>" + xml_escape(n.sup) +
                 "</mn></msubsup>";
        }
        if (!n.sub.empty()) return "<msub>" + base + mathml_part(n.sub) + "</msub>";
        if (!n.sup.empty()) return "<msup>" + base + "<mn>" + xml_escape(n.sup) + "</mn></msup>";
        return base;
      },
      [](const std::string& x, const std::string& y, const std::string& z) {
        return mrow(mo("⟨") + x + mo(",") + y + mo(",") + z + mo("⟩"));
      },
      [](const std::string& t) { return mo(t == "-" ? "−" : t); },
      [](const std::string& s) { return mrow(mo("(") + s + mo(")")); },
      [](const std::string& a, const std::string& b) {
        return "<mfrac>" + mrow(a) + mrow(b) + "</mfrac>";
      },
      [](const std::string& a) { return "<msqrt>" + a + "</msqrt>"; },
      [](const std::string& a) { return "<msup>" + mrow(a) + "<mn>2</mn></msup>"; },
      [](const std::string& a) { return mrow(mo("|") + a + mo("|")); },
      [](const std::string& a) { return mrow(mo("‖") + a + mo("‖")); },
      [](const std::string& f, const std::string& a) {
        return mrow("<mi>" + f + "</mi>" + mo("(") + a + mo(")"));
      },
      [](const std::string& a, const std::string& b) {
        return "<msup>" + mrow(a) + mrow(b) + "</msup>";
      },
      "<mo>,</mo>"};
  return d;
}

const Dialect& text_dialect() {
  static const Dialect d{
      [](const std::string& s) { return !s.empty() && s[0] == '-' ? "−" + s.substr(1) : s; },
      [](const std::string& s) { return s; },
      [](const ExprNode& n) {
        std::string s = text_part(n.base);
        if (!n.sub.empty()) s += "_" + text_part(n.sub);
        if (n.sup == "2") {
          s += "²";
        } else if (!n.sup.empty()) {
          s += "^" + n.sup;
        }
        return s;
      },
      [](const std::string& x, const std::string& y, const std::string& z) {
        return "⟨" + x + ", " + y + ", " + z + "⟩";
      },
      [](const std::string& t) { return t == "-" ? std::string("−") : " " + t + " "; },
      [](const std::string& s) { return "(" + s + ")"; },
      [](const std::string& a, const std::string& b) {
        bool simple_a = a.find(' ') == std::string::npos;
        bool simple_b = b.find(' ') == std::string::npos && b.rfind("−", 0) != 0;
        return (simple_a ? a : "(" + a + ")") + " / " + (simple_b ? b : "(" + b + ")");
      },
      [](const std::string& a) {
        bool simple = a.find(' ') == std::string::npos && a.find('/') == std::string::npos;
        return simple ? "√" + a : "√(" + a + ")";
      },
      [](const std::string& a) { return a + "²"; },
      [](const std::string& a) { return "|" + a + "|"; },
      [](const std::string& a) { return "‖" + a + "‖"; },
      [](const std::string& f, const std::string& a) { return f + "(" + a + ")"; },
      [](const std::string& a, const std::string& b) {
        bool simple = b.find(' ') == std::string::npos;
        return a + "^" + (simple ? b : "(" + b + ")");
      },
      ", "};
  return d;
}

}  // namespace

std::string to_latex(const E& e, const RenderOptions& o) { return render(e, latex_dialect(), o); }
std::string to_mathml(const E& e, const RenderOptions& o) { return render(e, mathml_dialect(), o); }
std::string to_text(const E& e, const RenderOptions& o) { return render(e, text_dialect(), o); }

namespace {

// The exact form as a formula: (p + s√k)/q.
E exact_formula(const ExactForm& x) {
  E root;
  if (x.s != 0) {
    E r = raygrade::sqrt(E(static_cast<double>(x.k)));
    if (std::llabs(x.s) != 1) {
      auto n = make(Op::kMul, {E(static_cast<double>(std::llabs(x.s))), r});
      n->implicit = true;
      r = wrap(n);
    }
    root = r;
  }
  E top;
  if (x.s == 0) {
    top = E(static_cast<double>(x.p));
  } else if (x.p == 0) {
    top = x.s < 0 ? -root : root;
  } else {
    top = x.s < 0 ? E(static_cast<double>(x.p)) - root : E(static_cast<double>(x.p)) + root;
  }
  return x.q == 1 ? top : top / E(static_cast<double>(x.q));
}

std::string render_result(const Value& v, const Dialect& d, const RenderOptions& o) {
  if (o.exact && v.is_scalar()) {
    if (auto x = exact_form(v.scalar)) {
      // Never "≈" between equal strings: the exact form is shown only where it says more.
      std::string exact = render(exact_formula(*x), d, o);
      std::string number = render_number(v.scalar, d, o, true);
      return exact == number ? number : exact + d.op("≈") + number;
    }
  }
  return render_value(v, d, o, true);
}

}  // namespace

std::string value_latex(const Value& v, const RenderOptions& o) {
  return render_result(v, latex_dialect(), o);
}
std::string value_mathml(const Value& v, const RenderOptions& o) {
  return render_result(v, mathml_dialect(), o);
}
std::string value_text(const Value& v, const RenderOptions& o) {
  return render_result(v, text_dialect(), o);
}

}  // namespace raygrade
