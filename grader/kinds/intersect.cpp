// The intersect and first-hit kinds.
#include "kinds/intersect.h"

#include <set>

#include "accuracy/settle.h"
#include "derivation/number_format.h"
#include "kinds/form.h"
#include "kinds/part_names.h"
#include "kinds/sketch.h"
#include "shapes/primitives.h"

namespace raygrade {

std::unique_ptr<Task> IntersectTask::read(const Cursor& problem) {
  return std::make_unique<IntersectTask>(read_ray(problem.at("ray")),
                                         read_lone_object(problem.at("object")),
                                         problem.string_or("method", ""));
}

nlohmann::json IntersectTask::answer() const {
  Intersection x = object_->intersect(ray_);
  settle_nearest(*object_, ray_, x);
  return intersection_json(x);
}

std::optional<std::string> IntersectTask::level() const {
  Intersection x = object_->intersect(ray_);
  return settle_nearest(*object_, ray_, x);
}

std::vector<SolutionPart> IntersectTask::derive(std::string_view method,
                                                const Overrides* overrides) const {
  std::string_view m = method.empty() ? std::string_view(method_) : method;
  return {SolutionPart{"", object_->derive(ray_, m, overrides)}};
}

Sketch IntersectTask::sketch() const {
  Sketch f;
  object_->sketch(f, "");
  Intersection x = object_->intersect(ray_);
  sketch_ray(f, ray_, {object_.get()}, x.hits);
  for (const auto& h : x.hits) sketch_hit(f, h, Ink::kHit);
  return f;
}

std::optional<SceneGivens> IntersectTask::scene_givens() const {
  SceneGivens g;
  g.objects.push_back({"", object_.get(), nullptr});
  g.ray = ray_;
  return g;
}

std::unique_ptr<Shape> read_lone_object(const Cursor& object) {
  std::unique_ptr<Shape> shape = read_shape(object);
  if (auto name = object.find("name")) {
    name->fail("a name tells an object apart from others, and this kind has one object",
               "unused-key");
  }
  return shape;
}

std::vector<NamedShape> read_named_objects(const Cursor& list) {
  std::vector<NamedShape> out;
  std::set<std::string> names;
  auto items = list.items();
  if (items.empty()) list.fail("the list of objects is empty", "invalid");
  for (const auto& item : items) {
    std::string name = item.at("name").string();
    if (name.empty()) item.at("name").fail("the name must not be empty", "invalid");
    if (!names.insert(name).second) {
      item.at("name").fail(fmt::format("duplicate object name '{}'", name), "duplicate-name");
    }
    out.push_back(NamedShape{name, read_shape(item)});
  }
  return out;
}

std::unique_ptr<Task> FirstHitTask::read(const Cursor& problem) {
  return std::make_unique<FirstHitTask>(read_ray(problem.at("ray")),
                                        read_named_objects(problem.at("objects")),
                                        problem.string_or("method", ""));
}

// Two objects whose nearest hits agree within this many ulps of t are hit at the same t (a
// tie): each t comes from its own formula and rounds on its own.
constexpr double kTieRelative = 8 * 2.220446049250313e-16;

FirstHit first_hit(const Ray& ray, const std::vector<NamedShape>& objects) {
  FirstHit out;
  std::vector<Intersection> xs;
  std::vector<const Shape*> shapes;
  for (const auto& o : objects) {
    xs.push_back(o.shape->intersect(ray));
    shapes.push_back(o.shape.get());
  }
  // The adaptive ladder settles each decision and the order where the study covers every object.
  out.level = settle_first(shapes, ray, xs, out.index, out.tie);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (xs[i].hits.empty()) {
      out.nearest.emplace_back(std::nullopt);
      continue;
    }
    const Hit& h = xs[i].hits.front();
    out.nearest.emplace_back(h);
    if (out.level) continue;
    double tie = kTieRelative * std::max(1.0, std::abs(h.t));
    if (out.index >= 0 && std::abs(h.t - out.hit.t) <= tie) {
      out.tie = true;  // the first in the list keeps the name
    } else if (out.index < 0 || h.t < out.hit.t) {
      out.index = static_cast<int>(i);
      out.hit = h;
      out.tie = false;
    }
  }
  if (out.level && out.index >= 0) out.hit = *out.nearest[out.index];
  return out;
}

FirstHit IntersectTask::first_met(const Ray& ray) const {
  FirstHit out;
  Intersection x = object_->intersect(ray);
  if (x.hits.empty()) {
    out.nearest.emplace_back(std::nullopt);
    return out;
  }
  out.index = 0;
  out.hit = x.hits.front();
  out.nearest.emplace_back(out.hit);
  return out;
}

std::optional<std::string> FirstHitTask::level() const { return first_hit(ray_, objects_).level; }

nlohmann::json FirstHitTask::answer() const {
  FirstHit f = first_hit(ray_, objects_);
  nlohmann::json hits = nlohmann::json::array();
  if (f.index >= 0) hits.push_back(hit_json(f.hit));
  nlohmann::json j = {{"object", f.index >= 0 ? nlohmann::json(objects_[f.index].name) : nullptr},
                      {"hits", hits}};
  if (f.tie) j["tie"] = true;
  return j;
}

std::vector<std::string> FirstHitTask::methods() const {
  // The methods every object shares; the sphere's two methods when all are spheres.
  std::vector<std::string> common = objects_.front().shape->methods();
  for (const auto& o : objects_) {
    std::vector<std::string> m = o.shape->methods(), keep;
    for (const auto& x : common) {
      if (std::find(m.begin(), m.end(), x) != m.end()) keep.push_back(x);
    }
    common = keep;
  }
  if (common.empty()) common.emplace_back("default");
  return common;
}

