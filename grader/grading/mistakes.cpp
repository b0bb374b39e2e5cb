// The mistake catalogue and the formula rewrites that model each mistake.
#include "grading/mistakes.h"

#include <fmt/format.h>

#include <cmath>

#include "core/error.h"
#include "core/internal_error.h"
#include "shapes/primitives.h"

namespace raygrade {
namespace {

// The primitives that have formula mistakes of their own (`mistakes()`, in their own files).
template <typename P>
concept HasOwnMistakes = requires {
  { P::mistakes() } -> std::same_as<const std::vector<PrimitiveMistake>&>;
};

// Calls f(m) for every primitive's own mistake, in the list's order.
template <typename F>
void for_each_primitive_mistake(F&& f) {
  for_each_type(
      [&]<typename P>() {
        if constexpr (HasOwnMistakes<P>) {
          for (const PrimitiveMistake& m : P::mistakes()) f(m);
        }
      },
      Primitives{});
}

}  // namespace

const std::vector<MistakeInfo>& mistake_catalogue() {
  static const std::vector<MistakeInfo> catalogue = [] {
    std::vector<MistakeInfo> c = {
        {"discriminant-sign", "sign", "Sign slip in the discriminant",
         "The discriminant is b² − 4ac; with + 4ac the roots move.", 0},
        {"b-sign", "sign", "Sign slip in the quadratic's b",
         "b = 2 D·(O − C): with C − O instead of O − C the sign of b flips, and with it both "
         "roots.",
         0},
        {"far-root", "root-choice", "Far root given as the first hit",
         "Of two roots, the ray meets the surface first at the smaller t ≥ 0; the larger is "
         "where it leaves.",
         0},
        {"negative-t", "root-choice", "Negative t given as a hit",
         "A root with t < 0 lies behind the ray's origin: it solves the equation but is not a "
         "hit.",
         0},
        {"unit-direction-t", "convention", "t measured along the normalized direction",
         "t counts lengths of the direction as given. The direction here is not a unit vector, "
         "so a distance along D/|D| must be divided by |D| to give t.",
         0},
        {"object-space-unit-t", "convention", "t measured along a unit object-space direction",
         "A transformed object is met in its own space by the ray M⁻¹O + t·A⁻¹D, with A⁻¹D "
         "kept as it is, not normalized, so that t is the same in both spaces. Normalized, t "
         "counts lengths in object space, which the transform's scale changes: divide that "
         "distance by |A⁻¹D| to get the world t.",
         0},
        {"cross-order", "orientation", "Cross product in the wrong order",
         "a × b = −(b × a): swapping the factors flips the vector. With vertices a, b, c in "
         "order the normal is (b − a) × (c − a); a camera's right vector is d × u.",
         0.5},
        {"inward-normal", "orientation", "Normal pointing inward",
         "A closed surface's normal points outward, away from its inside.", 0.5},
        {"normal-not-inverse-transpose", "orientation", "Normal transformed by the matrix",
         "A transformed object's normal goes back to the world by the inverse transpose (A⁻¹)ᵀ, "
         "which keeps it perpendicular to the surface; the matrix A itself tilts it whenever it "
         "scales unevenly.",
         0},
        {"pixel-corner", "convention", "Pixel corner instead of pixel centre",
         "The offsets x − resX/2 aim at the pixel's lower-left corner; the centre needs half a "
         "pixel more, x + 0.5 − resX/2.",
         0.5},
        {"pixel-centre", "convention", "Pixel centre instead of pixel corner",
         "This problem uses the corner convention x − resX/2 (as in the course's formula); the "
         "extra half pixel aims at the centre instead.",
         0.5},
        {"r-not-squared", "algebra", "r where r² belongs",
         "The surface's equation has r² (|P − C|² = r²); using r itself changes every root.", 0},
        {"diffuse-in-shadow", "lighting", "Diffuse term at a point in shadow",
         "The diffuse and specular terms need light arriving from the light source; when the "
         "shadow ray toward it meets an object first, only the ambient term remains.",
         0},
        {"media-not-nested", "refraction", "The space between objects where an outer medium is",
         "Leaving a transparent object that lies inside another, the ray goes on in the outer "
         "one: n is the index of the innermost medium the ray is still inside, not the "
         "scene's.",
         0},
        {"n1-n2-swapped", "refraction", "n1 and n2 swapped",
         "n1 is the index of the medium the ray comes from, n2 of the one it goes into.", 0},
        {"component-is-total", "lighting", "The total given for one component",
         "A node's intensity is the sum of its components: ambient, diffuse and specular (the "
         "local part), then k_r·I_R and k_t·I_T from its children. One component is one of "
         "those terms.",
         0},
        {"secondary-unweighted", "lighting", "A child's intensity without its weight",
         "What a reflection or refraction ray brings is its intensity times the weight of the "
         "surface it leaves: k_r·I_R and k_t·I_T (with a Fresnel model, F·k_r and (1 − F)·k_t).",
         0},
        {"lit-point-ambient-only", "lighting", "Ambient term only at a lit point",
         "When the shadow ray reaches the light (and the surface faces it), the diffuse and "
         "specular terms apply as well as the ambient one.",
         0},
        {"halfway-vector", "lighting", "N·H where R·V is asked",
         "The Phong highlight is (R·V)ⁿ with R = 2(N·L)N − L, the light's mirror direction. "
         "N·H with the halfway vector H = (L + V)/‖L + V‖ is Blinn-Phong's highlight, another "
         "model with other numbers.",
         0},
        // not a part: the mistake's family, colour
        {"scalar-for-colour", "colour", "One number where a colour is asked",
         "When a light or a material is a colour, every intensity is a colour [r, g, b], worked "
         "channel by channel; one number does not say which channel it is.",
         0},
    };
    for_each_primitive_mistake([&](const PrimitiveMistake& m) { c.push_back(m.info); });
    return c;
  }();
  return catalogue;
}

const MistakeInfo& mistake_info(std::string_view id) {
  for (const auto& m : mistake_catalogue()) {
    if (m.id == id) return m;
  }
  throw InternalError(fmt::format("no mistake named '{}' in the catalogue", id));
}

FoundMistake make_mistake(std::string_view id, std::string part, const std::string& specific) {
  const MistakeInfo& m = mistake_info(id);
  return FoundMistake{std::string(m.id), std::string(m.kind), std::move(part),
                      fmt::format("{}: {} {}", m.title, specific, m.explanation)};
}

E rewrite_tree(const E& e, const std::function<std::optional<E>(const E&)>& replace) {
  if (e.empty()) return e;
  if (auto r = replace(e)) return *r;
  const ExprNode& n = e.node();
  if (n.args.empty()) return e;
  auto copy = std::make_shared<ExprNode>(n);
  bool changed = false;
  for (auto& a : copy->args) {
    E b = rewrite_tree(a, replace);
    if (&b.node() != &a.node()) changed = true;
    a = b;
  }
  return changed ? E(std::shared_ptr<const ExprNode>(std::move(copy))) : e;
}

namespace {

bool is_symbol(const E& e, std::string_view name) {
  return !e.empty() && e.node().op == Op::kSymbol && e.node().name == name;
}

std::optional<E> discriminant_sign(std::string_view step, const E& f) {
  if (step != "discriminant" || f.empty() || f.node().op != Op::kSub) return std::nullopt;
  return f.node().args[0] + f.node().args[1];
}

std::optional<E> b_sign(std::string_view step, const E& f) {
  // A step b that only negates another quantity (a camera's bottom edge b = −t) is not a
  // quadratic's b.
  // not a part: a derivation's quantity (a quadratic's b)
  if (step != "b" || (f.node().op == Op::kNeg && f.node().args[0].node().op == Op::kSymbol)) {
    return std::nullopt;
  }
  return -f;
}

// a × b written b × a: every cross product in the step's formula with its factors swapped.
std::optional<E> cross_order(std::string_view /*step*/, const E& f) {
  bool changed = false;
  E g = rewrite_tree(f, [&](const E& x) -> std::optional<E> {
    if (x.node().op != Op::kCross) return std::nullopt;
    changed = true;
    return cross(x.node().args[1], x.node().args[0]);
  });
  if (!changed) return std::nullopt;
  return g;
}

std::optional<E> r_not_squared(std::string_view /*step*/, const E& f) {
  bool changed = false;
  E g = rewrite_tree(f, [&](const E& x) -> std::optional<E> {
    if (x.node().op == Op::kSquare && is_symbol(x.node().args[0], "r")) {
      changed = true;
      return x.node().args[0];
    }
    return std::nullopt;
  });
  if (!changed) return std::nullopt;
  return g;
}

// The symbol `name` as a formula writes it, or nothing.
std::optional<E> symbol_in(const E& e, std::string_view name) {
  if (e.empty()) return std::nullopt;
  if (is_symbol(e, name)) return e;
  for (const auto& a : e.node().args) {
    if (auto s = symbol_in(a, name)) return s;
  }
  return std::nullopt;
}

// n1 and n2 exchanged in every step that has both: the ratio η = n1/n2 (and Fresnel's R_s,
// R_p, R0) with the indices of the two media the wrong way round.
std::optional<E> n1_n2_swapped(std::string_view /*step*/, const E& f) {
  std::optional<E> n1 = symbol_in(f, "n1"), n2 = symbol_in(f, "n2");
  if (!n1 || !n2) return std::nullopt;
  return rewrite_tree(f, [&](const E& x) -> std::optional<E> {
    if (is_symbol(x, "n1")) return *n2;
    if (is_symbol(x, "n2")) return *n1;
    return std::nullopt;
  });
}

// Every light's shadow factor s (shadow_1, shadow_2, ...: 1 when its shadow ray reaches it, 0
// when it is blocked) replaced by `value`.
std::optional<E> shadow_factors_as(const E& f, double value) {
  bool changed = false;
  E g = rewrite_tree(f, [&](const E& x) -> std::optional<E> {
    if (x.node().op != Op::kSymbol || !x.node().name.starts_with("shadow_")) return std::nullopt;
    changed = true;
    return E(value);
  });
  if (!changed) return std::nullopt;
  return g;
}

// A blocked light's terms counted: its shadow factor taken as 1.
std::optional<E> diffuse_in_shadow(std::string_view /*step*/, const E& f) {
  return shadow_factors_as(f, 1);
}

// A lit light's terms left out: every shadow factor taken as 0, only the ambient term left.
std::optional<E> lit_point_ambient_only(std::string_view /*step*/, const E& f) {
  return shadow_factors_as(f, 0);
}

// Blinn-Phong's N·H for Phong's R·V: each light's step RV_i = R_i·V worked as N·H_i, with the
// halfway vector H_i = (L_i + V)/‖L_i + V‖ between the light and the eye E as a shade problem
// gives them (V = (E − P)/‖E − P‖). A ray tree has no eye E (its viewer is the incoming ray,
// and its grader reads its nodes its own way): there the formula cannot be worked and the
// mistake does not apply.
std::optional<E> halfway_vector(std::string_view step, const E& f) {
  const ExprNode& n = f.node();
  if (!step.starts_with("RV_") || n.op != Op::kDot || !is_symbol(n.args[1], "V")) {
    return std::nullopt;
  }
  std::string i(step.substr(3));
  E L = sym("L_" + i, "L_" + i), P = sym("P", "P"), Eye = sym("E", "E");
  E V = (Eye - P) / norm(Eye - P);
  return dot(sym("N", "N"), (L + V) / norm(L + V));
}

// An image-plane coordinate's pixel count (the column i or the row j) in the steps u_s and
// v_s, as `change` turns it: without the half pixel (i + 0.5 → i), or with it (i → i + 0.5).
std::optional<E> pixel_count(std::string_view step, const E& f, bool centre_to_corner) {
  // not a part: the derivation's quantities u_s and v_s
  if (step != "u_s" && step != "v_s") return std::nullopt;
  bool changed = false;
  E g = rewrite_tree(f, [&](const E& x) -> std::optional<E> {
    const ExprNode& n = x.node();
    bool count = is_symbol(x, "i") || is_symbol(x, "j");
    bool half = n.op == Op::kAdd && (is_symbol(n.args[0], "i") || is_symbol(n.args[0], "j")) &&
                n.args[1].node().op == Op::kNumber && n.args[1].node().number == 0.5;
    if (centre_to_corner && half) {
      changed = true;
      return n.args[0];
    }
    if (!centre_to_corner && count) {
      changed = true;
      return x + 0.5;
    }
    return std::nullopt;
  });
  if (!changed) return std::nullopt;
  return g;
}

// A centre problem's pixel taken at its corner, and a corner problem's at its centre.
std::optional<E> pixel_corner(std::string_view step, const E& f) {
  return pixel_count(step, f, true);
}
std::optional<E> pixel_centre(std::string_view step, const E& f) {
  // Only where the formula has no half pixel already.
  std::optional<E> corner = pixel_count(step, f, true);
  if (corner) return std::nullopt;
  return pixel_count(step, f, false);
}

// Two derivations differ in some step's value.
bool same_value(const Value& a, const Value& b) {
  constexpr double kSame = 1e-12;  // far below any tolerance; above rounding noise
  if (a.kind != b.kind) return false;
  if (a.is_scalar()) return std::abs(a.scalar - b.scalar) <= kSame * (1 + std::abs(b.scalar));
  if (a.is_vector()) return length(a.vector - b.vector) <= kSame * (1 + length(b.vector));
  return a.truth == b.truth;
}

bool same_parts(const std::vector<SolutionPart>& a, const std::vector<SolutionPart>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto& sa = a[i].derivation.steps;
    const auto& sb = b[i].derivation.steps;
    if (sa.size() != sb.size()) return false;
    for (std::size_t k = 0; k < sa.size(); ++k) {
      if (sa[k].name != sb[k].name || !same_value(sa[k].value, sb[k].value)) return false;
    }
  }
  return true;
}

}  // namespace

