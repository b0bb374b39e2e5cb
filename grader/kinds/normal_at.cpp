// The normal kind: the surface normal at a given point, as the gradient of the object's
// surface there, in object space and back in the world.
#include "kinds/normal_at.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "derivation/number_format.h"
#include "kinds/intersect.h"
#include "kinds/sketch.h"
#include "shapes/flat.h"
#include "shapes/transformed.h"

namespace raygrade {
namespace {

Vec3d vec_of(const nlohmann::json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

std::vector<Vec3d> vertices_of(const nlohmann::json& j) {
  std::vector<Vec3d> out;
  for (const auto& v : j.at("vertices")) out.push_back(vec_of(v));
  return out;
}

// The nearest point to p of the segment a–b.
Vec3d nearest_on_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  Vec3d ab = b - a;
  double s = std::clamp(dot(p - a, ab) / length_squared(ab), 0.0, 1.0);
  return a + s * ab;
}

// A flat polygon: p projected on its plane, kept when inside, else the nearest edge point.
SurfacePoint nearest_flat(const std::vector<Vec3d>& v, const Vec3d& p) {
  Vec3d n = newell_normal(v);
  Vec3d u = normalized(n);
  Vec3d q = p - dot(p - v[0], u) * u;
  // Inside: q is on the inner side of every edge when the polygon is convex; in general, by
  // the winding of the edges around q (the sum of the angles they subtend is 2π inside).
  double winding = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    Vec3d a = v[i] - q, b = v[(i + 1) % v.size()] - q;
    winding += std::atan2(dot(cross(a, b), u), dot(a, b));
  }
  SurfacePoint s{q, n, "", ""};
  // The winding is 2π inside and 0 outside (π on an edge, where the edge point is as near).
  if (std::abs(winding) > std::numbers::pi) return s;
  double best = kInfinity;
  for (std::size_t i = 0; i < v.size(); ++i) {
    Vec3d e = nearest_on_segment(q, v[i], v[(i + 1) % v.size()]);
    if (length(e - p) < best) {
      best = length(e - p);
      s.nearest = e;
    }
  }
  return s;
}

struct Candidate {
  Vec3d nearest, normal;
  std::string part;
};

// The nearest of the candidates, and a second one as near within `tie` (a rim, an edge).
SurfacePoint nearest_of(const std::vector<Candidate>& cs, const Vec3d& p, double tie) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < cs.size(); ++i) {
    if (length(cs[i].nearest - p) < length(cs[best].nearest - p)) best = i;
  }
  SurfacePoint s{cs[best].nearest, cs[best].normal, cs[best].part, ""};
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (i != best && length(cs[i].nearest - p) <= length(cs[best].nearest - p) + tie) {
      s.other = cs[i].part;
    }
  }
  return s;
}

SurfacePoint nearest_cylinder(const nlohmann::json& j, const Vec3d& p, double tie) {
  Vec3d b = vec_of(j.at("base"));
  Vec3d a = normalized(vec_of(j.at("axis")));
  double r = j.at("radius").get<double>();
  Vec3d q = p - b;
  double y = dot(q, a);
  Vec3d radial = q - y * a;
  double rho = length(radial);
  // On the axis every direction across it is as near; take any.
  Vec3d out = rho > 0 ? radial / rho
                      : normalized(cross(a, std::abs(a.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0}));
  std::vector<Candidate> cs;
  std::optional<double> h;
  if (j.contains("height")) h = j.at("height").get<double>();
  double ys = h ? std::clamp(y, 0.0, *h) : y;
  cs.push_back({b + ys * a + r * out, radial, "side"});
  if (j.value("capped", false)) {
    Vec3d across = rho <= r ? radial : r * out;
    cs.push_back({b + across, -a, "bottom cap"});
    cs.push_back({b + *h * a + across, a, "top cap"});
  }
  return nearest_of(cs, p, tie);
}

SurfacePoint nearest_box(const nlohmann::json& j, const Vec3d& p, double tie) {
  Vec3d lo = vec_of(j.at("min")), hi = vec_of(j.at("max"));
  const char* axis[] = {"x", "y", "z"};
  std::vector<Candidate> cs;
  for (int i = 0; i < 3; ++i) {
    for (int side = 0; side < 2; ++side) {
      Vec3d q{std::clamp(p.x, lo.x, hi.x), std::clamp(p.y, lo.y, hi.y),
              std::clamp(p.z, lo.z, hi.z)};
      double face = side ? hi[i] : lo[i];
      q[i] = face;
      Vec3d n{};
      n[i] = side ? 1 : -1;
      cs.push_back({q, n, fmt::format("face {} = {}", axis[i], format_number(face))});
    }
  }
  return nearest_of(cs, p, tie);
}

}  // namespace

