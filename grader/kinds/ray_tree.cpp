// The ray-tree kind.
#include "kinds/ray_tree.h"

#include <algorithm>
#include <set>

#include "core/internal_error.h"
#include "derivation/derivation.h"
#include "derivation/number_format.h"
#include "kinds/camera_ray.h"
#include "kinds/form.h"
#include "kinds/part_names.h"
#include "kinds/swatch.h"
#include "kinds/view_ray.h"
#include "scenes/tree_draw.h"
#include "scenes/tree_json.h"
#include "scenes/tree_steps.h"

namespace raygrade {

PrimaryRay read_primary_ray(const Cursor& problem) {
  if (problem.has("ray")) {
    if (problem.has("camera"))
      problem.at("camera").fail("give either a ray or a camera", "invalid");
    return {read_ray(problem.at("ray")), std::nullopt};
  }
  if (!problem.has("camera")) problem.fail("a ray or a camera and pixel is needed", "missing");
  if (is_view_camera(problem.at("camera"))) {
    ViewCamera view = read_view_camera(problem.at("camera"));
    auto [i, j] = read_pixel(problem, view.nx, view.ny);
    return {view_ray(view, i, j, read_pixel_convention(problem)), given_camera(view, i, j)};
  }
  Camera cam = read_camera(problem.at("camera"));
  auto [x, y] = read_pixel(problem, cam.res_x, cam.res_y);
  Vec3d d = camera_ray_direction(cam, x, y, read_pixel_convention(problem));
  return {Ray{cam.eye, d, 0, kInfinity}, given_camera(cam, x, y)};
}

Ask read_ask(const Cursor& problem, Ask fallback) {
  if (!problem.has("ask")) return fallback;
  std::string a = problem.at("ask").string();
  if (a == "hit") return Ask::kHit;
  if (a == "tree") return Ask::kTree;
  if (a == "intensity") return Ask::kIntensity;
  if (a == "media") return Ask::kMedia;
  problem.at("ask").fail(fmt::format("unknown ask '{}' (known: hit, tree, intensity, media)", a),
                         "invalid");
}

const std::vector<std::string>& intensity_components() {
  static const std::vector<std::string> names = {"ambient",   "diffuse",     "specular", "local",
                                                 "reflected", "transmitted", "total"};
  return names;
}

double component_value(const TreeNode& node, std::string_view component) {
  double diffuse = 0, specular = 0;
  for (const auto& s : node.lights) {
    diffuse += s.phong.diffuse;
    specular += s.phong.specular;
  }
  if (component == "ambient") return node.ambient_term;
  if (component == "diffuse") return diffuse;
  if (component == "specular") return specular;
  if (component == "local") return node.local;
  if (component == "reflected") return node.reflected;
  if (component == "transmitted") return node.transmitted;
  if (component == "total") return node.intensity;
  throw InternalError(fmt::format("no intensity component named '{}'", component));
}

void apply_labels(RayTree& tree, const std::map<std::string, std::string>& labels) {
  for (const auto& [path, label] : labels) {
    for (auto& n : tree.nodes) {
      if (n.path == path) n.label = label;
    }
  }
}

RayTreeTask::RayTreeTask(Scene scene, Ray primary, Ask ask,
                         const std::map<std::string, std::string>& labels)
    : scene_(std::move(scene)), primary_(primary), tree_(trace(scene_, primary_, ask)) {
  apply_labels(tree_, labels);
}

void RayTreeTask::follow(const Conventions& conventions) {
  tree_.facing_away = conventions.facing_away;
  for (auto& t : channels_) t.facing_away = conventions.facing_away;
}

void RayTreeTask::trace_channels(std::vector<Scene> channel_scenes,
                                 const std::map<std::string, std::string>& labels) {
  channel_scenes_ = std::move(channel_scenes);
  for (const auto& s : channel_scenes_) {
    RayTree t = trace(s, primary_, Ask::kIntensity);
    apply_labels(t, labels);
    // The channels differ in numbers only: the same rays hit the same points.
    bool same = t.nodes.size() == tree_.nodes.size();
    for (std::size_t i = 0; same && i < t.nodes.size(); ++i) {
      same = t.nodes[i].path == tree_.nodes[i].path;
    }
    if (!same) throw InternalError("a colour channel's ray tree differs from the scene's tree");
    channels_.push_back(std::move(t));
  }
  for (auto& e : tree_.effects) {
    if (e.name != "intensity") continue;
    e.simulated = true;
    e.reason =
        "the scene has colours: every intensity is worked channel by channel (r, g, b), each "
        "channel a tree of numbers";
  }
}

std::vector<Vec3d> RayTreeTask::node_colours() const {
  std::vector<Vec3d> out(tree_.nodes.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      out[i][k] = channels_[static_cast<std::size_t>(k)].nodes[i].intensity;
  }
  return out;
}

Vec3d RayTreeTask::colour_intensity() const {
  Vec3d c{};
  for (std::size_t k = 0; k < channels_.size() && k < 3; ++k) {
    c[static_cast<int>(k)] = channels_[k].nodes.front().intensity;
  }
  return c;
}

std::unique_ptr<Task> RayTreeTask::read(const Cursor& problem) {
  Scene scene = read_scene(problem.at("scene"));
  PrimaryRay primary = read_primary_ray(problem);
  Ask ask = read_ask(problem, Ask::kTree);
  // A colour scene's intensities are traced channel by channel; the scene's own tree keeps the
  // rays and the terms.
  bool colour = ask == Ask::kIntensity && has_colour(scene);
  std::vector<Scene> channel_scenes;
  if (colour) {
    ask = Ask::kTree;
    for (int c = 0; c < 3; ++c) {
      channel_scenes.push_back(read_scene(problem.at("scene")));
      keep_channel(channel_scenes.back(), c);
    }
  }
  std::map<std::string, std::string> labels;
  if (auto l = problem.find("labels")) {
    if (!l->is_object()) l->fail("labels is an object from a node's path to its label", "type");
    for (const auto& [path, value] : l->json().items()) labels[path] = l->at(path).string();
  }
  auto task = std::make_unique<RayTreeTask>(std::move(scene), primary.ray, ask, labels);
  task->camera_ = primary.camera;
  if (colour) task->trace_channels(std::move(channel_scenes), labels);
  // Every labelled path must be a hit of the tree, and the labels must stay unique.
  std::set<std::string> seen;
  for (const auto& [path, label] : labels) {
    const TreeNode* n = task->tree().find(path);
    if (!n || !n->hit) {
      std::vector<std::string> paths;
      for (const auto& node : task->tree().nodes) {
        if (node.hit) paths.push_back(node.path);
      }
      problem.at("labels").at(path).fail(
          fmt::format("the tree has no hit point at path '{}' (its points: {})", path,
                      fmt::join(paths, ", ")),
          "unknown-path");
    }
  }
  for (const auto& n : task->tree().nodes) {
    if (!seen.insert(n.label).second) {
      problem.at("labels").fail(fmt::format("the label '{}' names two nodes", n.label),
                                "duplicate-label");
    }
  }
  if (auto c = problem.find("components")) task->read_components(*c);
  return task;
}

namespace {

// Three channels' numbers as one colour [r, g, b].
nlohmann::json rgb_json(const nlohmann::json& r, const nlohmann::json& g, const nlohmann::json& b) {
  return nlohmann::json::array({r, g, b});
}

constexpr const char* kChannelTitles[3] = {"red", "green", "blue"};

// One channel's intensities, node by node, children before the parents that add them.
Derivation channel_steps(const RayTree& t, int channel) {
  Deriver d("whitted",
            fmt::format("The {} channel ({})", kChannelTitles[channel], kChannelNames[channel]));
  // Backwards with reverse iterators: the code uses no <ranges> (std::views::reverse).
  // NOLINTNEXTLINE(modernize-loop-convert)
  for (auto it = t.nodes.rbegin(); it != t.nodes.rend(); ++it) {
    const TreeNode& n = *it;
    std::string name = fmt::format("I_{}_{}", n.label, kChannelNames[channel]);
    if (!n.hit) {
      d.given(name, name, n.intensity, fmt::format("{} misses: the background", n.path));
      continue;
    }
    d.given(name, name, n.intensity,
            fmt::format("{}: I_local + {} = {} + {} + {} (ambient {})", n.label,
                        n.fresnel ? "F·k_r·I_R + (1 − F)·k_t·I_T" : "k_r·I_R + k_t·I_T",
                        format_number(n.local), format_number(n.reflected),
                        format_number(n.transmitted), format_number(n.ambient_term)));
  }
  return std::move(d).finish();
}

}  // namespace

// `components`: {"I1": ["diffuse", "specular"], "I2": ["total"]}, by the tree's labels.
void RayTreeTask::read_components(const Cursor& c) {
  if (ask() != Ask::kIntensity) {
    c.fail("components are parts of intensities: the problem needs \"ask\": \"intensity\"",
           "invalid");
  }
  if (colour()) {
    c.fail(
        "components are asked of scenes whose intensities are numbers; in a colour scene, "
        "ask for the intensity and its terms, which are graded channel by channel",
        "unsupported");
  }
  if (!c.is_object() || c.json().empty()) {
    c.fail("components is an object from a hit point's label to the components asked there",
           "type");
  }
  const std::vector<std::string>& known = intensity_components();
  for (const auto& [label, value] : c.json().items()) {
    const TreeNode* node = nullptr;
    std::vector<std::string> labels;
    for (const auto& n : tree_.nodes) {
      if (!n.hit) continue;
      labels.push_back(n.label);
      if (n.label == label) node = &n;
    }
    if (!node) {
      c.at(label).fail(fmt::format("the tree has no hit point labelled '{}' (its points: {})",
                                   label, fmt::join(labels, ", ")),
                       "unknown-label");
    }
    auto items = c.at(label).items();
    if (items.empty()) c.at(label).fail("name at least one component", "invalid");
    for (const auto& item : items) {
      std::string name = item.string();
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        item.fail(fmt::format("unknown component '{}' (known: {})", name, fmt::join(known, ", ")),
                  "invalid");
      }
      for (const auto& a : components_) {
        if (a.node == node->index && a.component == name) {
          item.fail(fmt::format("{} is asked twice at {}", name, label), "duplicate");
        }
      }
      components_.push_back(ComponentAsk{node->index, label, name});
    }
  }
}

