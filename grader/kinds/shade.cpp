// The shade kind.
#include "kinds/shade.h"

#include "derivation/number_format.h"
#include "kinds/sketch.h"
#include "scenes/optics.h"

namespace raygrade {
namespace {

Vec3d to_light(const Light& l, const Vec3d& p) {
  return normalized(l.type == LightType::kPoint ? l.position - p : -l.direction);
}

}  // namespace

std::unique_ptr<Task> ShadeTask::read(const Cursor& problem) {
  Vec3d point = problem.at("point").vec3();
  Vec3d normal = problem.at("normal").nonzero_vec3();
  Vec3d eye = problem.at("eye").vec3();
  if (eye == point) problem.at("eye").fail("the eye is at the point itself", "degenerate");
  Material m = problem.has("material") ? read_material(problem.at("material")) : Material{};
  double ia = problem.number_or("ambient_light", 1);
  if (ia < 0) problem.at("ambient_light").fail("ambient_light must not be negative", "range");
  std::vector<ShadeLight> lights;
  auto items = problem.at("lights").items();
  for (std::size_t i = 0; i < items.size(); ++i) {
    Cursor c = items[i];
    // `blocked` belongs to the exercise, not to the light: read it, then the light without it.
    bool blocked = c.boolean_or("blocked", false);
    nlohmann::json rest = c.json();
    rest.erase("blocked");
    Cursor light(c.file(), &rest, c.path());
    lights.push_back({read_light(light, static_cast<int>(i)), blocked});
  }
  return std::make_unique<ShadeTask>(point, normalized(normal), eye, m, ia, std::move(lights));
}

nlohmann::json ShadeTask::answer() const {
  Vec3d v = normalized(eye_ - point_);
  double diffuse = 0, specular = 0;
  bool any = false;
  nlohmann::json per = nlohmann::json::array();
  for (const auto& sl : lights_) {
    Vec3d l = to_light(sl.light, point_);
    PhongLight p =
        phong_light(normal_, l, v, sl.light.intensity, m_.diffuse, m_.specular, m_.shininess);
    bool reaches = !sl.blocked && p.n_dot_l > 0;
    any |= reaches;
    nlohmann::json j = {{"light", sl.light.name},
                        {"n_dot_l", p.n_dot_l},
                        {"r_dot_v", p.r_dot_v},
                        {"reaches", reaches},
                        {"diffuse", reaches ? p.diffuse : 0.0},
                        {"specular", reaches ? p.specular : 0.0}};
    if (reaches) {
      diffuse += p.diffuse;
      specular += p.specular;
    }
    per.push_back(std::move(j));
  }
  double ambient = m_.ambient * ambient_light_;
  // A term whose coefficient is 0 does not apply, whatever the lights do.
  nlohmann::json terms = {"ambient"};
  if (any && m_.diffuse > 0) terms.push_back("diffuse");
  if (any && m_.specular > 0) terms.push_back("specular");
  return {{"ambient", ambient},   {"diffuse", diffuse},
          {"specular", specular}, {"intensity", ambient + diffuse + specular},
          {"lights", per},        {"terms", terms}};
}

std::vector<SolutionPart> ShadeTask::derive(std::string_view /*method*/,
                                            const Overrides* overrides) const {
  Deriver d("phong", "The Phong model, term by term", overrides);
  E P = d.given("P", "P", point_, "the point");
  E N = d.given("N", "N", normal_, "the unit normal");
  E Eye = d.given("E", "E", eye_, "the eye");
  d.step("V", "V", (Eye - P) / norm(Eye - P), "toward the viewer");
  E ka = d.given("k_a", "k_a", m_.ambient);
  E ia = d.given("I_a", "I_a", ambient_light_, "the ambient light");
  std::vector<E> sum;
  d.step("ambient", "I_amb", ka * ia, "the ambient term always applies");
  sum.push_back(d.sym("ambient"));
  for (std::size_t k = 0; k < lights_.size(); ++k) {
    const Light& l = lights_[k].light;
    std::string i = std::to_string(k + 1);
    if (l.type == LightType::kPoint) {
      E pos = d.given("S_" + i, "S_" + i, l.position, fmt::format("light {}", l.name));
      d.step("L_" + i, "L_" + i, (pos - P) / norm(pos - P), "toward the light");
    } else {
      E dir = d.given("dL_" + i, "d_L" + i, l.direction, fmt::format("light {}", l.name));
      d.step("L_" + i, "L_" + i, -dir / norm(dir), "toward the light");
    }
    Value nl = d.step("NL_" + i, "N·L_" + i, dot(N, d.sym("L_" + i)));
    if (lights_[k].blocked || nl.scalar <= 0) {
      d.note(
          lights_[k].blocked
              ? fmt::format("The shadow ray to {} is blocked: no diffuse or specular term.", l.name)
              : "N·L ≤ 0: the light is behind the surface.");
      continue;
    }
    E ip = d.given("Ip_" + i, "I_p" + i, l.intensity);
    d.step("diffuse_" + i, "I_d" + i, m_.diffuse * ip * d.sym("NL_" + i),
           fmt::format("k_d·I_p·(N·L) with k_d = {}", format_number(m_.diffuse)));
    sum.push_back(d.sym("diffuse_" + i));
    if (m_.specular == 0) {
      d.note(fmt::format("k_s = 0: no specular term for {}.", l.name));
      continue;
    }
    d.step("R_" + i, "R_" + i, 2 * d.sym("NL_" + i) * N - d.sym("L_" + i),
           "the mirror direction of the light");
    Value rv = d.step("RV_" + i, "R·V_" + i, dot(d.sym("R_" + i), d.sym("V")));
    PhongLight p = phong_light(normal_, normalized(d.value("L_" + i).vector), d.value("V").vector,
                               l.intensity, m_.diffuse, m_.specular, m_.shininess);
    d.given("specular_" + i, "I_s" + i, rv.scalar > 0 ? p.specular : 0.0,
            rv.scalar > 0 ? fmt::format("k_s·I_p·(R·V)^n with k_s = {}, n = {}",
                                        format_number(m_.specular), format_number(m_.shininess))
                          : "R·V ≤ 0: no highlight");
    sum.push_back(d.sym("specular_" + i));
  }
  E total = sum.front();
  for (std::size_t k = 1; k < sum.size(); ++k) total = total + sum[k];
  Value t = d.step("I", "I", total, "the sum of the terms that apply");
  d.conclude(fmt::format("The intensity at P is I = {}.", format_number(t.scalar)));
  return {SolutionPart{"", std::move(d).finish()}};
}

// The point on its surface seen edge-on, the unit vectors of the Phong model drawn from it one
// unit long: N, V toward the eye, and per light L toward it with its mirror direction R when
// the light reaches the point; a light that does not (blocked, or behind the surface) is drawn
// dotted with the reason. The view puts N up and V's part along the surface to the right.
Sketch ShadeTask::sketch() const {
  Sketch f;
  Vec3d v = normalized(eye_ - point_);
  sketch_surface(f, point_, normal_, v, "N");
  f.point(point_, Ink::kHit, "P");
  f.arrow(point_, point_ + v, Ink::kPoint, "V (to the eye)");
  for (std::size_t k = 0; k < lights_.size(); ++k) {
    const ShadeLight& sl = lights_[k];
    // The names of the worked steps (L_1, R_1), with the light's own name.
    std::string i = std::to_string(k + 1);
    Vec3d l = to_light(sl.light, point_);
    double n_dot_l = dot(normal_, l);
    if (sl.blocked || n_dot_l <= 0) {
      f.arrow(point_, point_ + l, Ink::kMiss,
              fmt::format("L_{}, light {}: {}", i, sl.light.name,
                          sl.blocked ? "blocked" : "behind the surface"));
      continue;
    }
    f.arrow(point_, point_ + l, Ink::kRay, fmt::format("L_{}, light {}", i, sl.light.name));
    if (m_.specular > 0) f.arrow(point_, point_ + 2 * n_dot_l * normal_ - l, Ink::kGuide, "R_" + i);
  }
  return f;
}

}  // namespace raygrade
