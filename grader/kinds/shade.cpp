// The shade kind.
#include "kinds/shade.h"

#include <algorithm>

#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/part_names.h"
#include "kinds/sketch.h"
#include "kinds/swatch.h"
#include "scenes/optics.h"
#include "shapes/transform.h"

namespace raygrade {
namespace {

Vec3d to_light(const Light& l, const Vec3d& p) {
  return normalized(l.type == LightType::kPoint ? l.position - p : -l.direction);
}

// a·b for two quantities of a derivation: a colour times a colour is the componentwise product
// a ⊙ b; otherwise a number scales a number or a colour.
E times(const E& a, const Value& av, const E& b, const Value& bv) {
  if (!av.is_vector() || !bv.is_vector()) return a * b;
  return hadamard(a, b);
}

// A coefficient of the material as the derivation gives it: a number, or a colour.
Value coefficient_value(double v, const std::optional<Vec3d>& rgb) {
  return rgb ? Value(*rgb) : Value(v);
}

// The sum of a term over the lights as a step (with one light, its term is the sum).
std::optional<E> sum_of_terms(Deriver& d, const std::vector<E>& terms, const std::string& name,
                              const std::string& shown, const std::string& why) {
  if (terms.empty()) return std::nullopt;
  if (terms.size() == 1) return terms.front();
  E total = terms.front();
  for (std::size_t k = 1; k < terms.size(); ++k) total = total + terms[k];
  d.step(name, shown, total, why);
  return d.sym(name);
}

}  // namespace

std::unique_ptr<Task> ShadeTask::read(const Cursor& problem) {
  Vec3d point = problem.at("point").vec3();
  Vec3d normal = problem.at("normal").nonzero_vec3();
  Vec3d eye = problem.at("eye").vec3();
  if (eye == point) problem.at("eye").fail("the eye is at the point itself", "degenerate");
  // A material's `colour` belongs to the point's shading, not to read_material: read it apart.
  std::optional<SurfaceColour> surface;
  Material m;
  if (problem.has("material")) {
    Cursor mc = problem.at("material");
    if (mc.is_object() && mc.has("colour")) surface = read_surface_colour(mc.at("colour"));
    nlohmann::json rest = mc.json();
    if (rest.is_object()) rest.erase("colour");
    m = read_material(Cursor(mc.file(), &rest, mc.path()));
  }
  Transform object;
  if (problem.has("object_transform")) {
    if (!surface) {
      problem.at("object_transform")
          .fail(
              "object_transform places the material's colour pattern: the material has no "
              "colour",
              "invalid");
    }
    object = read_transform(problem.at("object_transform"));
  }
  Intensity ia{1, std::nullopt};
  if (problem.has("ambient_light"))
    ia = read_intensity(problem.at("ambient_light"), "ambient_light");
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
  if (!surface) {
    return std::make_unique<ShadeTask>(point, normal, eye, m, ia, std::move(lights));
  }
  // The colour at the point: in the object's space, then the pattern's.
  Vec3d c = surface->uniform;
  if (surface->pattern) {
    Vec3d po = object.to_object.point(point);
    c = pattern_at(*surface->pattern, surface->pattern->transform.to_object.point(po)).colour;
  }
  Material folded = m;
  Vec3d ka = Intensity{m.ambient, m.ambient_rgb}.rgb();
  Vec3d kd = Intensity{m.diffuse, m.diffuse_rgb}.rgb();
  folded.ambient_rgb = Vec3d{ka.x * c.x, ka.y * c.y, ka.z * c.z};
  folded.diffuse_rgb = Vec3d{kd.x * c.x, kd.y * c.y, kd.z * c.z};
  folded.ambient = std::max({folded.ambient_rgb->x, folded.ambient_rgb->y, folded.ambient_rgb->z});
  folded.diffuse = std::max({folded.diffuse_rgb->x, folded.diffuse_rgb->y, folded.diffuse_rgb->z});
  auto task = std::make_unique<ShadeTask>(point, normal, eye, folded, ia, std::move(lights));
  task->set_surface(*surface, object, m);
  return task;
}

void ShadeTask::set_surface(SurfaceColour surface, Transform object, Material base) {
  surface_ = std::move(surface);
  object_ = std::move(object);
  base_ = base;
  object_point_ = object_.to_object.point(point_);
  if (surface_->pattern) {
    pattern_point_ = surface_->pattern->transform.to_object.point(object_point_);
    surface_value_ = pattern_at(*surface_->pattern, pattern_point_);
  } else {
    surface_value_.colour = surface_->uniform;
  }
}

// The pattern's steps as The Ray Tracer Challenge works them: the point in object space, then
// in pattern space, then the count whose parity picks a or b (or the gradient's blend).
void ShadeTask::surface_steps(Deriver& d) const {
  const PatternValue& v = surface_value_;
  if (!surface_->pattern) {
    d.given("C", "C", surface_->uniform, "the material's colour");
    return;
  }
  const Pattern& p = *surface_->pattern;
  d.note(fmt::format("The material's colour is a {} pattern of a = {} and b = {}.",
                     to_string(p.type), colour_text(p.a), colour_text(p.b)));
  if (!object_.identity()) {
    d.given("P_o", "P_o", object_point_,
            fmt::format("P in the object's space, M⁻¹P (M: {})", describe_transform(object_)));
  }
  if (!p.transform.identity()) {
    d.given("P_pat", "P_pat", pattern_point_,
            fmt::format("in the pattern's space, T⁻¹ of the object-space point (T: {})",
                        describe_transform(p.transform)));
  }
  const Vec3d& q = pattern_point_;
  std::string parity = fmt::format("{} is {}: the colour {}", format_number(v.floor_sum),
                                   v.even ? "even" : "odd", v.even ? "a" : "b");
  switch (p.type) {
    case PatternType::kStripe:
      d.given("floor_x", "⌊x⌋", v.floor_sum, fmt::format("x = {}; {}", format_number(q.x), parity));
      break;
    case PatternType::kGradient: {
      d.given("floor_x", "⌊x⌋", v.floor_sum, fmt::format("x = {}", format_number(q.x)));
      d.step("frac", "f", E(q.x) - d.sym("floor_x"), "x − ⌊x⌋, how far across the band");
      E A = d.given("a", "a", p.a);
      E B = d.given("b", "b", p.b);
      d.step("C", "C", A + (B - A) * d.sym("frac"), "a + (b − a)·f");
      return;
    }
    case PatternType::kRing:
      d.step("r", "r", sqrt(square(E(q.x)) + square(E(q.z))),
             "√(x² + z²), the distance from the y axis");
      d.given("floor_r", "⌊r⌋", v.floor_sum, parity);
      break;
    case PatternType::kCheckers: {
      E fx = d.given("floor_x", "⌊x⌋", std::floor(q.x), fmt::format("x = {}", format_number(q.x)));
      E fy = d.given("floor_y", "⌊y⌋", std::floor(q.y), fmt::format("y = {}", format_number(q.y)));
      E fz = d.given("floor_z", "⌊z⌋", std::floor(q.z), fmt::format("z = {}", format_number(q.z)));
      d.step("floor_sum", "s", fx + fy + fz, "⌊x⌋ + ⌊y⌋ + ⌊z⌋; " + parity);
      break;
    }
  }
  d.given("C", "C", v.colour, v.even ? "the colour a" : "the colour b");
}

bool ShadeTask::colour() const {
  if (ambient_light_.colour || has_colour(m_)) return true;
  for (const auto& sl : lights_) {
    if (has_colour(sl.light)) return true;
  }
  return false;
}

// Channel by channel (one channel when nothing is a colour): a number stays a number.
nlohmann::json ShadeTask::answer() const {
  Vec3d v = normalized(eye_ - point_);
  bool rgb = colour();
  int channels = rgb ? 3 : 1;
  // k_s = 0: there is no specular term, and the answer does not list one.
  bool specular_applies = m_.specular > 0;
  Vec3d ambient{}, diffuse{}, specular{}, intensity{};
  bool any = false;
  nlohmann::json per = nlohmann::json::array();
  for (const auto& sl : lights_) {
    Vec3d l = to_light(sl.light, point_);
    Vec3d d{}, s{};
    PhongLight p;
    for (int c = 0; c < channels; ++c) {
      Material mc = channel(m_, c);
      p = phong_light(normal_, l, v, channel(sl.light, c).intensity, mc.diffuse, mc.specular,
                      m_.shininess);
      d[c] = p.diffuse;
      s[c] = p.specular;
    }
    bool reaches = !sl.blocked && p.n_dot_l > 0;
    any |= reaches;
    if (!reaches) d = s = Vec3d{};
    nlohmann::json j = {{"light", sl.light.name},
                        {"n_dot_l", p.n_dot_l},
                        {"r_dot_v", p.r_dot_v},
                        {"reaches", reaches},
                        {"diffuse", channels_json(d, rgb)}};
    if (specular_applies) j["specular"] = channels_json(s, rgb);
    diffuse = diffuse + d;
    specular = specular + s;
    per.push_back(std::move(j));
  }
  for (int c = 0; c < channels; ++c) {
    ambient[c] = channel(m_, c).ambient * ambient_light_.channel(c);
    intensity[c] = ambient[c] + diffuse[c] + specular[c];
  }
  // A term whose coefficient is 0 does not apply, whatever the lights do.
  nlohmann::json terms = {"ambient"};
  if (any && m_.diffuse > 0) terms.push_back("diffuse");
  if (any && specular_applies) terms.push_back("specular");
  nlohmann::json out = {{"ambient", channels_json(ambient, rgb)},
                        {"diffuse", channels_json(diffuse, rgb)},
                        {"intensity", channels_json(intensity, rgb)},
                        {"lights", per},
                        {"terms", terms}};
  if (specular_applies) out["specular"] = channels_json(specular, rgb);
  if (surface_) out["colour"] = channels_json(surface_value_.colour, true);
  return out;
}

std::vector<SolutionPart> ShadeTask::derive(std::string_view /*method*/,
                                            const Overrides* overrides) const {
  Deriver d("phong", "The Phong model, term by term", overrides);
  bool rgb = colour();
  E P = d.given("P", "P", point_, "the point");
  E N = d.given("n", "N_0", given_normal_, "the surface normal as given");
  d.step("N", "N", N / norm(N), "the unit normal");
  N = d.sym("N");
  E Eye = d.given("E", "E", eye_, "the eye");
  d.step("V", "V", (Eye - P) / norm(Eye - P), "toward the viewer");
  if (rgb) {
    d.note(
        "Intensities are colours [r, g, b], worked channel by channel: a number acts on every "
        "channel alike, and a colour times a colour is the componentwise product ⊙.");
  }
  // A material's coefficient as given, or (with a surface colour) times the colour C.
  auto coefficient = [&](const std::string& name, const std::string& shown, double base,
                         const std::optional<Vec3d>& base_rgb, double folded,
                         const std::optional<Vec3d>& folded_rgb) -> std::pair<E, Value> {
    if (!surface_) {
      Value v = coefficient_value(folded, folded_rgb);
      return {d.given(name, shown, v), v};
    }
    Value b = coefficient_value(base, base_rgb);
    E g = d.given(name + "_0", shown + "0", b, "as given");
    Value c = d.value("C");
    Value v = d.step(name, shown, times(g, b, d.sym("C"), c), shown + " ⊙ C");
    return {d.sym(name), v};
  };
  if (surface_) {
    surface_steps(d);
    d.note(fmt::format(
        "The surface colour C multiplies the ambient and diffuse coefficients (k_a = {}, k_d = "
        "{} as given); the highlight keeps the light's colour.",
        colour_text(Intensity{base_.ambient, base_.ambient_rgb}.rgb()),
        colour_text(Intensity{base_.diffuse, base_.diffuse_rgb}.rgb())));
  }
  auto [ka, ka_v] =
      coefficient("k_a", "k_a", base_.ambient, base_.ambient_rgb, m_.ambient, m_.ambient_rgb);
  // With colours, the lights are colours too (a number as [I, I, I]).
  Value ia_v = rgb ? Value(ambient_light_.rgb()) : Value(ambient_light_.value);
  E ia = d.given("I_a", "I_a", ia_v, "the ambient light");
  d.step("ambient", "I_amb", times(ka, ka_v, ia, ia_v),
         ka_v.is_vector() ? "k_a ⊙ I_a: the ambient term always applies"
                          : "the ambient term always applies");
  auto [kd, kd_v] =
      coefficient("k_d", "k_d", base_.diffuse, base_.diffuse_rgb, m_.diffuse, m_.diffuse_rgb);
  bool specular = m_.specular > 0;
  E ks, shininess;
  Value ks_v;
  if (specular) {
    ks_v = coefficient_value(m_.specular, m_.specular_rgb);
    ks = d.given("k_s", "k_s", ks_v);
    shininess = d.given("shininess", "n", m_.shininess, "the shininess exponent");
  }
  std::vector<E> diffuse, highlight;
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
    Value nl_v = d.step("NL_" + i, "N·L_" + i, dot(N, d.sym("L_" + i)));
    E nl = d.sym("NL_" + i);
    d.step("R_" + i, "R_" + i, 2 * nl * N - d.sym("L_" + i), "the mirror direction of the light");
    d.step("RV_" + i, "R·V_" + i, dot(d.sym("R_" + i), d.sym("V")));
    bool blocked = lights_[k].blocked;
    E s = d.given("shadow_" + i, "s_" + i, Value(blocked ? 0 : 1),
                  blocked ? fmt::format("the shadow ray to {} is blocked", l.name)
                          : fmt::format("the shadow ray reaches {}", l.name));
    if (nl_v.scalar <= 0) d.note("N·L ≤ 0: the light is behind the surface.");
    Value ip_v = rgb ? Value(l.colour ? *l.colour : Vec3d{l.intensity, l.intensity, l.intensity})
                     : Value(l.intensity);
    E ip = d.given("Ip_" + i, "I_p" + i, ip_v);
    // Whether the light reaches P is the verdict on its diffuse factor, so that the clamp left
    // out counts a light below the horizon in its verdict as in its terms.
    d.step("reaches_" + i, "reaches_" + i, compare(s * max({E(0), nl}), "!=", E(0)),
           "s·max(0, N·L) ≠ 0: the light reaches P when it is not blocked and N·L > 0");
    d.step("diffuse_" + i, "I_d" + i, s * times(kd, kd_v, ip, ip_v) * max({E(0), nl}),
           kd_v.is_vector() ? "s·(k_d ⊙ I_p)·max(0, N·L): none when blocked or behind"
                            : "s·k_d·I_p·max(0, N·L): none when blocked or behind");
    diffuse.push_back(d.sym("diffuse_" + i));
    if (!specular) {
      d.note(fmt::format("k_s = 0: no specular term for {}.", l.name));
      continue;
    }
    d.step("specular_" + i, "I_s" + i,
           s * times(ks, ks_v, ip, ip_v) * pow(max({E(0), d.sym("RV_" + i)}), shininess) *
               d.sym("reaches_" + i),
           "s·k_s·I_p·max(0, R·V)^n, none when the light does not reach P (a verdict counts "
           "as 1 or 0): no highlight when R·V ≤ 0");
    highlight.push_back(d.sym("specular_" + i));
  }
  std::vector<E> parts = {d.sym("ambient")};
  if (auto x = sum_of_terms(d, diffuse, "diffuse", "I_d", "the diffuse terms of every light")) {
    parts.push_back(*x);
  }
  if (auto x = sum_of_terms(d, highlight, "specular", "I_s", "the specular terms of every light")) {
    parts.push_back(*x);
  }
  E total = parts.front();
  for (std::size_t k = 1; k < parts.size(); ++k) total = total + parts[k];
  Value t = d.step("I", "I", total, "the sum of the terms");
  d.conclude(rgb ? fmt::format("The colour at P is I = {} (r, g, b).", colour_text(t.vector))
                 : fmt::format("The intensity at P is I = {}.", format_number(t.scalar)));
  if (!rgb) return {SolutionPart{"", std::move(d).finish()}};
  // The colours of the terms and their sum as swatches.
  std::vector<std::pair<std::string, Vec3d>> swatches = {{"I_amb", d.value("ambient").vector}};
  for (std::size_t k = 1; k <= lights_.size(); ++k) {
    for (auto [term, shown] : {std::pair{"diffuse_", "I_d"}, std::pair{"specular_", "I_s"}}) {
      auto it = d.env().find(term + std::to_string(k));
      if (it != d.env().end() && it->second.is_vector()) {
        swatches.emplace_back(shown + std::to_string(k), it->second.vector);
      }
    }
  }
  swatches.emplace_back("I", t.vector);
  return {SolutionPart{"", std::move(d).finish(), {swatch_figure(swatches)}}};
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

std::optional<SceneGivens> ShadeTask::scene_givens() const {
  SceneGivens g;
  g.point = point_;
  g.surface.emplace();
  g.surface->normal = given_normal_;
  g.surface->eye = eye_;
  for (const auto& l : lights_) {
    bool directional = l.light.type == LightType::kDirectional;
    g.lights.push_back({l.light.name, directional, l.light.position, l.light.direction});
  }
  return g;
}

std::unique_ptr<Task> ShadeKind::read(const Cursor& problem) { return ShadeTask::read(problem); }

std::vector<PartSpec> ShadeKind::parts() {
  using C = Comparison;
  PartSpec specular{part_names::kSpecular, "the sum of the specular terms", 0, C::kScalar};
  specular.zero_when_absent = true;  // k_s = 0: 0 is the term, as much as none
  specular.why_absent = [](const nlohmann::json&,
                           const std::function<std::string(double)>&) -> std::string {
    return "k_s = 0: the material has no specular term, so there is none to give.";
  };
  PartSpec colour{"colour",
                  "the material's colour at the point (a pattern's colour there), [r, g, b]", 0,
                  C::kScalar};
  colour.optional_when_absent = true;  // a material without a colour has none to give
  return {{part_names::kIntensity, "the Phong intensity", 1, C::kScalar},
          {"ambient", "the ambient term k_a·I_a", 0, C::kScalar},
          {part_names::kDiffuse, "the sum of the diffuse terms", 0, C::kScalar},
          specular,
          {part_names::kTerms, "which terms apply (ambient, diffuse, specular)", 0, C::kNames},
          {part_names::kLights,
           "per light: whether it reaches the point, N·L, R·V and its two terms", 0, C::kRows},
          colour};
}

nlohmann::json ShadeKind::answer_form(const Problem& p) {
  // With colours every term is [r, g, b]: three numbers, as a vector's field takes them.
  const auto* task = dynamic_cast<const ShadeTask*>(p.task.get());
  bool rgb = task && task->colour();
  const FieldTypeEntry term =
      rgb ? field_type_entry<field_types::Vector>() : field_type_entry<field_types::Number>();
  std::string unit = rgb ? " [r, g, b]" : "";
  nlohmann::json lights = form::field<field_types::Rows>("lights", "Each light");
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& n : form::names_of(p.source.value("lights", nlohmann::json()))) {
    rows.push_back({{"label", "light " + n}, {"fixed", {{"light", n}}}});
  }
  lights["rows"] = rows;
  lights["columns"] =
      nlohmann::json::array({form::field<field_types::Number>("n_dot_l", "N·L"),
                             form::field<field_types::Number>("r_dot_v", "R·V"),
                             form::field<field_types::YesNo>("reaches", "reaches the point?"),
                             form::field(term, "diffuse", "diffuse" + unit),
                             form::field(term, "specular", "specular" + unit)});
  nlohmann::json terms = form::field<field_types::Set>("terms", "The terms that apply");
  terms["options"] = nlohmann::json::array({"ambient", "diffuse", "specular"});
  return form::fields({form::field(term, "ambient", "The ambient term" + unit),
                       form::field(term, "diffuse", "The diffuse term" + unit),
                       form::field(term, "specular", "The specular term" + unit),
                       form::field(term, "intensity", "The intensity" + unit), lights, terms});
}