const std::vector<FormulaMistake>& formula_mistakes() {
  static const std::vector<FormulaMistake> mistakes = [] {
    std::vector<FormulaMistake> m = {
        {"discriminant-sign", &discriminant_sign},
        {"b-sign", &b_sign},
        {"r-not-squared", &r_not_squared},
        {"cross-order", &cross_order},
        {"n1-n2-swapped", &n1_n2_swapped},
        {"diffuse-in-shadow", &diffuse_in_shadow},
        {"lit-point-ambient-only", &lit_point_ambient_only},
        {"pixel-corner", &pixel_corner},
        {"pixel-centre", &pixel_centre},
        {"halfway-vector", &halfway_vector},
    };
    for_each_primitive_mistake([&](const PrimitiveMistake& own) {
      m.push_back({own.info.id, own.rewrite});
    });
    return m;
  }();
  return mistakes;
}

std::vector<MistakenSolution> mistaken_solutions(const Task& task) {
  std::vector<MistakenSolution> out;
  for (const auto& method : task.methods()) {
    std::vector<SolutionPart> right;
    try {
      right = task.derive(method, nullptr);
    } catch (const Error&) {
      continue;
    }
    for (const auto& fm : formula_mistakes()) {
      Overrides o;
      o.formula = fm.rewrite;
      try {
        auto parts = task.derive(method, &o);
        if (!same_parts(parts, right)) {
          out.push_back(MistakenSolution{std::string(fm.id), method, std::move(parts)});
        }
      } catch (const Error&) {
        // The mistake takes the derivation off the method's way (no root where one was).
      } catch (const EvaluationFault&) {
        // The mistake makes the derivation meaningless here (a vector where a number was).
      }
    }
  }
  return out;
}

