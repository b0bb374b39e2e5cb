// Transforms: reading the steps, composing them, and moving rays and normals between spaces.
#include "shapes/transform.h"

#include <cmath>
#include <numbers>

#include "derivation/number_format.h"

namespace raygrade {

Affine Affine::then(const Affine& next) const {
  // next(this(p)) = N·(A·p + b) + c = (N·A)·p + (N·b + c)
  Affine out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      out.rows[i][j] = next.rows[i][0] * rows[0][j] + next.rows[i][1] * rows[1][j] +
                       next.rows[i][2] * rows[2][j];
    }
  }
  out.translation = next.linear(translation) + next.translation;
  return out;
}

double Affine::determinant() const { return dot(rows[0], cross(rows[1], rows[2])); }

Affine Affine::transpose_linear() const {
  Affine out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.rows[i][j] = rows[j][i];
  }
  return out;
}

Affine Affine::inverse() const {
  // A⁻¹ = adj(A)/det(A): the columns of the adjugate are cross products of A's rows.
  double det = determinant();
  Vec3d c0 = cross(rows[1], rows[2]), c1 = cross(rows[2], rows[0]), c2 = cross(rows[0], rows[1]);
  Affine out;
  for (int i = 0; i < 3; ++i) out.rows[i] = Vec3d{c0[i], c1[i], c2[i]} / det;
  out.translation = -out.linear(translation);
  return out;
}

bool Affine::is_identity() const {
  return rows[0] == Vec3d{1, 0, 0} && rows[1] == Vec3d{0, 1, 0} && rows[2] == Vec3d{0, 0, 1} &&
         translation == Vec3d{};
}

Ray Transform::ray_to_object(const Ray& world) const {
  Ray r = world;
  r.origin = to_object.point(world.origin);
  r.direction = to_object.linear(world.direction);
  return r;
}

Vec3d Transform::normal_to_world_unit(const Vec3d& n) const {
  return normalized(normal_to_world.linear(n));
}

Intersection Transform::hits_to_world(const Ray& world, Intersection x) const {
  for (Hit& h : x.hits) {
    // t is the world ray's t: the direction went into object space by A⁻¹ without normalizing.
    h.point = world.at(h.t);
    h.normal = normal_to_world_unit(h.normal);
  }
  return x;
}

namespace {

// Whether the linear part of `a` is singular up to rounding: a zero row, rows that are
// parallel within kSingularRelative (the determinant of the rows scaled to unit length), or an
// inverse beyond double's range (scales of 1e-200 whose determinant underflows).
bool singular(const Affine& a) {
  Affine unit;
  for (int i = 0; i < 3; ++i) {
    double len = length(a.rows[i]);
    if (!(len > 0) || !std::isfinite(len)) return true;
    unit.rows[i] = a.rows[i] / len;
  }
  if (!(std::abs(unit.determinant()) > kSingularRelative)) return true;
  Affine inv = a.inverse();
  for (const auto& r : inv.rows) {
    if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z)) return true;
  }
  return false;
}

// cos and sin of an angle in degrees, exact at the quarter turns: cos(π/2) in double is
// 6.1e-17, not 0, and a box turned 90° would show a slab of d_y = 6.1e-17 and t = −8e15 in its
// worked solution. Other angles are computed from their remainder modulo 360.
std::pair<double, double> cos_sin_degrees(double degrees) {
  double r = std::fmod(degrees, 360.0);  // exact
  if (r < 0) r += 360;
  if (r == 0 || r == 360) return {1, 0};  // 360 when a tiny negative angle rounds up
  if (r == 90) return {0, 1};
  if (r == 180) return {-1, 0};
  if (r == 270) return {0, -1};
  double a = r * std::numbers::pi / 180;
  return {std::cos(a), std::sin(a)};
}

