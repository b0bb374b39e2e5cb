// Grading the kind `ray-tree` node by node: the tree's shape (which rays, which objects they
// hit), which points are in shadow, and which Phong terms apply at each, with partial credit
// per node and the reason for every node marked wrong.
#include <fmt/format.h>

#include <set>
#include <unordered_map>

#include "derivation/number_format.h"
#include "grading/grade_colour.h"
#include "grading/kind_grader.h"
#include "grading/mistakes.h"
#include "grading/parts.h"
#include "grading/tolerance.h"
#include "kinds/part_names.h"
#include "kinds/ray_tree.h"
#include "scenes/tree_json.h"

namespace raygrade {
namespace {

// An extra node costs half a node of the tree part: drawing a ray that does not exist is a
// mistake, but a smaller one than missing a ray that does.
constexpr double kExtraNodePenalty = 0.5;

struct StudentNode {
  std::string label;
  std::string where;  // its JSON path in the answer
  std::optional<std::string> path, parent, ray, object;
  bool leaves = false;  // "object": null: the student says the ray meets nothing
  std::optional<bool> in_shadow;
  std::optional<std::set<std::string>> shadowed_by;  // the objects the student says block
  std::optional<std::set<std::string>> terms;
  std::string resolved;  // the path in the tree it stands for ("" when it cannot be placed)
};

std::set<std::string> term_set(const std::vector<std::string>& v) { return {v.begin(), v.end()}; }

std::string terms_words(const std::set<std::string>& t) {
  std::vector<std::string> order;
  for (const char* k : {"ambient", "diffuse", "specular"}) {
    if (t.count(k)) order.emplace_back(k);
  }
  for (const auto& k : t) {
    // not a part: the Phong terms' names, the values of a point's terms
    if (k != "ambient" && k != "diffuse" && k != "specular") order.push_back(k);
  }
  // In the words of the answer form's choices: "ambient only", "ambient, diffuse and specular".
  if (order.empty()) return "no terms";
  if (order.size() == 1) return order.front() + " only";
  std::string last = order.back();
  order.pop_back();
  return fmt::format("{} and {}", fmt::join(order, ", "), last);
}

class RayTreeGrader final : public KindGrader {
 public:
  explicit RayTreeGrader(const Problem& p) : task_(dynamic_cast<const RayTreeTask&>(*p.task)) {
    context_.problem = &p;
    context_.tolerance = read_tolerance_policy(p);
    Ask ask = task_.ask();
    if (ask == Ask::kHit) {
      context_.points = read_points_policy(p, default_points(p.kind, {part_names::kHit}));
    } else if (ask == Ask::kMedia) {
      context_.points = read_points_policy(p, default_points(p.kind, {part_names::kMedia}));
    } else if (!task_.components().empty()) {
      std::vector<std::pair<std::string, double>> parts;
      for (const auto& c : task_.components()) parts.emplace_back(c.part(), 1);
      context_.points = read_points_policy(p, parts);
    } else if (ask == Ask::kTree) {
      context_.points = read_points_policy(
          p, default_points(p.kind, {part_names::kTree, part_names::kShadows, part_names::kTerms}));
    } else {
      context_.points = read_points_policy(
          p, default_points(p.kind, {part_names::kTree, part_names::kShadows, part_names::kTerms,
                                     part_names::kIntensity}));
    }
  }

  void grade(const AnswerReader& a, GradeResult& out) const override {
    if (task_.tree().ask == Ask::kHit) return grade_hit(a, out);
    if (task_.tree().ask == Ask::kMedia) return grade_media(a, out);
    if (!task_.components().empty()) return grade_components(a, out);
    a.allow_only({"nodes", "all_terms", "ambient_only", "rays", "effects", part_names::kIntensity});
    std::vector<StudentNode> nodes = read_nodes(a);
    // Reference hit node index -> the student's node standing for it.
    std::map<int, const StudentNode*> match;
    std::vector<const StudentNode*> extra;
    for (const auto& s : nodes) {
      const TreeNode* r = s.resolved.empty() ? nullptr : task_.tree().find(s.resolved);
      if (r && r->hit && !match.count(r->index)) {
        match[r->index] = &s;
      } else if (!r || r->hit) {
        extra.push_back(&s);
      }
    }
    auto lists = read_lists(a);
    if (a.has("nodes")) {
      out.parts.push_back(grade_tree(match, extra));
    } else {
      out.parts.push_back(missing_part(context_, part_names::kTree, "No tree (nodes) given."));
    }
    grade_lighting(match, lists, nodes.empty(), out);
    if (task_.ask() == Ask::kIntensity) grade_intensity(a, out);
  }