nlohmann::json RayTreeTask::answer() const {
  nlohmann::json j = tree_json(tree_, scene_);
  if (!components_.empty()) {
    nlohmann::json c = nlohmann::json::object();
    for (const auto& a : components_) {
      c[a.label][a.component] = component_value(tree_.nodes[a.node], a.component);
    }
    j["components"] = c;
  }
  if (channels_.empty()) return j;
  nlohmann::json c[3];
  for (int k = 0; k < 3; ++k) c[k] = tree_json(channels_[k], channel_scenes_[k]);
  for (std::size_t i = 0; i < tree_.nodes.size(); ++i) {
    const nlohmann::json& r = c[0]["nodes"][i];
    const nlohmann::json& g = c[1]["nodes"][i];
    const nlohmann::json& b = c[2]["nodes"][i];
    // A miss sees the background; a hit has its terms.
    if (r.contains("background")) {
      j["nodes"][i]["background"] = rgb_json(r["background"], g["background"], b["background"]);
    }
    if (!r.contains("intensity")) continue;
    nlohmann::json terms = nlohmann::json::object();
    for (const auto& [key, value] : r["intensity"].items()) {
      terms[key] = rgb_json(value, g["intensity"][key], b["intensity"][key]);
    }
    j["nodes"][i]["intensity"] = terms;
  }
  j["intensity"] = rgb_json(c[0]["intensity"], c[1]["intensity"], c[2]["intensity"]);
  return j;
}

