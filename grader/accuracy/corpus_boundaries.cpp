// Hard cases of scale and of slab or axis boundaries, and the corpus file.
#include <cmath>
#include <fstream>
#include <sstream>

#include "accuracy/corpus.h"
#include "core/error.h"
#include "json/source.h"

namespace raygrade {
namespace {

AccuracyCase make(std::string id, std::string group, Primitive p, Vec3d o, Vec3d d,
                  std::vector<Vec3d> points, double radius = 0) {
  return AccuracyCase{std::move(id), std::move(group), p, o, d, std::move(points), radius};
}

void huge_coordinates(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    Vec3d shift = 1e8 * rng.unit_vector();
    AccuracyCase c = random_cases(kAllPrimitives[i % 6], 1, rng.next()).front();
    c.id = fmt::format("huge-coordinates-{}", i);
    c.group = "huge-coordinates";
    c.origin = c.origin + shift;
    bool is_vector = c.primitive == Primitive::kPlane || c.primitive == Primitive::kCylinder;
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      if (!(is_vector && k == (c.primitive == Primitive::kPlane ? 0u : 1u))) {
        c.points[k] = c.points[k] + shift;
      }
    }
    out.push_back(std::move(c));
  }
}

void direction_scales(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 48; ++i) {
    AccuracyCase c = random_cases(kAllPrimitives[i % 6], 1, rng.next()).front();
    double scale = i % 2 == 0 ? 1e-150 : 1e150;
    c.id = fmt::format("direction-scale-{}", i);
    c.group = "direction-scale";
    c.direction = scale * c.direction;
    out.push_back(std::move(c));
  }
}

void box_slabs(std::vector<AccuracyCase>& out, SplitMix& rng) {
  Vec3d lo{-1, -1, -1}, hi{1, 2, 3};
  std::vector<std::pair<Vec3d, Vec3d>> rays = {
      {{-1, 0, -5}, {0, 0, 1}},   // origin on the x = min plane, along it: touches the face
      {{1, 0.5, -5}, {0, 0, 1}},  // on x = max
      {{-1, 2, -5}, {0, 0, 1}},   // along an edge
      {{-1, 3, -5}, {0, 0, 1}},   // on the plane, outside the face
      {{-3, -3, -3}, {1, 1, 1}},  // through the corner (-1, -1, -1)
      {{-3, 0, 0}, {1, 0, 0}},    // two zero components, through the middle
      {{-1, -1, 0}, {0, 0, 1}},   // on two slab planes at once
      {{0, 0, 0}, {0, 0, -1}},    // inside
      {{2, 4, 6}, {-1, -2, -3}},  // through the corner (1, 2, 3)
  };
  for (std::size_t i = 0; i < rays.size(); ++i) {
    out.push_back(make(fmt::format("box-slab-{}", i), "box-slab", Primitive::kBox, rays[i].first,
                       rays[i].second, {lo, hi}));
  }
  for (int i = 0; i < 30; ++i) {
    // Rays aimed at a corner or an edge of a random box, to the nearest double.
    Vec3d a{rng.uniform(-1, 0), rng.uniform(-1, 0), rng.uniform(-1, 0)};
    Vec3d b = a + Vec3d{rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)};
    Vec3d target{a.x, i % 2 ? b.y : rng.uniform(a.y, b.y), a.z};
    Vec3d o = target + Vec3d{rng.uniform(-3, -1), rng.uniform(-2, 2), rng.uniform(-3, -1)};
    out.push_back(
        make(fmt::format("box-edge-{}", i), "box-slab", Primitive::kBox, o, target - o, {a, b}));
  }
}

void cylinder_axes(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 30; ++i) {
    Vec3d base{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d axis = i % 3 == 0 ? Vec3d{0, 0, 1} : (i % 3 == 1 ? Vec3d{1, 1, 0} : rng.unit_vector());
    double r = rng.uniform(0.5, 2);
    Vec3d side = normalized(cross(axis, rng.unit_vector()));
    double where = i % 2 == 0 ? 0.5 : 1.5;  // inside or outside the side
    Vec3d o = base + (where * r) * side;
    double tilt = i % 5 < 2 ? 0 : std::pow(10.0, -rng.uniform(6, 12));
    Vec3d d = axis + tilt * side;
    out.push_back(make(fmt::format("cylinder-axis-{}", i), "cylinder-axis", Primitive::kCylinder, o,
                       d, {base, axis}, r));
  }
}

// Directions scaled by 1e-170 to 1e+148: a sphere of radius 1 at distance 5 (two hits, t of
// order 1e-148 to 1e+170), then every primitive at a random scale 10^s, s in [−300, 148]. The
// problem format reads no direction whose squared length overflows a double (about 1.8e308),
// so 1e+148 is as far as a direction of length 5 goes there; the solver itself is tested up to
// 1e+300 (tests/solver_accuracy_test.cpp).
void extreme_direction_scales(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 24; ++i) {
    int j = i / 2;  // 1e+60, 1e+68, ..., 1e+148 and 1e-60, 1e-70, ..., 1e-170
    int exponent = i % 2 == 0 ? 60 + 8 * j : -(60 + 10 * j);
    double scale = std::pow(10.0, exponent);
    Vec3d aim = Vec3d{0, 0, 5} + 0.6 * perpendicular(Vec3d{0, 0, 1}, rng);
    out.push_back(make(fmt::format("extreme-scale-sphere-{}", i), "extreme-scale",
                       Primitive::kSphere, {0, 0, 0}, scale * aim, {{0, 0, 5}}, 1));
  }
  for (int i = 0; i < 60; ++i) {
    AccuracyCase c = random_cases(kAllPrimitives[i % 6], 1, rng.next()).front();
    c.id = fmt::format("extreme-scale-{}", i);
    c.group = "extreme-scale";
    c.direction = std::pow(10.0, rng.uniform(-300, 148)) * c.direction;
    out.push_back(std::move(c));
  }
}