 private:
  const RayTree& tree() const { return task_.tree(); }
  const Scene& scene() const { return task_.scene(); }
  std::string object_name(int i) const { return scene().objects[i].name; }

  void grade_hit(const AnswerReader& a, GradeResult& out) const {
    a.allow_only({part_names::kObject, "hits", "rays", "effects"});
    const TreeNode& root = tree().nodes.front();
    std::vector<std::string> fb;
    double credit = 0;
    std::string want = root.hit ? object_name(root.object) : "";
    if (!a.has(part_names::kObject)) fb.emplace_back("No object named.");
    if (a.has(part_names::kObject)) {
      std::string got =
          a.at(part_names::kObject).json().is_null() ? "" : a.at(part_names::kObject).string();
      if (got == want) {
        credit += 0.5;
      } else {
        fb.push_back(root.hit ? fmt::format("The ray first hits {}, not {}.", want,
                                            got.empty() ? "nothing" : got)
                              : "The ray hits nothing.");
      }
    }
    if (root.hit && a.has("hits") && !a.at("hits").items().empty()) {
      AnswerReader h = a.at("hits").items().front();
      if (h.has(part_names::kT)) {
        auto n = h.at(part_names::kT).number();
        const Tolerance& tol = context_.tolerance.for_field(part_names::kT);
        if (n.value &&
            compare_number(*n.value, root.t, std::abs(root.t), tol).match == Match::kRight) {
          credit += 0.5;
        } else {
          fb.push_back(n.value
                           ? fmt::format("t is {}, not {}.", format_number(root.t), n.value->text)
                           : "t: " + n.fault);
        }
      } else {
        fb.emplace_back("No t given.");
      }
    } else if (!root.hit) {
      bool none = a.has("hits") && a.at("hits").items().empty();
      credit += none ? 0.5 : 0;
      if (!none) fb.emplace_back("The ray hits nothing: give \"hits\": [].");
    } else {
      fb.push_back(a.has("hits") ? fmt::format("You say the ray misses; it hits {} at t = {}.",
                                               want, format_number(root.t))
                                 : "No hits given.");
    }
    if (credit >= 1) fb.emplace_back("Right.");
    out.parts.push_back(make_part(context_, part_names::kHit, credit, fb));
  }