std::vector<SolutionPart> RayTreeTask::derive(std::string_view /*method*/,
                                              const Overrides* overrides) const {
  std::vector<SolutionPart> parts = tree_parts(tree_, scene_, overrides);
  if (!components_.empty()) {
    Deriver d("whitted", "The components asked");
    for (auto& sentence : component_sentences()) d.conclude(std::move(sentence));
    parts.push_back(SolutionPart{"", std::move(d).finish(), {}});
  }
  if (channels_.empty()) return parts;
  // The tree's figure with each point's colour beside it.
  std::vector<Vec3d> colours = node_colours();
  for (auto& f : parts.front().figures) {
    if (!f.svg.empty()) f.svg = tree_svg(tree_, scene_, &colours);
  }
  // The colour: each channel's intensities, then the colour they make, before the answer.
  SolutionPart answer = std::move(parts.back());
  parts.pop_back();
  for (int k = 0; k < 3; ++k) {
    parts.push_back(SolutionPart{fmt::format("Intensities, {} channel", kChannelTitles[k]),
                                 channel_steps(channels_[k], k),
                                 {}});
  }
  std::string colour = fmt::format(
      "The colour seen along the primary ray is {} (r, g, b): the scene's colours are worked "
      "channel by channel, a number acting on every channel alike.",
      colour_text(colour_intensity()));
  answer.derivation.conclusion.push_back(colour);
  answer.derivation.sentences.emplace_back(colour);
  // Each hit point's colour, and the background a missing ray sees, as swatches.
  std::vector<std::pair<std::string, Vec3d>> swatches;
  for (std::size_t i = 0; i < tree_.nodes.size(); ++i) {
    const TreeNode& n = tree_.nodes[i];
    swatches.emplace_back(
        n.hit ? fmt::format("I at {}", n.label) : fmt::format("I of {} (background)", n.path),
        colours[i]);
  }
  answer.figures.push_back(swatch_figure(swatches));
  parts.push_back(std::move(answer));
  return parts;
}

