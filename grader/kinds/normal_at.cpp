// The normal kind: the surface normal at a given point, as the gradient of the object's
// surface there, in object space and back in the world.
#include "kinds/normal_at.h"

#include <algorithm>
#include <cmath>

#include "core/internal_error.h"
#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/intersect.h"
#include "kinds/part_names.h"
#include "kinds/sketch.h"
#include "shapes/primitives.h"
#include "shapes/transformed.h"

namespace raygrade {
namespace {

// Calls f with `primitive` as its own type: one of the list of primitives.
template <typename F>
void as_primitive(const Shape& primitive, F&& f) {
  bool found = false;
  for_each_primitive([&]<typename T>() {
    if (auto* shape = dynamic_cast<const T*>(&primitive)) {
      f(*shape);
      found = true;
    }
  });
  if (!found) {
    throw InternalError(
        fmt::format("the normal kind's object, a {}, is not one of the list of "
                    "primitives",
                    primitive.type()));
  }
}

}  // namespace

SurfacePoint nearest_surface(const Shape& primitive, const Vec3d& p) {
  double tie = kOnSurfaceRelative * std::max(1.0, primitive.extent());
  SurfacePoint s;
  as_primitive(primitive, [&](const auto& shape) { s = shape.nearest_surface(p, tie); });
  return s;
}

const Shape& NormalTask::primitive() const {
  auto* t = dynamic_cast<const TransformedShape*>(object_.get());
  return t ? t->object() : *object_;
}

const Transform* NormalTask::transform() const {
  auto* t = dynamic_cast<const TransformedShape*>(object_.get());
  return t && !t->transform().identity() ? &t->transform() : nullptr;
}

std::unique_ptr<Task> NormalTask::read(const Cursor& problem) {
  auto task = std::make_unique<NormalTask>(read_lone_object(problem.at("object")),
                                           problem.at("point").vec3());
  const Transform* m = task->transform();
  Vec3d p = m ? m->to_object.point(task->point_) : task->point_;
  SurfacePoint s = nearest_surface(task->primitive(), p);
  Vec3d nearest = m ? m->to_world.point(s.nearest) : s.nearest;
  double off = length(nearest - task->point_);
  double tol = kOnSurfaceRelative * std::max(1.0, task->object_->extent());
  std::string type(task->object_->type());
  if (off > tol) {
    problem.at("point").fail(
        fmt::format("the point {} is not on the {}: it is {} from the surface point {}{} (a "
                    "point within {} of the surface is taken as on it)",
                    format_vector(task->point_), type, format_number(off), format_vector(nearest),
                    m ? " (the nearest in object space, taken back to the world)" : ", the nearest",
                    format_number(tol)),
        "off-surface");
  }
  if (!s.other.empty()) {
    problem.at("point").fail(fmt::format("the point {} lies where the {}'s {} meets its {}: the "
                                         "normal is not defined there",
                                         format_vector(task->point_), type, s.part, s.other),
                             "degenerate");
  }
  if (length(s.normal) == 0) {
    problem.at("point").fail(
        fmt::format("the point {} has no normal on the {}", format_vector(task->point_), type),
        "degenerate");
  }
  return task;
}

Vec3d NormalTask::world_normal() const {
  const Transform* m = transform();
  Vec3d p = m ? m->to_object.point(point_) : point_;
  Vec3d n = normalized(nearest_surface(primitive(), p).normal);
  return m ? normalized(m->normal_to_world.linear(n)) : n;
}

std::optional<Vec3d> NormalTask::normal_by_matrix() const {
  const Transform* m = transform();
  if (!m) return std::nullopt;
  Vec3d n = normalized(nearest_surface(primitive(), m->to_object.point(point_)).normal);
  Vec3d wrong = normalized(m->to_world.linear(n));
  if (length(wrong - world_normal()) <= kOnSurfaceRelative) return std::nullopt;
  return wrong;
}

bool NormalTask::solid() const {
  return normal_rule(primitive().type()).mistake == "inward-normal";
}

nlohmann::json NormalTask::answer() const {
  nlohmann::json j = {{"normal", vec_json(world_normal())}};
  if (const Transform* m = transform()) {
    j["object_normal"] =
        vec_json(normalized(nearest_surface(primitive(), m->to_object.point(point_)).normal));
  }
  return j;
}

std::vector<SolutionPart> NormalTask::derive(std::string_view /*method*/,
                                             const Overrides* overrides) const {
  Deriver d("gradient", "The normal at a point", overrides);
  const Transform* m = transform();
  E P = d.given("P", "P", point_, "the point on the surface");
  std::array<E, 3> c;
  if (m) {
    std::array<E, 3> r;
    for (int i = 0; i < 3; ++i) {
      r[i] = d.given(
          fmt::format("Minv_{}", i + 1), fmt::format("r_{}", i + 1), m->to_object.rows[i],
          i == 0
              ? fmt::format("The object is placed by M: {}. Row 1 of A⁻¹", describe_transform(*m))
              : fmt::format("row {} of A⁻¹", i + 1));
    }
    E u = d.given("Minv_b", "u", m->to_object.translation, "the translation of M⁻¹");
    d.step("P_obj", "P'", tuple(dot(r[0], P), dot(r[1], P), dot(r[2], P)) + u,
           "the point in object space: M⁻¹ P");
    P = d.sym("P_obj");
  }
  std::string type(primitive().type());
  Vec3d p = m ? m->to_object.point(point_) : point_;
  SurfacePoint s = nearest_surface(primitive(), p);
  std::string N = m ? "N_obj" : "N";
  NormalNames names{N, m ? "N'" : "N", m ? "P'" : "P"};
  as_primitive(primitive(), [&](const auto& shape) { shape.derive_normal(d, P, s, names); });
  if (m) {
    for (int i = 0; i < 3; ++i) {
      const Affine& inv = m->to_object;
      c[i] =
          d.given(fmt::format("Minv_T_{}", i + 1), fmt::format("c_{}", i + 1),
                  Vec3d{inv.rows[0][i], inv.rows[1][i], inv.rows[2][i]},
                  fmt::format("row {} of (A⁻¹)ᵀ: normals go back by the inverse transpose", i + 1));
    }
    E n = d.sym(N);
    d.step("m", "m", tuple(dot(c[0], n), dot(c[1], n), dot(c[2], n)),
           "the normal taken back by the inverse transpose (not yet of unit length)");
    d.step("N", "N", d.sym("m") / norm(d.sym("m")), "the unit normal in the world");
  }
  d.conclude(Sentence(fmt::format("The unit normal of the {} at P is N = ", type))
                 .value(d.value("N"))
                 .text("."));
  return {SolutionPart{"", std::move(d).finish()}};
}

// The surface seen edge-on at P with the unit normal drawn one unit long.
Sketch NormalTask::sketch() const {
  Sketch f;
  Vec3d n = world_normal();
  Vec3d along = std::abs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  sketch_surface(f, point_, n, along - dot(along, n) * n, "N = " + sketch_vector(n));
  f.point(point_, Ink::kHit, "P");
  return f;
}

std::optional<SceneGivens> NormalTask::scene_givens() const {
  SceneGivens g;
  g.objects.push_back({"", object_.get(), nullptr});
  g.point = point_;
  return g;
}

std::unique_ptr<Task> NormalKind::read(const Cursor& problem) { return NormalTask::read(problem); }

std::vector<PartSpec> NormalKind::parts() {
  using C = Comparison;
  return {{part_names::kNormal, "the outward unit normal at the point (any positive multiple)", 1,
           C::kDirection},
          {"object_normal", "a transformed object's normal in object space, before (A⁻¹)ᵀ", 0,
           C::kDirection}};
}

nlohmann::json NormalKind::answer_form(const Problem& p) {
  nlohmann::json fields = nlohmann::json::array(
      {form::field<field_types::Vector>("normal", "The outward unit normal at P")});
  if (p.task->answer().contains("object_normal")) {
    fields.push_back(form::field<field_types::Vector>("object_normal",
                                                      "The normal in object space, before (A⁻¹)ᵀ"));
  }
  return form::fields(fields);
}

std::string_view NormalKind::schema() {
  return R"json({
  "required": [
    "object",
    "point"
  ],
  "properties": {
    "object": {
      "$ref": "#/$defs/object"
    },
    "point": {
      "$ref": "#/$defs/vec3"
    }
  }
})json";
}

}  // namespace raygrade