  // n1 and n2 at each hit along the ray, in order: half a hit's credit for each.
  void grade_media(const AnswerReader& a, GradeResult& out) const {
    a.allow_only({"hits"});
    if (!a.has("hits")) {
      out.parts.push_back(missing_part(context_, part_names::kMedia, "No hits given."));
      return;
    }
    const std::vector<Crossing>& want = tree().crossings;
    std::vector<AnswerReader> given = a.at("hits").items();
    const Tolerance& tol = context_.tolerance.for_field("n");
    std::vector<std::string> fb;
    double earned = 0;
    for (std::size_t k = 0; k < want.size(); ++k) {
      const Crossing& c = want[k];
      std::string where =
          fmt::format("Hit {} ({} at t = {})", k + 1, object_name(c.object), format_number(c.t));
      if (k >= given.size()) {
        fb.push_back(fmt::format("Missing: {}.", where));
        continue;
      }
      const AnswerReader& h = given[k];
      h.allow_only({part_names::kObject, part_names::kT, "n1", "n2", part_names::kMedia});
      if (h.has(part_names::kObject) &&
          h.at(part_names::kObject).string() != object_name(c.object)) {
        fb.push_back(fmt::format("{}: the hit is on {}, not {}.", where, object_name(c.object),
                                 h.at(part_names::kObject).string()));
      }
      std::optional<StudentNumber> got[2];
      double ref[2] = {c.n1, c.n2};
      const char* names[2] = {"n1", "n2"};
      bool right[2] = {false, false};
      for (int i = 0; i < 2; ++i) {
        if (!h.has(names[i])) {
          fb.push_back(fmt::format("{}: no {} given.", where, names[i]));
          continue;
        }
        auto n = h.at(names[i]).number();
        if (!n.value) {
          fb.push_back(fmt::format("{}: {}: {}", where, names[i], n.fault));
          continue;
        }
        got[i] = *n.value;
        right[i] = compare_number(*n.value, ref[i], std::abs(ref[i]), tol).match == Match::kRight;
        if (right[i]) earned += 0.5;
      }
      if (right[0] && right[1]) continue;
      std::string specific = fmt::format("{}: n1 = {} ({}), n2 = {} ({}).", where,
                                         format_number(c.n1), media_words(scene(), c.before),
                                         format_number(c.n2), media_words(scene(), c.after));
      fb.push_back(specific);
      auto same = [&](const std::optional<StudentNumber>& g, double v) {
        return g && compare_number(*g, v, std::abs(v), tol).match == Match::kRight;
      };
      if (c.n1 != c.n2 && same(got[0], c.n2) && same(got[1], c.n1)) {
        out.mistakes.push_back(make_mistake("n1-n2-swapped", part_names::kMedia, specific));
      } else if ((!right[1] && c.after.size() > 0 && same(got[1], scene().refractive_index)) ||
                 (!right[0] && c.before.size() > 0 && same(got[0], scene().refractive_index))) {
        out.mistakes.push_back(make_mistake("media-not-nested", part_names::kMedia, specific));
      }
    }
    double extra = given.size() > want.size() ? double(given.size() - want.size()) : 0;
    if (extra > 0) {
      fb.push_back(fmt::format("The ray crosses {} boundar{}, not {}.", want.size(),
                               want.size() == 1 ? "y" : "ies", given.size()));
    }
    double total = static_cast<double>(want.size());
    double credit = total > 0 ? std::max(0.0, earned - kExtraNodePenalty * extra) / total
                              : (extra != 0 ? 0 : 1);
    if (fb.empty()) fb.push_back(fmt::format("Right: n1 and n2 at all {} hits.", want.size()));
    out.parts.push_back(make_part(context_, part_names::kMedia, credit, fb));
  }

  std::vector<StudentNode> read_nodes(const AnswerReader& a) const {
    std::vector<StudentNode> out;
    if (!a.has("nodes")) return out;
    for (const auto& n : a.at("nodes").items()) {
      // not a part: a node's keys (docs/scenes.md), some spelled as parts are
      n.allow_only({"label",       "path",
                    "parent",      "ray",
                    "object",      "in_shadow",
                    "shadowed_by", "faces_away",
                    "terms",       "lights",
                    "children",    "depth",
                    "origin",      "direction",
                    "hit",         "t",
                    "point",       "normal",
                    "inside",      "fresnel",
                    "intensity",   "total_internal_reflection",
                    "background",  "n1",
                    "n2"});
      StudentNode s;
      s.where = n.path();
      s.label = n.has("label") ? n.at("label").string() : "";
      if (n.has("path")) s.path = n.at("path").string();
      if (n.has("parent") && !n.at("parent").json().is_null()) s.parent = n.at("parent").string();
      if (n.has(RayTreeKind::kNodeRay)) s.ray = n.at(RayTreeKind::kNodeRay).string();
      if (n.has(part_names::kObject)) {
        if (n.at(part_names::kObject).json().is_null()) {
          s.leaves = true;
        } else {
          s.object = n.at(part_names::kObject).string();
        }
      }
      if (n.has("in_shadow")) {
        if (!n.at("in_shadow").json().is_boolean())
          n.at("in_shadow").fail("expected true or false", "type");
        s.in_shadow = n.at("in_shadow").json().get<bool>();
      }
      if (n.has("shadowed_by")) {
        std::set<std::string> by;
        AnswerReader c = n.at("shadowed_by");
        if (c.json().is_string()) {
          by.insert(c.string());
        } else {
          for (const auto& x : c.items()) by.insert(x.string());
        }
        s.shadowed_by = by;
      }
      if (n.has(part_names::kTerms)) {
        std::set<std::string> t;
        for (const auto& x : n.at(part_names::kTerms).items()) t.insert(x.string());
        s.terms = t;
      }
      out.push_back(std::move(s));
    }
    // Place each node in the tree: by its path, or by its parent and the kind of its ray.
    // A parent is the first node with its label, found by a map: linear in the nodes.
    Labels labels;
    for (std::size_t i = 0; i < out.size(); ++i) labels.try_emplace(out[i].label, i);
    for (auto& s : out) s.resolved = resolve(s, out, labels, 0);
    return out;
  }