// "I1's diffuse component is 0.6.", one sentence per component asked.
std::vector<std::string> RayTreeTask::component_sentences() const {
  std::vector<std::string> out;
  for (const auto& c : components_) {
    out.push_back(fmt::format("{}'s {} is {}.", c.label,
                              c.component == "total" ? "intensity" : c.component + " component",
                              format_number(component_value(tree_.nodes[c.node], c.component))));
  }
  return out;
}

std::vector<std::string> RayTreeTask::conclusion() const {
  std::vector<std::string> out = tree_answer(tree_, scene_).conclusion;
  if (!channels_.empty()) {
    out.push_back(fmt::format("The colour seen along the primary ray is {} (r, g, b).",
                              colour_text(colour_intensity())));
  }
  for (auto& s : component_sentences()) out.push_back(std::move(s));
  return out;
}

std::optional<SceneGivens> RayTreeTask::scene_givens() const {
  SceneGivens g;
  for (const auto& o : scene_.objects) g.objects.push_back({o.name, o.shape.get(), &o.transform});
  for (const auto& l : scene_.lights) {
    g.lights.push_back({l.name, l.type == LightType::kDirectional, l.position, l.direction});
  }
  // The ray as given, or the camera and pixel it comes from.
  if (camera_) {
    g.camera = camera_;
  } else {
    g.ray = primary_;
  }
  return g;
}

std::unique_ptr<Task> RayTreeKind::read(const Cursor& problem) {
  return RayTreeTask::read(problem);
}

std::vector<PartSpec> RayTreeKind::parts() {
  using C = Comparison;
  return {
      {part_names::kHit, "ask \"hit\": the object the ray hits first and its t", 1, C::kHits},
      {part_names::kTree, "the hit points of the tree and their objects", 1, C::kTree},
      {part_names::kShadows, "which hit points are in shadow, and by what when named", 1, C::kFlag},
      {part_names::kTerms, "which Phong terms apply at each hit point", 1, C::kNames},
      {part_names::kIntensity, "ask \"intensity\": the intensity along the primary ray", 1,
       C::kScalar},
      {part_names::kMedia, "ask \"media\": n1 and n2 at every hit along the ray, in order", 1,
       C::kHits}};
}

