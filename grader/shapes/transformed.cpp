// Transformed primitives: the ray into object space, the primitive's own steps there, and the
// hits back in the world, as derivation steps.
#include "shapes/transformed.h"

#include <cctype>
#include <cmath>

#include "derivation/number_format.h"

namespace raygrade {
namespace {

// A step of the primitive's derivation is taken for a hit's t (or normal) when its value is the
// hit's within this relative distance: the same quantity, computed once by the reference
// solver (in double-double for normals) and once by the formula the worked solution shows.
constexpr double kSameValueRelative = 1e-9;

bool same(double a, double b) {
  return std::abs(a - b) <= kSameValueRelative * std::max(1.0, std::abs(b));
}

// The last computed step of `inner` named like `prefix...` whose value is `v`: the last, since
// a method's result comes after the pieces that may share its value (a box's t_enter after
// t_low_x).
const Step* step_with_value(const Derivation& inner, char prefix, const Value& v) {
  const Step* found = nullptr;
  for (const auto& s : inner.steps) {
    if (s.given || s.name.empty() || std::tolower(s.name[0]) != prefix || s.value.kind != v.kind) {
      continue;
    }
    if ((v.is_scalar() && same(s.value.scalar, v.scalar)) ||
        (v.is_vector() && same(s.value.vector.x, v.vector.x) &&
         same(s.value.vector.y, v.vector.y) && same(s.value.vector.z, v.vector.z))) {
      found = &s;
    }
  }
  return found;
}

// The matrix with rows `rows` (givens) times the vector `v`.
E times(const std::array<E, 3>& rows, const E& v) {
  return tuple(dot(rows[0], v), dot(rows[1], v), dot(rows[2], v));
}

}  // namespace

NormalRule normal_rule_of(const Shape& shape) {
  NormalRule rule = normal_rule(shape.type());
  if (dynamic_cast<const TransformedShape*>(&shape) && !rule.sentence.empty()) {
    rule.sentence =
        " A transformed object's outward normal is its primitive's, taken back to the world by "
        "the inverse transpose (A⁻¹)ᵀ and normalized.";
  }
  return rule;
}

Intersection TransformedShape::intersect(const Ray& ray) const {
  return transform_.hits_to_world(ray, object_->intersect(transform_.ray_to_object(ray)));
}

Derivation TransformedShape::derive(const Ray& ray, std::string_view method,
                                    const Overrides* overrides) const {
  Deriver d("", "", overrides);
  // Into object space
  E Ow = d.given("O_world", "O_w", ray.origin, "the ray's origin in the world");
  E Dw = d.given("D_world", "D_w", ray.direction, "the ray's direction in the world");
  const Affine& inv = transform_.to_object;
  std::array<E, 3> r;
  for (int i = 0; i < 3; ++i) {
    std::string note = fmt::format("row {} of A⁻¹", i + 1);
    if (i == 0) {
      note = fmt::format(
          "The object is placed by M: {} (p_w = A p + b). Row 1 of A⁻¹, the inverse of its "
          "linear part",
          describe_transform(transform_));
    }
    r[i] = d.given(fmt::format("Minv_{}", i + 1), fmt::format("r_{}", i + 1), inv.rows[i], note);
  }
  E u = d.given("Minv_b", "u", inv.translation, "the translation of M⁻¹: u = −A⁻¹b");
  Value O = d.step("O_obj", "O'", times(r, Ow) + u, "the ray's origin in object space: M⁻¹ O_w");
  Value D = d.step("D_obj", "D'", times(r, Dw),
                   "the ray's direction in object space: A⁻¹ D_w, not normalized, so that t is "
                   "the same in both spaces");
  Ray object_ray{O.vector, D.vector, ray.t_min, ray.t_max};

  // The primitive in object space
  Derivation inner = object_->derive(object_ray, method, overrides);
  d.append(inner);
  std::string type(object_->type());

  // Back to the world
  Intersection x = object_->intersect(object_ray);
  std::array<E, 3> c;
  if (!x.hits.empty()) {
    for (int i = 0; i < 3; ++i) {
      c[i] = d.given(fmt::format("Minv_T_{}", i + 1), fmt::format("c_{}", i + 1),
                     Vec3d{inv.rows[0][i], inv.rows[1][i], inv.rows[2][i]},
                     fmt::format("row {0} of (A⁻¹)ᵀ, column {0} of A⁻¹: normals go back by the "
                                 "inverse transpose",
                                 i + 1));
    }
  }
  std::vector<std::pair<Value, Value>> world;
  for (std::size_t k = 0; k < x.hits.size(); ++k) {
    const Hit& h = x.hits[k];
    const Step* ts = step_with_value(inner, 't', h.t);
    E t = ts ? d.sym(ts->name)
             : d.given(fmt::format("t_hit{}", k), fmt::format("t_{}", k), h.t,
                       "the hit's t in object space");
    const Step* ns = step_with_value(inner, 'n', h.normal);
    E n = ns ? d.sym(ns->name)
             : d.given(fmt::format("N{}_obj", k), fmt::format("N'_{}", k), h.normal,
                       "the outward unit normal at the hit in object space");
    Value P = d.step(fmt::format("P{}_world", k), fmt::format("P_{}^w", k), Ow + t * Dw,
                     "the hit in the world: the world ray at the same t");
    std::string m = fmt::format("m{}", k);
    d.step(m, fmt::format("m_{}", k), times(c, n),
           "the normal taken back by the inverse transpose (not yet of unit length)");
    Value N = d.step(fmt::format("N{}_world", k), fmt::format("N_{}^w", k),
                     d.sym(m) / norm(d.sym(m)), "the outward unit normal in the world");
    world.emplace_back(P, N);
  }
  for (const auto& s : inner.sentences) {
    Sentence in("In object space: ");
    for (const auto& p : s.parts()) {
      if (p.value.kind == Value::Kind::kNone) {
        in.text(p.text);
      } else {
        in.value(p.value);
      }
    }
    d.conclude(std::move(in));
  }
  if (world.empty()) {
    d.conclude(fmt::format("The ray does not hit the transformed {}.", type));
  } else {
    Sentence s(fmt::format("In the world, the ray hits the transformed {} at ", type));
    for (std::size_t k = 0; k < world.size(); ++k) {
      if (k) s.text("; at ");
      s.text("t = ")
          .value(x.hits[k].t)
          .text(", P = ")
          .value(world[k].first)
          .text(", N = ")
          .value(world[k].second);
    }
    s.text(".");
    d.conclude(std::move(s));
  }
  Derivation out = std::move(d).finish();
  out.method = inner.method;
  out.title = inner.title + ", transformed";
  return out;
}

nlohmann::json TransformedShape::to_json() const {
  nlohmann::json j = object_->to_json();
  j["transform"] = transform_.to_json();
  return j;
}

Vec3d TransformedShape::center() const { return transform_.to_world.point(object_->center()); }

double TransformedShape::extent() const {
  // The Frobenius norm of A bounds how far A stretches any vector.
  const auto& a = transform_.to_world.rows;
  return object_->extent() * std::sqrt(dot(a[0], a[0]) + dot(a[1], a[1]) + dot(a[2], a[2]));
}

}  // namespace raygrade