bool same_step_value(const Value& a, const Value& b) { return same_value(a, b); }

const Step* find_answer_step(const std::vector<SolutionPart>& parts, const nlohmann::json& value) {
  Value v;
  if (value.is_number()) {
    v = Value(value.get<double>());
  } else if (value.is_array() && value.size() == 3 && value[0].is_number() &&
             value[1].is_number() && value[2].is_number()) {
    v = Value(Vec3d{value[0].get<double>(), value[1].get<double>(), value[2].get<double>()});
  } else {
    return nullptr;
  }
  // The reference answer and the derivation compute a number by the same formula, but not
  // always in the same order: they agree far below any tolerance, not to the last bit.
  constexpr double kAgree = 1e-9;
  auto agree = [&](const Value& s) {
    if (s.kind != v.kind) return false;
    if (s.is_scalar()) return std::abs(s.scalar - v.scalar) <= kAgree * (1 + std::abs(v.scalar));
    return length(s.vector - v.vector) <= kAgree * (1 + length(v.vector));
  };
  const Step* found = nullptr;
  for (const auto& part : parts) {
    for (const auto& s : part.derivation.steps) {
      if (!s.given && agree(s.value)) found = &s;
    }
  }
  return found;
}

const Step* find_step(const std::vector<SolutionPart>& parts, std::string_view name) {
  const Step* found = nullptr;
  for (const auto& part : parts) {
    for (const auto& s : part.derivation.steps) {
      if (s.name == name) found = &s;
    }
  }
  return found;
}

std::vector<double> derivation_roots(const Derivation& d) {
  static const char* const kNames[] = {"t0", "t1", "t", "t_enter", "t_exit", "t_bottom", "t_top"};
  std::vector<double> out;
  for (const auto& s : d.steps) {
    if (s.given || !s.value.is_scalar() || !std::isfinite(s.value.scalar)) continue;
    for (const char* n : kNames) {
      if (s.name == n) out.push_back(s.value.scalar);
    }
  }
  return out;
}

}  // namespace raygrade