// Objects small next to their distance, where a normal from the rounded hit point
// (P − C)/r loses digits: spheres of radius 6e-9 at 1000 and of radius 1 at 1e11, spheres of
// radius 1e-9 to 1e-6 at 1e2 to 1e4, and thin far cylinders; rays aimed within the object.
void small_far_objects(std::vector<AccuracyCase>& out, SplitMix& rng) {
  auto sphere = [&](std::string id, double r, double dist) {
    Vec3d o{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d u = rng.unit_vector(), c = o + dist * u;
    Vec3d target = c + (r * rng.uniform(-0.9, 0.9)) * perpendicular(u, rng);
    out.push_back(make(std::move(id), "small-far", Primitive::kSphere, o, target - o, {c}, r));
  };
  for (int i = 0; i < 10; ++i) sphere(fmt::format("small-far-sphere-{}", i), 6e-9, 1000);
  for (int i = 0; i < 10; ++i) sphere(fmt::format("far-sphere-1e11-{}", i), 1, 1e11);
  for (int i = 0; i < 20; ++i) {
    sphere(fmt::format("small-far-sphere-{}", i + 10), std::pow(10.0, -rng.uniform(6, 9)),
           std::pow(10.0, rng.uniform(2, 4)));
  }
  for (int i = 0; i < 20; ++i) {
    double r = std::pow(10.0, -rng.uniform(6, 9)), dist = std::pow(10.0, rng.uniform(2, 4));
    Vec3d o{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d u = rng.unit_vector(), axis = perpendicular(u, rng);
    Vec3d base = o + dist * u + rng.uniform(-1, 1) * axis;
    Vec3d across = normalized(cross(axis, u));
    Vec3d target = base + (r * rng.uniform(-0.9, 0.9)) * across + rng.uniform(-1, 1) * axis;
    out.push_back(make(fmt::format("small-far-cylinder-{}", i), "small-far", Primitive::kCylinder,
                       o, target - o, {base, axis}, r));
  }
}

nlohmann::json truth_json(const Truth& t) {
  nlohmann::json j = {{"hit", t.hit}};
  if (t.hit) j["t"] = t.t;
  if (t.boundary) j["boundary"] = true;
  if (t.hit && !t.boundary)
    j["condition"] =
        std::isfinite(t.condition) ? nlohmann::json(t.condition) : nlohmann::json("inf");
  if (!t.hits.empty()) {
    nlohmann::json hits = nlohmann::json::array();
    for (const TruthHit& h : t.hits)
      hits.push_back({{"t", h.t}, {"normal", {h.normal.x, h.normal.y, h.normal.z}}});
    j["hits"] = hits;
  }
  return j;
}

}  // namespace

void scale_and_boundary_cases(std::vector<AccuracyCase>& out, SplitMix& rng) {
  huge_coordinates(out, rng);
  direction_scales(out, rng);
  box_slabs(out, rng);
  cylinder_axes(out, rng);
  extreme_direction_scales(out, rng);
  small_far_objects(out, rng);
}

nlohmann::json corpus_json(const std::vector<TruthCase>& cases) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : cases) {
    nlohmann::json j = case_json(c.input);
    j["truth"] = truth_json(c.truth);
    list.push_back(std::move(j));
  }
  return {{"generated_by", "raygrade bench --write-corpus tests/data/hard_cases.json"},
          {"truth", fmt::format("certified MPFR interval arithmetic at {} bits on the exact "
                                "binary inputs (decimals here read back to the same doubles)",
                                1024)},
          {"cases", list}};
}

std::vector<TruthCase> read_corpus(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw Error(Diagnostic{path, "", 0, 0, Severity::kError, "cannot read the corpus", "io"});
  std::stringstream text;
  text << in.rdbuf();
  JsonLimits limits;
  limits.max_bytes = 64 << 20;
  auto file = parse_json_text(path, text.str(), limits);
  Cursor root(file);
  std::vector<TruthCase> out;
  for (const auto& item : root.at("cases").items()) {
    TruthCase tc;
    tc.input = read_case(item);
    Cursor t = item.at("truth");
    tc.truth.hit = t.at("hit").boolean();
    if (tc.truth.hit) tc.truth.t = t.at("t").number();
    tc.truth.boundary = t.boolean_or("boundary", false);
    if (t.has("condition")) {
      tc.truth.condition = t.at("condition").json().is_string()
                               ? std::numeric_limits<double>::infinity()
                               : t.at("condition").number();
    }
    if (t.has("hits")) {
      for (const auto& h : t.at("hits").items()) {
        h.allow_only({"t", "normal"});
        tc.truth.hits.push_back({h.at("t").number(), h.at("normal").vec3()});
      }
    }
    out.push_back(std::move(tc));
  }
  return out;
}

}  // namespace raygrade