std::optional<SurfacePoint> nearest_surface(const Shape& primitive, const Vec3d& p) {
  nlohmann::json j = primitive.to_json();
  std::string type = j.at("type");
  double tie = kOnSurfaceRelative * std::max(1.0, primitive.extent());
  if (type == "sphere") {
    Vec3d c = vec_of(j.at("center"));
    double r = j.at("radius").get<double>();
    Vec3d pc = p - c;
    Vec3d dir = length(pc) > 0 ? normalized(pc) : Vec3d{0, 0, 1};
    return SurfacePoint{c + r * dir, pc, "", ""};
  }
  if (type == "plane") {
    Vec3d n = vec_of(j.at("normal"));
    Vec3d on = j.contains("point") ? vec_of(j.at("point"))
                                   : -j.at("d").get<double>() / length_squared(n) * n;
    return SurfacePoint{p - dot(p - on, n) / length_squared(n) * n, n, "", ""};
  }
  if (type == "triangle" || type == "polygon") return nearest_flat(vertices_of(j), p);
  if (type == "cylinder") return nearest_cylinder(j, p, tie);
  if (type == "box") return nearest_box(j, p, tie);
  return std::nullopt;
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
  std::optional<SurfacePoint> found = nearest_surface(task->primitive(), p);
  if (!found) {
    problem.at("object").at("type").fail(
        fmt::format("the normal kind takes a {}; not a {}", fmt::join(kNormalKindTypes, ", "),
                    task->primitive().type()),
        "unknown-type");
  }
  const SurfacePoint& s = *found;
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
    problem.at("point").fail(fmt::format("the point {} is the sphere's centre: it has no normal",
                                         format_vector(task->point_)),
                             "degenerate");
  }
  return task;
}

Vec3d NormalTask::world_normal() const {
  const Transform* m = transform();
  Vec3d p = m ? m->to_object.point(point_) : point_;
  Vec3d n = normalized(nearest_surface(primitive(), p)->normal);
  return m ? normalized(m->normal_to_world.linear(n)) : n;
}

std::optional<Vec3d> NormalTask::normal_by_matrix() const {
  const Transform* m = transform();
  if (!m) return std::nullopt;
  Vec3d n = normalized(nearest_surface(primitive(), m->to_object.point(point_))->normal);
  Vec3d wrong = normalized(m->to_world.linear(n));
  if (length(wrong - world_normal()) <= kOnSurfaceRelative) return std::nullopt;
  return wrong;
}

bool NormalTask::solid() const {
  std::string_view t = primitive().type();
  return t == "sphere" || t == "cylinder" || t == "box";
}

nlohmann::json NormalTask::answer() const {
  nlohmann::json j = {{"normal", vec_json(world_normal())}};
  if (const Transform* m = transform()) {
    j["object_normal"] =
        vec_json(normalized(nearest_surface(primitive(), m->to_object.point(point_))->normal));
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
  nlohmann::json j = primitive().to_json();
  std::string type = j.at("type");
  Vec3d p = m ? m->to_object.point(point_) : point_;
  SurfacePoint s = *nearest_surface(primitive(), p);
  std::string N = m ? "N_obj" : "N";
  std::string Nd = m ? "N'" : "N";
  if (type == "sphere") {
    E C = d.given("C", "C", vec_of(j.at("center")), "the sphere's centre");
    d.step("PC", m ? "P' − C" : "P − C", P - C,
           "from the centre to the point: the gradient of |X − C|² − r²");
    d.step(N, Nd, d.sym("PC") / norm(d.sym("PC")), "the outward unit normal");
  } else if (type == "plane") {
    E n = d.given("n", "n", vec_of(j.at("normal")), "the plane's normal as given");
    d.step(N, Nd, n / norm(n), "the same at every point of the plane");
  } else if (type == "triangle" || type == "polygon") {
    std::vector<Vec3d> v = vertices_of(j);
    std::vector<E> vs;
    for (std::size_t i = 0; i < v.size(); ++i) {
      vs.push_back(d.given(fmt::format("v{}", i), fmt::format("v_{}", i), v[i]));
    }
    if (v.size() == 3) {
      d.step("e1", "e_1", vs[1] - vs[0]);
      d.step("e2", "e_2", vs[2] - vs[0]);
      d.step("n", "n", cross(d.sym("e1"), d.sym("e2")), "by vertex order: e_1 × e_2");
    } else {
      E sum = cross(vs[0], vs[1]);
      for (std::size_t i = 1; i < v.size(); ++i) sum = sum + cross(vs[i], vs[(i + 1) % v.size()]);
      d.step("n", "n", sum, "Newell's normal: the sum of v_i × v_(i+1), by vertex order");
    }
    d.step(N, Nd, d.sym("n") / norm(d.sym("n")), "the same at every point of the face");
  } else if (type == "cylinder") {
    E B = d.given("B", "B", vec_of(j.at("base")), "the centre of the base");
    E a = d.given("a_hat", "â", normalized(vec_of(j.at("axis"))), "the unit axis");
    if (s.part == "side") {
      d.step("q", "q", P - B);
      d.step("y", "y", dot(d.sym("q"), a), "the height of P along the axis");
      d.step("radial", "q_⊥", d.sym("q") - d.sym("y") * a, "the part of q across the axis");
      d.step(N, Nd, d.sym("radial") / norm(d.sym("radial")), "the outward unit normal of the side");
    } else {
      d.step(N, Nd, s.part == "top cap" ? a : -a,
             fmt::format("P is on the {}: the normal is the axis, pointing out", s.part));
    }
  } else if (type == "box") {
    d.given(N, Nd, s.normal, fmt::format("P is on the {}: its outward normal", s.part));
  }
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

}  // namespace raygrade
