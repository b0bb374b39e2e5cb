// Box: reading, reference slab intersection and seed 004's slab derivation.
#include "shapes/box.h"

#include <algorithm>

#include "derivation/number_format.h"
#include "sampling/draft.h"
#include "sampling/solids.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"

namespace raygrade {

std::unique_ptr<Shape> Box::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.insert(keys.end(), {"min", "max"});
  object.allow_only(keys);
  Vec3d lo = object.at("min").vec3(), hi = object.at("max").vec3();
  for (int i = 0; i < 3; ++i) {
    if (!(lo[i] < hi[i])) {
      object.at("max").fail(
          fmt::format("degenerate box: max[{}] = {} is not above min[{}] = {}", i, hi[i], i, lo[i]),
          "degenerate");
    }
  }
  return std::make_unique<Box>(lo, hi);
}

nlohmann::json Box::to_json() const {
  return {{"type", "box"}, {"min", {lo_.x, lo_.y, lo_.z}}, {"max", {hi_.x, hi_.y, hi_.z}}};
}

namespace {

const char* kAxis[] = {"x", "y", "z"};

// The point on the face of `axis` at t, with that coordinate set exactly to the face.
Hit face_hit(const Ray& ray, double t, int axis, bool entering, const Vec3d& lo, const Vec3d& hi) {
  Hit h;
  h.t = t;
  h.point = ray.at(t);
  double s = ray.direction[axis] > 0 ? 1 : -1;
  if (entering) s = -s;
  h.normal = Vec3d{};
  h.normal[axis] = s;
  h.point[axis] = s < 0 ? lo[axis] : hi[axis];
  h.part = fmt::format("face {} = {}", kAxis[axis], h.point[axis]);
  return h;
}

}  // namespace

namespace {

// Each slab end (bound − o)/d rounds twice from exact input, so it is within 2 ulps of the
// truth; a t_enter above t_exit by less than twice that is a ray touching an edge or corner
// (closed box), not a miss.
constexpr double kSlabUlps = 4 * 2.220446049250313e-16;

// A ray that touches the box along an edge or at a corner whose slab ends, rounded, cross.
bool touches_edge(const Ray& ray, const SlabInterval<double>& s, const Vec3d& lo, const Vec3d& hi) {
  if (s.enter_axis < 0 || s.exit_axis < 0) return false;
  for (int i = 0; i < 3; ++i) {
    if (ray.direction[i] == 0 && (ray.origin[i] < lo[i] || ray.origin[i] > hi[i])) return false;
  }
  return s.t_enter - s.t_exit <= kSlabUlps * (std::abs(s.t_enter) + std::abs(s.t_exit));
}

}  // namespace

Intersection Box::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  auto s = slab_interval(ray.origin, ray.direction, lo_, hi_);
  if (!s.hit && touches_edge(ray, s, lo_, hi_)) {
    if (ray.accepts(s.t_enter)) {
      out.hits.push_back(face_hit(ray, s.t_enter, s.enter_axis, true, lo_, hi_));
    }
    return out;
  }
  if (!s.hit) return out;
  if (s.enter_axis >= 0 && ray.accepts(s.t_enter)) {
    out.hits.push_back(face_hit(ray, s.t_enter, s.enter_axis, true, lo_, hi_));
  }
  if (s.exit_axis >= 0 && ray.accepts(s.t_exit) && s.t_exit != s.t_enter) {
    out.hits.push_back(face_hit(ray, s.t_exit, s.exit_axis, false, lo_, hi_));
  }
  finish_hits(out.hits);
  return out;
}