  using Labels = std::unordered_map<std::string, std::size_t>;

  static std::string resolve(const StudentNode& s, const std::vector<StudentNode>& all,
                             const Labels& labels, int depth) {
    if (s.path) return *s.path;
    if (depth > kMaxTreeDepth) return "";  // a cycle of parents
    if (!s.parent) return !s.ray || *s.ray == "primary" ? "P" : "";
    auto p = labels.find(*s.parent);
    if (p == labels.end()) return "";
    std::string base = resolve(all[p->second], all, labels, depth + 1);
    if (base.empty() || !s.ray) return "";
    if (*s.ray == "reflection") return base + ".R";
    if (*s.ray == "refraction") return base + ".T";
    return "";
  }

  // Why the tree has no ray where the student drew one.
  std::string no_such_ray(const StudentNode& s) const {
    std::string where = s.label.empty() ? s.where : s.label;
    const TreeNode* parent = nullptr;
    if (s.resolved.size() > 2) parent = tree().find(s.resolved.substr(0, s.resolved.size() - 2));
    if (parent && parent->hit) {
      const SceneObject& o = scene().objects[parent->object];
      bool reflection = s.resolved.back() == 'R';
      if (reflection && !o.material.reflects() &&
          !(parent->refraction_math.total_internal_reflection))
        return fmt::format(
            "{}: {} does not reflect (reflectivity 0), so {} spawns no reflection "
            "ray.",
            where, o.name, parent->label);
      if (!reflection && !o.material.transmits())
        return fmt::format("{}: {} is opaque (transparency 0), so {} spawns no refraction ray.",
                           where, o.name, parent->label);
      if (parent->depth >= scene().max_depth)
        return fmt::format("{}: the depth limit (max_depth {}) ends the tree at {}.", where,
                           scene().max_depth, parent->label);
      if (reflection && parent->inside && !scene().internal_reflection)
        return fmt::format("{}: the problem assumes no internal reflection.", where);
      if (!reflection && parent->refraction_math.total_internal_reflection)
        return fmt::format("{}: at {} the light is totally reflected: no refraction ray.", where,
                           parent->label);
    }
    return fmt::format("{}: the tree has no such ray.", where);
  }

  PartResult grade_tree(const std::map<int, const StudentNode*>& match,
                        const std::vector<const StudentNode*>& extra) const {
    double earned = 0;
    int total = 0;
    std::vector<std::string> fb;
    // A point is named as the student named it where they gave it: the form's I1, I2, ...
    auto shown = [&](int index) {
      auto it = match.find(index);
      return it != match.end() && !it->second->label.empty() ? it->second->label
                                                             : tree().nodes[index].label;
    };
    for (const auto& n : tree().nodes) {
      if (!n.hit) continue;
      ++total;
      auto it = match.find(n.index);
      std::string what =
          n.parent < 0 ? "the primary ray"
                       : fmt::format("the {} ray from {}", to_string(n.kind), shown(n.parent));
      if (it == match.end()) {
        fb.push_back(
            fmt::format("Missing: the point where {} meets {}.", what, object_name(n.object)));
        continue;
      }
      const StudentNode& s = *it->second;
      if (s.leaves) {
        fb.push_back(fmt::format("{}: {} meets {}; it does not leave the scene.", s.label, what,
                                 object_name(n.object)));
        continue;
      }
      if (s.object && *s.object != object_name(n.object)) {
        earned += 0.5;
        fb.push_back(fmt::format("{}: {} meets {}, not {}.", s.label, what, object_name(n.object),
                                 *s.object));
      } else {
        earned += 1;
      }
    }
    for (const auto* s : extra) fb.push_back(no_such_ray(*s));
    double credit =
        total
            ? std::max(0.0, earned - kExtraNodePenalty * static_cast<double>(extra.size())) / total
            : 1;
    if (fb.empty()) fb.push_back(fmt::format("Right: all {} points of the tree.", total));
    return make_part(context_, part_names::kTree, credit, fb);
  }

  struct Lists {
    std::set<std::string> all, ambient;
    bool given = false;
  };