std::string_view ShadeKind::schema() {
  return R"json({
  "required": [
    "point",
    "normal",
    "eye",
    "lights"
  ],
  "properties": {
    "point": {
      "$ref": "#/$defs/vec3"
    },
    "normal": {
      "$ref": "#/$defs/nonzero_vec3"
    },
    "eye": {
      "$ref": "#/$defs/vec3"
    },
    "material": {
      "$ref": "#/$defs/material"
    },
    "ambient_light": {
      "$ref": "#/$defs/intensity"
    },
    "lights": {
      "type": "array",
      "items": {
        "type": "object",
        "description": "a light, and `blocked` when its shadow ray is blocked",
        "properties": {
          "name": {
            "type": "string"
          },
          "type": {
            "enum": [
              "point",
              "directional"
            ]
          },
          "position": {
            "$ref": "#/$defs/vec3"
          },
          "direction": {
            "$ref": "#/$defs/nonzero_vec3"
          },
          "intensity": {
            "$ref": "#/$defs/intensity"
          },
          "blocked": {
            "type": "boolean"
          }
        },
        "additionalProperties": false
      }
    },
    "object_transform": {
      "$ref": "#/$defs/transform",
      "description": "the transform of the object the point lies on, which places the material's colour pattern (docs/scenes.md, Patterns)"
    }
  }
})json";
}

}  // namespace raygrade