Derivation Box::derive(const Ray& ray, std::string_view /*method*/,
                       const Overrides* overrides) const {
  Deriver d("slab", "Box: the slab method", overrides);
  E O = d.given("O", "o", ray.origin, "the ray's origin");
  E D = d.given("D", "d", ray.direction, "the ray's direction");
  d.given("min", "min", lo_, "the box's low corner");
  d.given("max", "max", hi_, "the box's high corner");
  std::vector<E> lows, highs;
  bool empty = false;
  for (int i = 0; i < 3; ++i) {
    std::string ax = kAxis[i];
    E o = d.given("o_" + ax, "o_" + ax, ray.origin[i]);
    E di = d.given("d_" + ax, "d_" + ax, ray.direction[i]);
    E mn = d.given("min_" + ax, "min_" + ax, lo_[i]);
    E mx = d.given("max_" + ax, "max_" + ax, hi_[i]);
    if (ray.direction[i] == 0) {
      bool inside = ray.origin[i] >= lo_[i] && ray.origin[i] <= hi_[i];
      d.note(
          fmt::format("d_{} = 0: the ray never leaves its {} slab; o_{} = {} is {} [{}, {}], so "
                      "{}.",
                      ax, ax, ax, format_number(ray.origin[i]), inside ? "inside" : "outside",
                      format_number(lo_[i]), format_number(hi_[i]),
                      inside ? "this slab allows every t" : "the ray misses the box"));
      if (!inside) empty = true;
      continue;
    }
    bool swap = ray.direction[i] < 0;
    d.step("t_low_" + ax, "t_low," + ax, ((swap ? mx : mn) - o) / di,
           swap ? fmt::format("d_{} < 0, so the slab's ends swap: the low end comes from max_{}",
                              ax, ax)
                : "");
    d.step("t_high_" + ax, "t_high," + ax, ((swap ? mn : mx) - o) / di);
    lows.push_back(d.sym("t_low_" + ax));
    highs.push_back(d.sym("t_high_" + ax));
  }
  if (empty || lows.empty()) {
    d.conclude(empty ? "The ray does not hit the box: it runs parallel to a slab it lies outside."
                     : "The ray does not move.");
    return std::move(d).finish();
  }
  double enter =
      d.step("t_enter", "t_enter", lows.size() == 1 ? lows[0] : max(lows), "the largest low end")
          .scalar;
  double exit =
      d.step("t_exit", "t_exit", highs.size() == 1 ? highs[0] : min(highs), "the smallest high end")
          .scalar;
  if (enter > exit) {
    d.note("t_enter > t_exit: the slabs' intervals do not overlap.");
    d.conclude("The ray does not hit the box: the slabs' intervals do not overlap.");
    return std::move(d).finish();
  }
  std::vector<Candidate> candidates;
  Value P0 = d.step("P_enter", "P_enter", O + d.sym("t_enter") * D);
  candidates.push_back({enter, P0.vector, range_reason(ray, enter)});
  if (exit != enter) {
    Value P1 = d.step("P_exit", "P_exit", O + d.sym("t_exit") * D);
    candidates.push_back({exit, P1.vector, range_reason(ray, exit)});
  }
  conclude_candidates(d, "box", ray, candidates, true);
  return std::move(d).finish();
}

void Box::sketch(Sketch& figure, const std::string& label) const {
  // The twelve edges: from each corner with a low coordinate, one step along that axis.
  for (int corner = 0; corner < 8; ++corner) {
    Vec3d p{corner & 1 ? hi_.x : lo_.x, corner & 2 ? hi_.y : lo_.y, corner & 4 ? hi_.z : lo_.z};
    for (int axis = 0; axis < 3; ++axis) {
      if (corner & (1 << axis)) continue;
      Vec3d q = p;
      q[axis] = hi_[axis];
      figure.path({p, q}, false, Ink::kObject, corner == 0 && axis == 0 ? label : "");
    }
  }
}

nlohmann::ordered_json Box::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "required": [
    "min",
    "max"
  ],
  "properties": {
    "min": {
      "$ref": "#/$defs/vec3"
    },
    "max": {
      "$ref": "#/$defs/vec3"
    }
  },
  "examples": [
    {
      "type": "box",
      "min": [
        -1,
        -1,
        3
      ],
      "max": [
        1,
        1,
        5
      ]
    }
  ]
}
)json");
}

// The accuracy study's cases of boxes.

void Box::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& /*radius*/) {
  Vec3d lo = rng.point(1),
        size{rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5)};
  points = {lo, lo + size};
}