  Lists read_lists(const AnswerReader& a) const {
    Lists l;
    for (const char* key : {"all_terms", "ambient_only"}) {
      if (!a.has(key)) continue;
      l.given = true;
      for (const auto& x : a.at(key).items()) {
        (std::string(key) == "all_terms" ? l.all : l.ambient).insert(x.string());
      }
    }
    return l;
  }

  // The reason a node's terms are what they are, in words.
  std::string light_reason(const TreeNode& n) const {
    std::vector<std::string> parts;
    for (const auto& s : n.lights) {
      std::vector<std::string> by;
      for (int b : s.blockers) by.push_back(object_name(b));
      switch (s.status) {
        case LightStatus::kVisible:
          parts.push_back(fmt::format("its shadow ray toward {} reaches the light", s.light_name));
          break;
        case LightStatus::kTransmitted:
          parts.push_back(fmt::format("its shadow ray toward {} passes only transparent {}",
                                      s.light_name, fmt::join(by, ", ")));
          break;
        case LightStatus::kBlocked:
          parts.push_back(fmt::format("its shadow ray toward {} is blocked by {}", s.light_name,
                                      fmt::join(by, ", ")));
          break;
        case LightStatus::kBehind: {
          std::vector<std::string> would;
          for (int b : s.behind_blockers) would.push_back(object_name(b));
          parts.push_back(
              would.empty()
                  ? fmt::format("it faces away from {}", s.light_name)
                  : fmt::format("it faces away from {}, and its shadow ray toward {} would also "
                                "be blocked by {}",
                                s.light_name, s.light_name, fmt::join(would, ", ")));
          break;
        }
      }
    }
    if (parts.empty()) return "the scene has no lights";
    return fmt::format("{}", fmt::join(parts, "; "));
  }

  // "" when the student's blockers are the point's (at a point that faces away, `behind`:
  // those its shadow rays would meet); else what blocks it instead.
  std::string blocker_fault(const TreeNode& n, const std::set<std::string>& said,
                            bool behind) const {
    std::vector<std::string> by;
    if (!behind) {
      by = shadow_blockers(tree(), scene(), n);
    } else {
      for (const auto& l : n.lights)
        for (int b : l.behind_blockers)
          if (std::find(by.begin(), by.end(), object_name(b)) == by.end())
            by.push_back(object_name(b));
    }
    if (std::set<std::string>(by.begin(), by.end()) == said) return "";
    return fmt::format("blocked by {}, not {}", fmt::join(by, ", "), fmt::join(said, ", "));
  }

