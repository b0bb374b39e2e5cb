// The interpolate kind: barycentric weights of a point of a triangle, then the vertices' normals
// and texture coordinates blended by them.
#include "kinds/interpolate.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/part_names.h"
#include "scenes/optics.h"
#include "shapes/surface_point.h"

namespace raygrade {
namespace {

constexpr std::array<const char*, 3> kLetter = {"a", "b", "c"};
constexpr std::array<const char*, 3> kVertex = {"A", "B", "C"};

// Below this length the blend of the unit vertex normals has no direction of its own: each of
// its components carries a rounding error of a few units of 1 (u ≈ 1.1e-16), so its direction
// is off by about 4u/|blend|, which at 1e-8 is under 1e-7, a ten-thousandth of the default
// relative tolerance; shorter, the direction is rounding's.
constexpr double kShortestBlend = 1e-8;

bool unit(const Vec3d& n) { return std::abs(length(n) - 1) <= kUnitLengthTolerance; }

// The weights of p in the triangle v: w_b and w_c are the shares of the sub-triangles' signed
// areas across from B and C, w_a the rest.
std::array<double, 3> weights_of(const std::array<Vec3d, 3>& v, const Vec3d& p) {
  Vec3d e1 = v[1] - v[0], e2 = v[2] - v[0], ap = p - v[0];
  Vec3d n = cross(e1, e2);
  double nn = dot(n, n);
  double wb = dot(cross(ap, e2), n) / nn;
  double wc = dot(cross(e1, ap), n) / nn;
  return {1 - wb - wc, wb, wc};
}

}  // namespace

InterpolateTask::InterpolateTask(std::array<Vec3d, 3> vertices, std::array<Vec3d, 3> normals,
                                 std::optional<std::array<Texcoord, 3>> texcoords, Vec3d point)
    : v_(vertices), n_(normals), uv_(texcoords), p_(point), w_(weights_of(vertices, point)) {}

std::unique_ptr<Task> InterpolateTask::read(const Cursor& problem) {
  auto three = [](const Cursor& list, const char* what) {
    auto items = list.items();
    if (items.size() != 3) {
      list.fail(fmt::format("a triangle has 3 {}, not {}", what, items.size()), "invalid");
    }
    return items;
  };
  std::array<Vec3d, 3> v, n;
  auto vertices = three(problem.at("vertices"), "vertices");
  auto normals = three(problem.at("normals"), "normals");
  for (int i = 0; i < 3; ++i) {
    v[i] = vertices[i].vec3();
    n[i] = normals[i].nonzero_vec3();
    // A normal whose length squared underflows cannot be made unit (1e-200: 1e-400 is 0).
    if (length_squared(n[i]) < std::numeric_limits<double>::min()) {
      normals[i].fail(fmt::format("the normal is too short to be made unit: its length squared "
                                  "underflows (to {})",
                                  format_number(length_squared(n[i]))),
                      "undefined-normal");
    }
  }
  Vec3d face = cross(v[1] - v[0], v[2] - v[0]);
  double scale = std::max({1.0, length(v[1] - v[0]), length(v[2] - v[0])});
  if (length(face) <= 1e-12 * scale * scale) {
    problem.at("vertices")
        .fail("the three vertices lie on one line: the triangle has no area", "invalid");
  }
  std::optional<std::array<Texcoord, 3>> uv;
  if (auto t = problem.find("texcoords")) {
    auto items = three(*t, "texture coordinates");
    std::array<Texcoord, 3> coords;
    for (int i = 0; i < 3; ++i) {
      auto uv_items = items[i].items();
      if (uv_items.size() != 2) {
        items[i].fail("a texture coordinate is two numbers, [u, v]", "invalid");
      }
      coords[i] = {uv_items[0].number(), uv_items[1].number()};
    }
    uv = coords;
  }
  Cursor at = problem.at("point");
  Vec3d p = at.vec3();
  double off = dot(p - v[0], face) / length(face);
  if (std::abs(off) > kOnSurfaceRelative * scale) {
    at.fail(fmt::format("the point is {} off the triangle's plane", format_number(std::abs(off))),
            "invalid");
  }
  auto task = std::make_unique<InterpolateTask>(v, n, uv, p);
  for (int i = 0; i < 3; ++i) {
    if (task->w_[i] < -kOnSurfaceRelative) {
      at.fail(fmt::format("the point is outside the triangle: its weight w_{} is {}", kLetter[i],
                          format_number(task->w_[i])),
              "invalid");
    }
  }
  double blended = length(task->blend());
  if (!(blended >= kShortestBlend)) {
    problem.at("normals").fail(
        fmt::format("the vertex normals cancel at the point: their blend there, w_a·N̂_a + "
                    "w_b·N̂_b + w_c·N̂_c, is {} long, too short to have a direction (under {})",
                    format_number(blended), format_number(kShortestBlend)),
        "undefined-normal");
  }
  return task;
}

Vec3d InterpolateTask::blend() const {
  Vec3d s{0, 0, 0};
  for (int i = 0; i < 3; ++i) s = s + w_[i] * normalized(n_[i]);
  return s;
}

nlohmann::json InterpolateTask::answer() const {
  Vec3d s = blend();
  nlohmann::json j = {{"barycentric", {w_[0], w_[1], w_[2]}}, {"normal", vec_json(normalized(s))}};
  if (uv_) {
    for (int k = 0; k < 2; ++k) {
      double x = 0;
      for (int i = 0; i < 3; ++i) x += w_[i] * (*uv_)[i][k];
      j[k == 0 ? "u" : "v"] = x;
    }
  }
  return j;
}

std::vector<SolutionPart> InterpolateTask::derive(std::string_view /*method*/,
                                                  const Overrides* overrides) const {
  Deriver d("barycentric", "Interpolating across a triangle", overrides);
  std::array<E, 3> V, N;
  for (int i = 0; i < 3; ++i) {
    V[i] = d.given(kVertex[i], kVertex[i], v_[i], fmt::format("vertex {}", kVertex[i]));
  }
  E P = d.given("P", "P", p_, "the point of the triangle");
  for (int i = 0; i < 3; ++i) {
    std::string name = fmt::format("N_{}", kLetter[i]);
    N[i] = d.given(name, name, n_[i], fmt::format("the normal at {}", kVertex[i]));
  }
  d.step("n", "n", cross(V[1] - V[0], V[2] - V[0]), "the face normal (B − A) × (C − A)");
  d.step("area", "area", norm(d.sym("n")) / 2, "the triangle's area: half the normal's length");
  // The sub-triangle across from each vertex: P with the other two, in the same turn. Its
  // area is signed (+ inside the triangle), half its cross product along the unit face normal.
  for (int i = 0; i < 3; ++i) {
    const E &b = V[(i + 1) % 3], &c = V[(i + 2) % 3];
    d.step(fmt::format("area_{}", kLetter[i]), fmt::format("area_{}", kLetter[i]),
           dot(cross(b - P, c - P), d.sym("n")) / (2 * norm(d.sym("n"))),
           fmt::format("the area of the triangle P{}{}, across from {}", kVertex[(i + 1) % 3],
                       kVertex[(i + 2) % 3], kVertex[i]));
  }
  for (int i = 0; i < 3; ++i) {
    d.step(fmt::format("w_{}", kLetter[i]), fmt::format("w_{}", kLetter[i]),
           d.sym(fmt::format("area_{}", kLetter[i])) / d.sym("area"),
           fmt::format("the share of the area across from {}", kVertex[i]));
  }
  d.step("w", "w", tuple(d.sym("w_a"), d.sym("w_b"), d.sym("w_c")),
         "the weights (w_a, w_b, w_c), summing to 1");
  std::array<E, 3> Nh = N;
  for (int i = 0; i < 3; ++i) {
    if (unit(n_[i])) continue;
    std::string name = fmt::format("N_{}_hat", kLetter[i]);
    d.step(name, name, N[i] / norm(N[i]), "a vertex normal is blended as a unit vector");
    Nh[i] = d.sym(name);
  }
  E sum = d.sym("w_a") * Nh[0] + d.sym("w_b") * Nh[1] + d.sym("w_c") * Nh[2];
  d.step("n_s", "n_s", sum, "the vertex normals blended by the weights");
  Value nh = d.step("n_hat", "n_hat", d.sym("n_s") / norm(d.sym("n_s")),
                    "a blend of unit vectors is shorter than 1: normalise it again");
  Sentence end("The smooth normal at P is n̂ = ");
  end.value(nh);
  if (uv_) {
    // Every coordinate given first: u and v are worked alike, from the same table.
    std::array<std::array<E, 3>, 2> at;
    for (int k = 0; k < 2; ++k) {
      const char* c = k == 0 ? "u" : "v";
      for (int i = 0; i < 3; ++i) {
        std::string name = fmt::format("{}_{}", c, kLetter[i]);
        at[k][i] = d.given(name, name, (*uv_)[i][k],
                           fmt::format("the texture coordinate {} at {}", c, kVertex[i]));
      }
    }
    for (int k = 0; k < 2; ++k) {
      const char* c = k == 0 ? "u" : "v";
      d.step(c, c, d.sym("w_a") * at[k][0] + d.sym("w_b") * at[k][1] + d.sym("w_c") * at[k][2],
             fmt::format("{} blended by the same weights", c));
    }
    end.text(", and its texture coordinate is (u, v) = (")
        .value(d.value("u"))
        .text(", ")
        .value(d.value("v"))
        .text(")");
  }
  end.text(".");
  d.conclude(end);
  return {SolutionPart{"", std::move(d).finish()}};
}

// The triangle, each vertex's normal, the point and its smooth normal, each normal drawn at a
// fifth of the triangle's size.
Sketch InterpolateTask::sketch() const {
  Sketch f;
  f.path({v_[0], v_[1], v_[2]}, true, Ink::kObject);
  double size = std::max({length(v_[1] - v_[0]), length(v_[2] - v_[0]), length(v_[2] - v_[1])});
  double shown = size / 5;
  for (int i = 0; i < 3; ++i) {
    f.point(v_[i], Ink::kPoint, kVertex[i]);
    f.arrow(v_[i], v_[i] + shown * normalized(n_[i]), Ink::kGuide, fmt::format("N_{}", kLetter[i]));
  }
  f.point(p_, Ink::kHit, "P");
  nlohmann::json a = answer();
  Vec3d nh{a["normal"][0], a["normal"][1], a["normal"][2]};
  f.arrow(p_, p_ + shown * nh, Ink::kRay, "n̂");
  return f;
}

std::optional<SceneGivens> InterpolateTask::scene_givens() const {
  SceneGivens g;
  g.point = p_;
  g.surface.emplace();
  g.surface->vertices = v_;
  g.surface->vertex_normals = n_;
  return g;
}

std::unique_ptr<Task> InterpolateKind::read(const Cursor& problem) {
  return InterpolateTask::read(problem);
}

std::vector<PartSpec> InterpolateKind::parts() {
  using C = Comparison;
  return {{part_names::kNormal, "the smooth normal at the point, as a unit vector", 2,
           C::kUnitDirection},
          {part_names::kBarycentric, "the point's weights (w_a, w_b, w_c)", 1, C::kPoint},
          {part_names::kU, "the texture coordinate u at the point (when the vertices have them)", 0,
           C::kScalar},
          {part_names::kV, "the texture coordinate v at the point", 0, C::kScalar}};
}

nlohmann::json InterpolateKind::answer_form(const Problem& /*p*/) {
  return form::fields(
      {form::field<field_types::Vector>("normal", "The smooth unit normal at P"),
       form::field<field_types::Vector>("barycentric", "The weights (w_a, w_b, w_c) of P"),
       form::field<field_types::Number>("u", "The texture coordinate u at P"),
       form::field<field_types::Number>("v", "The texture coordinate v at P")});
}

std::string_view InterpolateKind::schema() {
  return R"json({
  "required": ["vertices", "normals", "point"],
  "properties": {
    "vertices": {"type": "array", "items": {"$ref": "#/$defs/vec3"}, "minItems": 3,
                 "maxItems": 3, "description": "A, B and C"},
    "normals": {"type": "array", "items": {"$ref": "#/$defs/nonzero_vec3"}, "minItems": 3,
                "maxItems": 3, "description": "the normals at A, B and C (made unit first)"},
    "texcoords": {"type": "array", "minItems": 3, "maxItems": 3,
                  "items": {"type": "array", "items": {"$ref": "#/$defs/number"},
                            "minItems": 2, "maxItems": 2},
                  "description": "the texture coordinates [u, v] at A, B and C"},
    "point": {"$ref": "#/$defs/vec3", "description": "a point of the triangle"},
    "expected": {"type": "object", "additionalProperties": false,
                 "properties": {"normal": {"$ref": "#/$defs/vec3"},
                                "barycentric": {"$ref": "#/$defs/vec3"},
                                "u": {"$ref": "#/$defs/number"},
                                "v": {"$ref": "#/$defs/number"}}}
  }
})json";
}

}  // namespace raygrade