std::vector<SolutionPart> FirstHitTask::derive(std::string_view method,
                                               const Overrides* overrides) const {
  std::string_view m = method.empty() ? std::string_view(method_) : method;
  if (m == "default") m = "";
  std::vector<SolutionPart> parts;
  for (const auto& o : objects_) {
    parts.emplace_back(o.name, o.shape->derive(ray_, m, overrides));
  }
  // The selection: every object's nearest valid t, then the smallest.
  FirstHit f = first_hit(ray_, objects_);
  Deriver d("nearest", "The first hit: the smallest valid t", overrides);
  std::vector<E> ts;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (!f.nearest[i]) continue;
    std::string name = fmt::format("t_{}", i + 1);
    ts.push_back(d.given(name, name, f.nearest[i]->t,
                         fmt::format("the nearest valid hit of {}", objects_[i].name)));
  }
  if (ts.empty()) {
    d.conclude("The ray hits none of the objects.");
  } else {
    if (ts.size() > 1) d.step("t_first", "t_first", min(ts), "the smallest of them");
    d.conclude(Sentence(fmt::format("The ray first hits {} at t = ", objects_[f.index].name))
                   .value(f.hit.t)
                   .text(", at P = ")
                   .value(f.hit.point)
                   .text("."));
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      if (!f.nearest[i]) d.conclude(fmt::format("{} is not hit.", objects_[i].name));
    }
    if (f.tie) d.conclude("Another object is hit at the same t: the first in the list is named.");
  }
  parts.emplace_back("The first hit", std::move(d).finish());
  return parts;
}

Sketch FirstHitTask::sketch() const {
  Sketch f;
  std::vector<const Shape*> shapes;
  for (const auto& o : objects_) {
    o.shape->sketch(f, o.name);
    shapes.push_back(o.shape.get());
  }
  FirstHit first = first_hit(ray_, objects_);
  std::vector<Hit> hits;
  for (const auto& h : first.nearest) {
    if (h) hits.push_back(*h);
  }
  sketch_ray(f, ray_, shapes, hits);
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (!first.nearest[i] || static_cast<int>(i) == first.index) continue;
    sketch_hit(f, *first.nearest[i], Ink::kPoint);
  }
  if (first.index >= 0) sketch_hit(f, first.hit, Ink::kHit, "first hit, ");
  return f;
}

std::optional<SceneGivens> FirstHitTask::scene_givens() const {
  SceneGivens g;
  for (const auto& o : objects_) g.objects.push_back({o.name, o.shape.get(), nullptr});
  g.ray = ray_;
  return g;
}

std::unique_ptr<Task> IntersectKind::read(const Cursor& problem) {
  return IntersectTask::read(problem);
}

std::vector<PartSpec> IntersectKind::parts() {
  using C = Comparison;
  return {{part_names::kT, "every hit's t, in any order ([] when the ray misses)", 2, C::kHits},
          {part_names::kPoint, "every hit's point P = O + tD", 1, C::kPoint},
          {part_names::kNormal, "the unit normal at every hit (any positive multiple)", 0,
           C::kDirection},
          {part_names::kBarycentric,
           "a triangle hit's weights (w_a, w_b, w_c), or its u = w_b and v = w_c", 0, C::kWeights},
          {part_names::kSteps, "the derivation's named steps", 0, C::kSteps}};
}

nlohmann::json IntersectKind::answer_form(const Problem& p) {
  const nlohmann::json& object =
      p.source.contains("object") ? p.source["object"] : nlohmann::json();
  bool barycentric =
      object.is_object() && hits_have_barycentric(object.value("type", std::string()));
  nlohmann::json f = form::hits_field(barycentric, true, true);
  f["miss"] = "The ray misses (no hits)";
  f["contained"] = "The ray lies in the surface (contained)";
  return form::fields({f});
}

std::string_view IntersectKind::schema() {
  return R"json({
  "required": [
    "ray",
    "object"
  ],
  "properties": {
    "ray": {
      "$ref": "#/$defs/ray"
    },
    "object": {
      "$ref": "#/$defs/object"
    },
    "expected": {
      "$ref": "#/$defs/hits_answer"
    }
  }
})json";
}

std::unique_ptr<Task> FirstHitKind::read(const Cursor& problem) {
  return FirstHitTask::read(problem);
}

std::vector<PartSpec> FirstHitKind::parts() {
  using C = Comparison;
  return {
      {part_names::kObject, "the name of the object hit first (null when none is)", 2, C::kName},
      {part_names::kT, "the first hit's t", 1, C::kHits},
      {part_names::kPoint, "the first hit's point", 1, C::kPoint},
      {part_names::kNormal, "the unit normal there", 0, C::kDirection}};
}

nlohmann::json FirstHitKind::answer_form(const Problem& p) {
  return form::fields(
      {form::object_choice(form::names_of(p.source.value("objects", nlohmann::json()))),
       form::hits_field(false, false, true)});
}

std::string_view FirstHitKind::schema() {
  return R"json({
  "required": [
    "ray",
    "objects"
  ],
  "properties": {
    "ray": {
      "$ref": "#/$defs/ray"
    },
    "objects": {
      "type": "array",
      "items": {
        "$ref": "#/$defs/named_object"
      },
      "minItems": 1
    },
    "expected": {
      "$ref": "#/$defs/first_hit_answer"
    }
  }
})json";
}

}  // namespace raygrade