  void grade_lighting(const std::map<int, const StudentNode*>& match, const Lists& lists,
                      bool no_nodes, GradeResult& out) const {
    int total = 0, shadows_right = 0, terms_right = 0;
    bool any_shadow = false, any_terms = false;
    std::vector<std::string> shadow_fb, terms_fb;
    for (const auto& n : tree().nodes) {
      if (!n.hit) continue;
      ++total;
      auto it = match.find(n.index);
      const StudentNode* s = it == match.end() ? nullptr : it->second;
      // The label the student uses for this point: their node's, or the problem's.
      std::string label = s && !s->label.empty() ? s->label : n.label;
      std::optional<std::set<std::string>> terms;
      if (s && s->terms) terms = s->terms;
      if (!terms && (s || no_nodes) && lists.given) {
        if (lists.all.count(label)) terms = std::set<std::string>{"ambient", "diffuse", "specular"};
        if (lists.ambient.count(label)) terms = std::set<std::string>{"ambient"};
      }
      // In shadow: 1, lit: 0, not said: −1 (an int: GCC misreads an optional<bool> here).
      int shadow = s && s->in_shadow ? int(*s->in_shadow) : -1;
      std::set<std::string> want = term_set(node_terms(n));
      // Facing away and blocked as well: "in shadow" and "not in shadow" both hold, unless the
      // course's convention picks one (the shadow ray decides, or N·L is tested first).
      ShadowReading reading = shadow_reading(tree(), n);
      bool want_shadow = reading.in_shadow;
      bool either = reading.either;
      // Terms without in_shadow say only whether some light reaches the point: ambient alone
      // is right at a point in shadow and at one that faces away from every light alike.
      if (shadow < 0 && terms && !scene().lights.empty()) {
        shadow = terms->count("diffuse") ? 0 : (n.diffuse ? 1 : int(want_shadow));
      }
      std::string reason = light_reason(n);
      if (shadow >= 0) {
        any_shadow = true;
        std::string wrong_blocker = !s || !s->shadowed_by || shadow != 1 ? ""
                                    : want_shadow || either
                                        ? blocker_fault(n, *s->shadowed_by, faces_away(n))
                                        : "";
        if (((shadow == 1) == want_shadow || either) && wrong_blocker.empty()) {
          ++shadows_right;
        } else if (!wrong_blocker.empty()) {
          shadow_fb.push_back(fmt::format("{} is in shadow, {}.", label, wrong_blocker));
        } else {
          shadow_fb.push_back(fmt::format("{} is {}: {}.", label,
                                          want_shadow ? "in shadow" : "not in shadow", reason));
        }
      } else {
        shadow_fb.push_back(fmt::format("{}: not said whether it is in shadow.", label));
      }
      if (!terms) {
        terms_fb.push_back(fmt::format("{}: no Phong terms given.", label));
        continue;
      }
      any_terms = true;
      if (*terms == want) {
        ++terms_right;
        continue;
      }
      bool extra_light = !n.diffuse && (terms->count("diffuse") || terms->count("specular"));
      bool missing_light = n.diffuse && !terms->count("diffuse");
      std::string specific = fmt::format("{} needs {}, not {}: {}.", label, terms_words(want),
                                         terms_words(*terms), reason);
      terms_fb.push_back(specific);
      if (extra_light) {
        out.mistakes.push_back(make_mistake("diffuse-in-shadow", part_names::kTerms, specific));
      } else if (missing_light) {
        out.mistakes.push_back(
            make_mistake("lit-point-ambient-only", part_names::kTerms, specific));
      }
    }
    auto part = [&](const char* name, bool given, int right, std::vector<std::string> fb) {
      if (!given) return missing_part(context_, name);
      if (right == total) fb = {fmt::format("Right at all {} points.", total)};
      return make_part(context_, name, total ? double(right) / total : 1, fb);
    };
    out.parts.push_back(part(part_names::kShadows, any_shadow, shadows_right, shadow_fb));
    out.parts.push_back(part(part_names::kTerms, any_terms, terms_right, terms_fb));
  }

  // One intensity the student gives, against the reference: the one comparison of
  // intensities, for the primary ray's total and for every component.
  struct IntensityCheck {
    bool right = false;
    std::optional<double> given;  // the student's value, when it reads as a number
    std::string text;             // that value as the student typed it, for messages
    std::string fault;            // why it does not read, else ""
  };
  IntensityCheck check_intensity(const AnswerReader& given, double want) const {
    IntensityCheck c;
    auto n = given.number();
    if (!n.value) {
      c.fault = n.fault;
      return c;
    }
    c.given = n.value->value;
    c.text = n.value->text;
    const Tolerance& tol = context_.tolerance.for_field(part_names::kIntensity);
    c.right = compare_number(*n.value, want, std::abs(want), tol).match == Match::kRight;
    return c;
  }
  // An intensity in feedback, at the precision it is graded to.
  std::string shown_intensity(double want) const {
    return format_number(want,
                         shown_at(context_.tolerance.for_field(part_names::kIntensity), want, {}));
  }
  bool same_intensity(double got, double other) const {
    const Tolerance& tol = context_.tolerance.for_field(part_names::kIntensity);
    return std::abs(got - other) <= allowed_error(other, std::abs(other), tol);
  }

  void grade_intensity(const AnswerReader& a, GradeResult& out) const {
    if (!a.has(part_names::kIntensity)) {
      out.parts.push_back(missing_part(context_, part_names::kIntensity));
      return;
    }
    if (task_.colour()) {
      ColourVerdict v = grade_colour(part_names::kIntensity, a.at(part_names::kIntensity),
                                     task_.colour_intensity(),
                                     context_.tolerance.for_field(part_names::kIntensity), {});
      for (auto& m : v.mistakes) out.mistakes.push_back(std::move(m));
      if (v.feedback.empty()) v.feedback.emplace_back("Right.");
      out.parts.push_back(
          make_part(context_, part_names::kIntensity, v.credit, std::move(v.feedback)));
      return;
    }
    double want = tree().nodes.front().intensity;
    IntensityCheck c = check_intensity(a.at(part_names::kIntensity), want);
    if (c.right) {
      out.parts.push_back(make_part(context_, part_names::kIntensity, 1, {"Right."}));
    } else {
      out.parts.push_back(
          make_part(context_, part_names::kIntensity, 0,
                    {c.given ? fmt::format("The intensity along the primary ray is {}, not {}.",
                                           shown_intensity(want), c.text)
                             : "intensity: " + c.fault}));
    }
  }