void Box::Ladder::hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out) {
  if (round != 5) return;
  auto box_case = [&](std::string id, Vec3d o, Vec3d d, Vec3d lo, Vec3d hi) {
    out.push_back(make_case(std::move(id), "box-slab", primitive_of<Box>(), o, d, {lo, hi}));
  };
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
    box_case(fmt::format("box-slab-{}", i), rays[i].first, rays[i].second, lo, hi);
  }
  for (int i = 0; i < 30; ++i) {
    // Rays aimed at a corner or an edge of a random box, to the nearest double.
    Vec3d a{rng.uniform(-1, 0), rng.uniform(-1, 0), rng.uniform(-1, 0)};
    Vec3d b = a + Vec3d{rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)};
    Vec3d target{a.x, i % 2 ? b.y : rng.uniform(a.y, b.y), a.z};
    Vec3d o = target + Vec3d{rng.uniform(-3, -1), rng.uniform(-2, 2), rng.uniform(-3, -1)};
    box_case(fmt::format("box-edge-{}", i), o, target - o, a, b);
  }
}

// The box's normal at a point: its face's, ±x, ±y or ±z; an edge, where two faces meet, has
// none.

SurfacePoint Box::nearest_surface(const Vec3d& p, double tie) const {
  const char* axis[] = {"x", "y", "z"};
  std::vector<SurfaceCandidate> cs;
  for (int i = 0; i < 3; ++i) {
    for (int side = 0; side < 2; ++side) {
      Vec3d q{std::clamp(p.x, lo_.x, hi_.x), std::clamp(p.y, lo_.y, hi_.y),
              std::clamp(p.z, lo_.z, hi_.z)};
      double face = side ? hi_[i] : lo_[i];
      q[i] = face;
      Vec3d n{};
      n[i] = side ? 1 : -1;
      cs.push_back({q, n, fmt::format("face {} = {}", axis[i], format_number(face))});
    }
  }
  return nearest_of(cs, p, tie);
}

void Box::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& s,
                        const NormalNames& n) const {
  d.given(n.name, n.display, s.normal, fmt::format("P is on the {}: its outward normal", s.part));
}

// The box's generator: builds the answer first (hits at lattice points, at integer t) and the ray
// backwards from it.

namespace {

// Boxes have no tangent case here (a ray grazing an edge is an edge case of the slabs).
const std::vector<Outcome> kBoxOutcomes = {Outcome::kHit, Outcome::kMiss, Outcome::kInside,
                                           Outcome::kBehind};

}  // namespace

const std::vector<Outcome>& Box::outcomes() { return kBoxOutcomes; }

Draft Box::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kBoxOutcomes);
  AxisMap map = random_axis_map(rng);
  Vec3d lo = random_point(rng, 3);
  Vec3d size{double(rng.range(2, 5)), double(rng.range(2, 5)), double(rng.range(2, 5))};
  Vec3d hi = lo + size;
  // Enter through the face x = lo.x and leave through x = hi.x, away from every edge.
  auto inner = [&](int axis) { return double(rng.range(1, static_cast<int>(size[axis]) - 1)); };
  Vec3d p0, p1, full;
  int steps = 1;
  do {
    p0 = {lo.x, lo.y + inner(1), lo.z + inner(2)};
    p1 = {hi.x, lo.y + inner(1), lo.z + inner(2)};
    full = p1 - p0;
    steps = static_cast<int>(component_gcd(full));
  } while (o == Outcome::kInside && steps < 2);
  Vec3d d = reduced(full);
  int s = rng.range(1, 3);
  Vec3d origin;
  std::vector<KnownHit> hits;
  if (o != Outcome::kMiss) {
    chord_ray(rng, o, p0, p1, d, steps, s, origin, hits);
  } else {
    // The same line moved past the box's top in y: clear of it by at least one unit.
    origin = p0 - s * d + Vec3d{0, size.y + std::abs(p1.y - p0.y) + 1, 0};
  }
  Vec3d a = map(lo), b = map(hi);
  Vec3d mn{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  Vec3d mx{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  nlohmann::ordered_json object = {
      {"type", "box"}, {"min", vector_json(mn)}, {"max", vector_json(mx)}};
  for (auto& h : hits) h.point = map(h.point);
  return intersect_draft(
      map(origin), map(d), object,
      fmt::format("the axis-aligned box from {} to {}", point_text(mn), point_text(mx)), hits);
}

}  // namespace raygrade