Affine step_matrix(const TransformStep& s) {
  Affine m;
  if (s.op == "translate") {
    m.translation = s.vector;
  } else if (s.op == "scale") {
    m.rows = {Vec3d{s.vector.x, 0, 0}, Vec3d{0, s.vector.y, 0}, Vec3d{0, 0, s.vector.z}};
  } else if (s.op == "matrix") {
    m.rows = s.rows;
  } else {
    // Rodrigues' rotation formula about the unit axis k, by the right-hand rule.
    Vec3d k = normalized(s.vector);
    auto [c, sn] = cos_sin_degrees(s.degrees);
    double v = 1 - c;
    m.rows = {Vec3d{c + k.x * k.x * v, k.x * k.y * v - k.z * sn, k.x * k.z * v + k.y * sn},
              Vec3d{k.y * k.x * v + k.z * sn, c + k.y * k.y * v, k.y * k.z * v - k.x * sn},
              Vec3d{k.z * k.x * v - k.y * sn, k.z * k.y * v + k.x * sn, c + k.z * k.z * v}};
  }
  return m;
}

}  // namespace

Transform read_transform(const Cursor& list) {
  Transform t;
  for (const auto& item : list.items()) {
    if (!item.is_object() || item.json().size() != 1) {
      item.fail("a transform step is an object with one key: translate, rotate, scale or matrix",
                "type");
    }
    TransformStep s;
    if (item.has("translate")) {
      s.op = "translate";
      s.vector = item.at("translate").vec3();
    } else if (item.has("scale")) {
      s.op = "scale";
      Cursor c = item.at("scale");
      s.vector = c.json().is_number() ? Vec3d{c.number(), c.number(), c.number()} : c.vec3();
      if (s.vector.x == 0 || s.vector.y == 0 || s.vector.z == 0) {
        c.fail("a scale factor of 0 flattens the object", "degenerate");
      }
    } else if (item.has("rotate")) {
      s.op = "rotate";
      Cursor c = item.at("rotate");
      c.allow_only({"axis", "degrees"});
      s.vector = c.at("axis").nonzero_vec3();
      s.degrees = c.at("degrees").number();
    } else if (item.has("matrix")) {
      s.op = "matrix";
      Cursor c = item.at("matrix");
      auto rows = c.items();
      if (rows.size() != 3) c.fail("a matrix is a list of 3 rows of 3 numbers", "type");
      for (int i = 0; i < 3; ++i) s.rows[i] = rows[i].vec3();
      Affine m;
      m.rows = s.rows;
      if (singular(m)) c.fail("the matrix is singular: it has no inverse", "degenerate");
    } else {
      item.allow_only({"translate", "rotate", "scale", "matrix"});
      item.fail("a transform step is translate, rotate, scale or matrix", "type");
    }
    t.to_world = t.to_world.then(step_matrix(s));
    t.steps.push_back(s);
  }
  // Each step is invertible, but their product may round to a singular matrix (scales of
  // 1e-200 and 1e-200).
  if (singular(t.to_world)) list.fail("the transform is singular: it has no inverse", "degenerate");
  t.to_object = t.to_world.inverse();
  t.normal_to_world = t.to_object.transpose_linear();
  return t;
}

nlohmann::json Transform::to_json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : steps) {
    nlohmann::json v = nlohmann::json::array({s.vector.x, s.vector.y, s.vector.z});
    if (s.op == "rotate") {
      out.push_back({{"rotate", {{"axis", v}, {"degrees", s.degrees}}}});
    } else if (s.op == "matrix") {
      nlohmann::json rows = nlohmann::json::array();
      for (const auto& r : s.rows) rows.push_back({r.x, r.y, r.z});
      out.push_back({{"matrix", rows}});
    } else {
      out.push_back({{s.op, v}});
    }
  }
  return out;
}

std::string describe_transform(const Transform& t) {
  std::string out;
  for (const auto& s : t.steps) {
    if (!out.empty()) out += ", then ";
    if (s.op == "rotate") {
      out += fmt::format("rotate {}° about {}", format_number(s.degrees), format_vector(s.vector));
    } else if (s.op == "matrix") {
      out += fmt::format("the matrix with rows {}, {}, {}", format_vector(s.rows[0]),
                         format_vector(s.rows[1]), format_vector(s.rows[2]));
    } else {
      out += fmt::format("{} by {}", s.op, format_vector(s.vector));
    }
  }
  return out;
}

}  // namespace raygrade