  // The diffuse and specular sums a node would have if its blocked lights reached it.
  std::pair<double, double> unshadowed_terms(const TreeNode& n) const {
    const Material& m = scene().objects[n.object].material;
    Vec3d v = normalized(-n.ray.direction);
    double diffuse = 0, specular = 0;
    for (const auto& s : n.lights) {
      if (s.status == LightStatus::kBehind) continue;
      PhongLight p = phong_light(s.normal, s.l, v, scene().lights[s.light].intensity, m.diffuse,
                                 m.specular, m.shininess);
      diffuse += p.diffuse;
      specular += p.specular;
    }
    return {diffuse, specular};
  }

  // The named mistake a wrong component shows, if any.
  std::optional<FoundMistake> component_mistake(const ComponentAsk& ask, const TreeNode& n,
                                                double got, const std::string& specific) const {
    double want = component_value(n, ask.component);
    if (ask.component != "total" && ask.component != "local" && same_intensity(got, n.intensity) &&
        !same_intensity(want, n.intensity)) {
      return make_mistake("component-is-total", ask.part(), specific);
    }
    auto [diffuse, specular] = unshadowed_terms(n);
    // not a part: a component's name (ComponentAsk, kinds/ray_tree.h)
    double unshadowed = ask.component == "diffuse"    ? diffuse
                        : ask.component == "specular" ? specular
                        : ask.component == "local"    ? n.ambient_term + diffuse + specular
                                                      : want;
    if (!same_intensity(unshadowed, want) && same_intensity(got, unshadowed)) {
      return make_mistake("diffuse-in-shadow", ask.part(), specific);
    }
    int child = ask.component == "reflected"     ? n.reflection
                : ask.component == "transmitted" ? n.refraction
                                                 : -1;
    if (child >= 0) {
      double unweighted = tree().nodes[child].intensity;
      if (!same_intensity(unweighted, want) && same_intensity(got, unweighted)) {
        return make_mistake("secondary-unweighted", ask.part(), specific);
      }
    }
    return std::nullopt;
  }

  // `components`: {"I1": {"diffuse": 0.4, "specular": 0.3}}, one part per component asked.
  void grade_components(const AnswerReader& a, GradeResult& out) const {
    a.allow_only({"components", "nodes", "all_terms", "ambient_only", "rays", "effects",
                  part_names::kIntensity});
    std::optional<AnswerReader> given;
    if (a.has("components")) given = a.at("components");
    for (const auto& ask : task_.components()) {
      const TreeNode& n = tree().nodes[ask.node];
      double want = component_value(n, ask.component);
      std::string what =
          // not a part: the word for a total, in the feedback's sentence
          fmt::format("{}'s {}", ask.label, ask.component == "total" ? "intensity" : ask.component);
      if (!given || !given->has(ask.label) || !given->at(ask.label).has(ask.component)) {
        out.parts.push_back(missing_part(context_, ask.part(), fmt::format("No {} given.", what)));
        continue;
      }
      IntensityCheck c = check_intensity(given->at(ask.label).at(ask.component), want);
      if (c.right) {
        out.parts.push_back(make_part(context_, ask.part(), 1, {"Right."}));
        continue;
      }
      if (!c.given) {
        out.parts.push_back(make_part(context_, ask.part(), 0, {ask.part() + ": " + c.fault}));
        continue;
      }
      std::string specific = fmt::format("{} is {}, not {}.", what, shown_intensity(want), c.text);
      if (auto m = component_mistake(ask, n, *c.given, specific)) out.mistakes.push_back(*m);
      out.parts.push_back(make_part(context_, ask.part(), 0, {specific}));
    }
  }

  const RayTreeTask& task_;
};

}  // namespace

std::shared_ptr<const KindGrader> make_ray_tree_grader(const Problem& p) {
  return std::make_shared<RayTreeGrader>(p);
}

}  // namespace raygrade