nlohmann::json RayTreeKind::answer_form(const Problem& p) {
  std::string ask = p.source.value("ask", "tree");
  if (ask == "hit") {
    // The object and its t are one part, "hit".
    nlohmann::json scene = p.source.value("scene", nlohmann::json::object());
    nlohmann::json object =
        form::object_choice(form::names_of(scene.value("objects", nlohmann::json())));
    nlohmann::json hits = form::hits_field(false, false, false);
    object["parts"] = nlohmann::json::array({"hit"});
    for (auto& c : hits["columns"]) c["parts"] = nlohmann::json::array({"hit"});
    return form::fields({object, hits});
  }
  auto task = dynamic_cast<const RayTreeTask*>(p.task.get());
  if (!task) throw InternalError(fmt::format("problem {} is not a ray tree", p.id));
  nlohmann::json list = nlohmann::json::array();
  if (task->tree().ask == Ask::kMedia) {
    // Every boundary along the ray's line, in order: t, then the indices on either side.
    nlohmann::json hits =
        form::field<field_types::Hits>("hits", "Every surface the ray's line crosses, in order");
    nlohmann::json columns = nlohmann::json::array(
        {form::field<field_types::Number>("t", "t"),
         form::field<field_types::Number>("n1", "n1 (the side it comes from)"),
         form::field<field_types::Number>("n2", "n2 (the side it goes into)")});
    for (auto& c : columns) c["parts"] = nlohmann::json::array({"media"});
    hits["columns"] = columns;
    hits["several"] = true;
    list.push_back(hits);
    return form::fields(list);
  }
  if (!task->components().empty()) {
    // One number per component asked, keyed by the tree's labels.
    for (const auto& c : task->components()) {
      nlohmann::json f = form::field<field_types::Number>(
          "components/" + c.label + "/" + c.component,
          c.component == "total" ? fmt::format("{}'s intensity", c.label)
                                 : fmt::format("{}'s {} term", c.label, c.component));
      f["parts"] = nlohmann::json::array({c.part()});
      list.push_back(f);
    }
    return form::fields(list);
  }
  list.push_back(form::tree_field(task->scene()));
  if (task->ask() == Ask::kIntensity) {
    nlohmann::json f = task->colour()
                           ? form::field<field_types::Vector>(
                                 "intensity", "The colour seen along the primary ray (r, g, b)")
                           : form::field<field_types::Number>(
                                 "intensity", "The intensity seen along the primary ray");
    list.push_back(f);
  }
  return form::fields(list);
}

std::string_view RayTreeKind::schema() {
  return R"json({
  "required": [
    "scene"
  ],
  "properties": {
    "scene": {
      "$ref": "#/$defs/scene"
    },
    "ray": {
      "$ref": "#/$defs/ray"
    },
    "camera": {
      "anyOf": [
        {
          "$ref": "#/$defs/camera"
        },
        {
          "$ref": "#/$defs/view_camera"
        }
      ]
    },
    "pixel": {
      "$ref": "#/$defs/pixel"
    },
    "convention": {
      "enum": [
        "center",
        "corner"
      ]
    },
    "ask": {
      "enum": [
        "hit",
        "tree",
        "intensity",
        "media"
      ],
      "default": "tree"
    },
    "labels": {
      "type": "object",
      "additionalProperties": {
        "type": "string"
      },
      "description": "a node's path (P, P.R, P.T.R) to its label"
    },
    "components": {
      "type": "object",
      "description": "with ask intensity: a hit point's label to the components of its intensity asked there, each a part of its own",
      "additionalProperties": {
        "type": "array",
        "minItems": 1,
        "uniqueItems": true,
        "items": {
          "enum": [
            "ambient",
            "diffuse",
            "specular",
            "local",
            "reflected",
            "transmitted",
            "total"
          ]
        }
      },
      "minProperties": 1
    }
  },
  "oneOf": [
    {
      "required": [
        "ray"
      ]
    },
    {
      "required": [
        "camera",
        "pixel"
      ]
    }
  ]
})json";
}

}  // namespace raygrade
