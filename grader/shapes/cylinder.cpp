// Cylinder: reading, reference intersection, and the quadratic derivation of seed 000.
#include "shapes/cylinder.h"

#include <algorithm>

#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/solids.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"
#include "shapes/round.h"

namespace raygrade {

Cylinder::Cylinder(Vec3d base, Vec3d axis, double radius, std::optional<double> height, bool capped)
    : base_(base),
      axis_given_(axis),
      axis_(normalized(axis)),
      radius_(radius),
      height_(height),
      capped_(capped) {}

std::unique_ptr<Shape> Cylinder::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.insert(keys.end(), {"base", "axis", "radius", "height", "capped"});
  object.allow_only(keys);
  Vec3d axis = object.has("axis") ? object.at("axis").nonzero_vec3() : Vec3d{0, 0, 1};
  std::optional<double> height;
  if (object.has("height")) height = object.at("height").positive_number();
  bool capped = object.boolean_or("capped", false);
  if (capped && !height)
    object.at("capped").fail("an infinite cylinder cannot have caps: give a height", "invalid");
  return std::make_unique<Cylinder>(object.at("base").vec3(), axis,
                                    object.at("radius").positive_number(), height, capped);
}

nlohmann::json Cylinder::to_json() const {
  nlohmann::json j = {{"type", "cylinder"},
                      {"base", {base_.x, base_.y, base_.z}},
                      {"axis", {axis_given_.x, axis_given_.y, axis_given_.z}},
                      {"radius", radius_}};
  if (height_) j["height"] = *height_;
  if (capped_) j["capped"] = true;
  return j;
}

Vec3d Cylinder::center() const { return height_ ? base_ + (*height_ / 2) * axis_ : base_; }

double Cylinder::extent() const { return height_ ? std::max(radius_, *height_ / 2) : 2 * radius_; }

Intersection Cylinder::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  Vec3d f = ray.origin - base_;
  double fa = dot(f, axis_), da = dot(ray.direction, axis_);
  double scale = length(f) + length(ray.direction) + radius_ + (height_ ? *height_ : 0);
  double seam = kSeamRelative * scale;
  bool parallel =
      length(cross(axis_, ray.direction)) <= kAxisParallelRelative * length(ray.direction);
  // Compute the side's hits
  if (parallel) {
    // The ray never crosses the side; it lies in it when its distance to the axis is r.
    Vec3d radial = f - fa * axis_;
    if (std::abs(length(radial) - radius_) <= seam) {
      if (!height_) {
        out.contained = true;  // it meets the infinite side along a whole line
        return out;
      }
      // On a finite side it touches the surface from rim to rim.
      for (double level : {0.0, *height_}) {
        double t = (level - fa) / da;
        if (ray.accepts(t)) out.hits.push_back(Hit{t, ray.at(t), normalized(radial), {}, "rim"});
      }
    }
  } else {
    // The side's roots and normals in double-double, rounded once, as the sphere's: the axis
    // normalized in it, and the normal the part of O − B + t·D across the axis, from the exact
    // O − B and the unrounded t.
    Vec3dd o(ray.origin), d(ray.direction), base(base_), axis = unit_dd(Vec3dd(axis_given_));
    Roots<DoubleDouble> roots = cylinder_side_roots(o, d, base, axis, DoubleDouble(radius_));
    DoubleDouble ts[2] = {roots.t0, roots.t1};
    for (int i = 0; i < roots.count; ++i) {
      double t = static_cast<double>(ts[i]);
      if (!ray.accepts(t)) continue;
      Vec3d p = ray.at(t);
      double h = dot(p - base_, axis_);
      if (height_ && (h < -seam || h > *height_ + seam)) continue;
      Vec3dd v = (o - base) + ts[i] * d;
      Vec3d normal = unit_rounded(v - dot(v, axis) * axis);
      out.hits.push_back(Hit{t, p, normal, std::nullopt, "side"});
    }
  }
  // Compute the caps' hits
  if (capped_ && da != 0) {
    for (int cap = 0; cap < 2; ++cap) {
      double level = cap == 0 ? 0 : *height_;
      double t = (level - fa) / da;
      if (!ray.accepts(t)) continue;
      Vec3d p = ray.at(t);
      Vec3d radial = (p - base_) - dot(p - base_, axis_) * axis_;
      if (length(radial) > radius_ + seam) continue;
      out.hits.push_back(
          Hit{t, p, cap == 0 ? -axis_ : axis_, std::nullopt, cap == 0 ? "bottom cap" : "top cap"});
    }
  }
  finish_hits(out.hits, seam);
  return out;
}

Derivation Cylinder::derive(const Ray& ray, std::string_view /*method*/,
                            const Overrides* overrides) const {
  Deriver d("quadratic",
            capped_   ? "Cylinder: the side's quadratic, the height test and the caps"
            : height_ ? "Cylinder: the side's quadratic, then the height test"
                      : "Infinite cylinder: the side's quadratic",
            overrides);
  bool vertical = axis_given_.x == 0 && axis_given_.y == 0 && axis_given_.z > 0;
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E D = d.given("D", "D", ray.direction, "the ray's direction");
  E B = d.given("B", "B", base_, "the base point on the axis");
  E r = d.given("r", "r", radius_);
  E A;
  if (vertical) {
    // Seed 000: x² + y² = r² (centered at the origin) or (x − a)² + (y − b)² = r².
    E px = d.given("px", "p_x", ray.origin.x), py = d.given("py", "p_y", ray.origin.y);
    E vx = d.given("vx", "v_x", ray.direction.x), vy = d.given("vy", "v_y", ray.direction.y);
    bool centered = base_.x == 0 && base_.y == 0;
    E cx = 0, cy = 0;
    if (!centered) {
      cx = d.given("cx", "c_x", base_.x, "the axis passes through (c_x, c_y), the seed's (a, b)");
      cy = d.given("cy", "c_y", base_.y);
    }
    E ex = centered ? px : px - cx, ey = centered ? py : py - cy;
    d.step("a", "a", square(vx) + square(vy),
           "substituting x = p_x + t v_x, y = p_y + t v_y into the circle's equation");
    d.step("b", "b", 2 * (ex * vx + ey * vy));
    d.step("c", "c", square(ex) + square(ey) - square(r));
    A = vec({0, 0, 1});
  } else {
    A = d.given("A", "A", axis_, "the unit axis");
    d.step("f", "f", O - B);
    d.step("D_perp", "D_perp", D - dot(D, A) * A, "D without its component along the axis");
    d.step("f_perp", "f_perp", d.sym("f") - dot(d.sym("f"), A) * A);
    d.step("a", "a", dot(d.sym("D_perp"), d.sym("D_perp")));
    d.step("b", "b", 2 * dot(d.sym("f_perp"), d.sym("D_perp")));
    d.step("c", "c", dot(d.sym("f_perp"), d.sym("f_perp")) - square(r));
  }
  double a = d.scalar("a");
  std::vector<Candidate> candidates;
  if (a == 0) {
    d.note("a = 0: the ray runs parallel to the axis and never crosses the side.");
  } else {
    double disc =
        d.step("discriminant", "Delta", square(d.sym("b")) - 4 * d.sym("a") * d.sym("c")).scalar;
    if (disc < 0) {
      d.note("Δ < 0: the ray misses the infinite cylinder.");
    } else {
      double t0 =
          d.step("t0", "t_0", (-d.sym("b") - sqrt(d.sym("discriminant"))) / (2 * d.sym("a")))
              .scalar;
      double t1 =
          d.step("t1", "t_1", (-d.sym("b") + sqrt(d.sym("discriminant"))) / (2 * d.sym("a")))
              .scalar;
      std::vector<double> ts = {t0};
      if (t1 != t0) ts.push_back(t1);
      for (std::size_t k = 0; k < ts.size(); ++k) {
        std::string p = k == 0 ? "P0" : "P1";
        Value P = d.step(p, k == 0 ? "P_0" : "P_1", O + d.sym(k == 0 ? "t0" : "t1") * D);
        std::string reason = range_reason(ray, ts[k]);
        if (height_) {
          std::string h = k == 0 ? "h0" : "h1";
          double hv = d.step(h, k == 0 ? "h_0" : "h_1", dot(d.sym(p) - B, A),
                             fmt::format("height along the axis: must lie in [0, {}]",
                                         format_number(*height_)))
                          .scalar;
          if (reason.empty() && (hv < 0 || hv > *height_)) {
            reason =
                fmt::format("it lies outside the cylinder's height (h = {})", format_number(hv));
          }
        }
        candidates.push_back({ts[k], P.vector, reason});
      }
    }
  }
  if (capped_) {
    double da = d.step("D_axis", dot(D, A), dot(D, A)).scalar;
    if (da != 0) {
      for (int cap = 0; cap < 2; ++cap) {
        std::string t = cap == 0 ? "t_bottom" : "t_top";
        E level = cap == 0 ? E(0) : E(*height_);
        double tv = d.step(t, t, (level - dot(O - B, A)) / d.sym("D_axis"),
                           cap == 0 ? "the bottom cap's plane" : "the top cap's plane")
                        .scalar;
        std::string p = cap == 0 ? "P_bottom" : "P_top";
        Value P = d.step(p, p, O + d.sym(t) * D);
        std::string rho = cap == 0 ? "rho2_bottom" : "rho2_top";
        double rv = d.step(rho, cap == 0 ? "rho_bottom^2" : "rho_top^2",
                           square(d.sym(p) - B - dot(d.sym(p) - B, A) * A),
                           "squared distance from the axis: ≤ r² on the cap")
                        .scalar;
        std::string reason = range_reason(ray, tv);
        if (reason.empty() && rv > radius_ * radius_) reason = "it lies outside the cap's disc";
        candidates.push_back({tv, P.vector, reason});
      }
      std::sort(candidates.begin(), candidates.end(),
                [](const Candidate& x, const Candidate& y) { return x.t < y.t; });
    }
  }
  conclude_candidates(d, "cylinder", ray, candidates, true);
  return std::move(d).finish();
}

void Cylinder::sketch(Sketch& figure, const std::string& label) const {
  figure.cylinder(base_, axis_, radius_, height_ ? *height_ : 0, Ink::kObject, label);
}

// The axis point of the base labelled with the circle's equation in the derivation's symbols
// (seed 000: x² + y² = r², or (x − c_x)² + (y − c_y)² = r² with the centre written (c_x, c_y)),
// and the radius r drawn from it toward the side the ray comes from, so that it stays clear of
// the ray when the ray crosses the axis.
void Cylinder::sketch_symbols(Sketch& figure, const Ray& ray,
                              const std::vector<std::string>& symbols) const {
  auto uses = [&](const char* name) {
    return std::find(symbols.begin(), symbols.end(), name) != symbols.end();
  };
  bool vertical = axis_given_.x == 0 && axis_given_.y == 0 && axis_given_.z > 0;
  std::string label = "axis";
  if (vertical) {
    label = uses("cx") || uses("cy") ? "(c_x, c_y): (x − c_x)² + (y − c_y)² = r²"
                                     : "(0, 0): x² + y² = r²";
  }
  figure.point(base_, Ink::kGuide, label);
  if (!uses("r")) return;
  Vec3d toward = -(ray.direction - dot(ray.direction, axis_) * axis_);
  if (length(toward) <= kAxisParallelRelative * length(ray.direction)) {
    toward = ray.origin - base_;
    toward = toward - dot(toward, axis_) * axis_;
  }
  if (length(toward) == 0) {
    Vec3d helper = std::abs(axis_.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    toward = cross(axis_, helper);
  }
  figure.path({base_ + radius_ * normalized(toward), base_}, false, Ink::kGuide, "r");
}

nlohmann::ordered_json Cylinder::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "required": [
    "base",
    "radius"
  ],
  "properties": {
    "base": {
      "$ref": "#/$defs/vec3"
    },
    "axis": {
      "$ref": "#/$defs/nonzero_vec3",
      "default": [
        0,
        0,
        1
      ]
    },
    "radius": {
      "$ref": "#/$defs/positive"
    },
    "height": {
      "$ref": "#/$defs/positive",
      "description": "finite from base along the unit axis; infinite when left out"
    },
    "capped": {
      "type": "boolean",
      "default": false
    }
  },
  "dependentRequired": {
    "capped": [
      "height"
    ]
  },
  "examples": [
    {
      "type": "cylinder",
      "base": [
        0,
        0,
        0
      ],
      "axis": [
        0,
        1,
        0
      ],
      "radius": 1
    },
    {
      "type": "cylinder",
      "base": [
        0,
        -1,
        4
      ],
      "axis": [
        0,
        1,
        0
      ],
      "radius": 1,
      "height": 2,
      "capped": true
    }
  ]
}
)json");
}

// The accuracy study's cases of infinite cylinders.

void Cylinder::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& radius) {
  points = {rng.point(0.5), rng.unit_vector()};
  radius = rng.uniform(0.3, 1);
}

namespace {

AccuracyCase cylinder_case(std::string id, std::string group, Vec3d o, Vec3d d, Vec3d base,
                           Vec3d axis, double r) {
  return make_case(std::move(id), std::move(group), primitive_of<Cylinder>(), o, d, {base, axis},
                   r);
}

void cylinder_grazing(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    Vec3d base{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d axis = i % 3 == 0 ? Vec3d{0, 0, 1} : rng.unit_vector();
    Vec3d e1 = perpendicular(axis, rng), e2 = normalized(cross(axis, e1));
    double r = rng.uniform(0.5, 2), p = r * (1 + offset(rng, 4, 15));
    double z0 = rng.uniform(-2, 2), z1 = rng.uniform(-2, 2);
    Vec3d o = base + p * e2 + 5.0 * e1 + z0 * axis;
    Vec3d d = -5.0 * e1 + (z1 - z0) * axis;
    out.push_back(
        cylinder_case(fmt::format("grazing-cylinder-{}", i), "grazing", o, d, base, axis, r));
  }
}

void along_axis(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 30; ++i) {
    Vec3d base{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d axis = i % 3 == 0 ? Vec3d{0, 0, 1} : (i % 3 == 1 ? Vec3d{1, 1, 0} : rng.unit_vector());
    double r = rng.uniform(0.5, 2);
    Vec3d side = normalized(cross(axis, rng.unit_vector()));
    double where = i % 2 == 0 ? 0.5 : 1.5;  // inside or outside the side
    Vec3d o = base + (where * r) * side;
    double tilt = i % 5 < 2 ? 0 : std::pow(10.0, -rng.uniform(6, 12));
    Vec3d d = axis + tilt * side;
    out.push_back(
        cylinder_case(fmt::format("cylinder-axis-{}", i), "cylinder-axis", o, d, base, axis, r));
  }
}

// Thin far cylinders, where a normal from the rounded hit point loses digits; rays aimed
// within the cylinder.
void small_far(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 20; ++i) {
    double r = std::pow(10.0, -rng.uniform(6, 9)), dist = std::pow(10.0, rng.uniform(2, 4));
    Vec3d o{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d u = rng.unit_vector(), axis = perpendicular(u, rng);
    Vec3d base = o + dist * u + rng.uniform(-1, 1) * axis;
    Vec3d across = normalized(cross(axis, u));
    double height = rng.uniform(-1, 1), aside = rng.uniform(-0.9, 0.9);
    Vec3d target = base + (r * aside) * across + height * axis;
    out.push_back(cylinder_case(fmt::format("small-far-cylinder-{}", i), "small-far", o, target - o,
                                base, axis, r));
  }
}

}  // namespace

void Cylinder::Ladder::hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out) {
  switch (round) {
    case 0: cylinder_grazing(out, rng); break;
    case 1:
      // Exact tangents: integer data, the discriminant is exactly zero.
      out.push_back(
          cylinder_case("tangent-3", "tangent", {-5, 1, 0}, {1, 0, 0.5}, {0, 0, 0}, {0, 0, 1}, 1));
      out.push_back(
          cylinder_case("tangent-4", "tangent", {3, -7, 2}, {0, 1, 0}, {0, 0, 0}, {0, 0, 2}, 3));
      break;
    case 2:
      out.push_back(cylinder_case("on-surface-2", "on-surface", {0, 2, 7}, {0, -1, 1}, {0, 0, 0},
                                  {0, 0, 1}, 2));
      break;
    case 6: along_axis(out, rng); break;
    case 8: small_far(out, rng); break;
    default: break;
  }
}

// The cylinder's normal at a point: the part of P − B across the axis on the side, ±â on a
// cap; a capped cylinder's rim, where side and cap meet, has none.

SurfacePoint Cylinder::nearest_surface(const Vec3d& p, double tie) const {
  Vec3d q = p - base_;
  double y = dot(q, axis_);
  Vec3d radial = q - y * axis_;
  Vec3d out = unit_across(p, base_, axis_);
  std::vector<SurfaceCandidate> cs;
  double ys = height_ ? std::clamp(y, 0.0, *height_) : y;
  cs.push_back({base_ + ys * axis_ + radius_ * out, radial, "side"});
  if (capped_ && height_) {
    Vec3d across = length(radial) <= radius_ ? radial : radius_ * out;
    cs.push_back({base_ + across, -axis_, "bottom cap"});
    cs.push_back({base_ + *height_ * axis_ + across, axis_, "top cap"});
  }
  return nearest_of(cs, p, tie);
}

void Cylinder::derive_normal(Deriver& d, const E& P, const SurfacePoint& s,
                             const NormalNames& n) const {
  E B = d.given("B", "B", base_, "the centre of the base");
  E a = d.given("a_hat", "â", axis_, "the unit axis");
  if (s.part == "side") {
    d.step("q", "q", P - B);
    d.step("y", "y", dot(d.sym("q"), a), "the height of P along the axis");
    d.step("radial", "q_⊥", d.sym("q") - d.sym("y") * a, "the part of q across the axis");
    d.step(n.name, n.display, d.sym("radial") / norm(d.sym("radial")),
           "the outward unit normal of the side");
  } else {
    d.step(n.name, n.display, s.part == "top cap" ? a : -a,
           fmt::format("P is on the {}: the normal is the axis, pointing out", s.part));
  }
}

// The cylinder's generator: builds the answer first (hits at lattice points, at integer t) and the
// ray backwards from it.

const std::vector<Outcome>& Cylinder::outcomes() { return kSolidOutcomes; }

Draft Cylinder::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kSolidOutcomes);
  AxisMap map = random_axis_map(rng);
  int r = rng.pick(std::vector<int>{2, 3, 5, 10});
  Vec3d base = random_point(rng, 3);
  const auto& points = lattice_circle(r);
  Vec3d up{0, 0, 1};
  int s = rng.range(1, 3);
  // Built around the z axis, then turned by `map` (a rotation or reflection of the axes).
  Vec3d origin, d;
  std::vector<KnownHit> hits;
  int top = 0;  // the highest hit's height above the base
  if (o == Outcome::kTangent || o == Outcome::kMiss) {
    Vec3d a = rng.pick(points);
    int z = rng.range(1, 3);
    d = reduced(Vec3d{-a.y, a.x, 0}) + double(rng.range(-1, 1)) * up;
    Vec3d p = base + a + double(z) * up;
    origin = p - s * d;
    if (o == Outcome::kMiss)
      origin = origin + a;
    else
      hits.push_back({double(s), p});
    top = z;
  } else {
    Chord ch;
    int z0 = 0, z1 = 0;
    do {
      ch = random_chord(rng, points, 1);
      z0 = rng.range(1, 4);
      z1 = rng.range(1, 4);
      Vec3d full = (ch.b + double(z1) * up) - (ch.a + double(z0) * up);
      ch.steps = static_cast<int>(component_gcd(full));
      ch.d = reduced(full);
    } while (o == Outcome::kInside && ch.steps < 2);
    d = ch.d;
    Vec3d p0 = base + ch.a + double(z0) * up, p1 = base + ch.b + double(z1) * up;
    top = std::max(z0, z1);
    chord_ray(rng, o, p0, p1, d, ch.steps, s, origin, hits);
  }
  nlohmann::ordered_json object = {{"type", "cylinder"},
                                   {"base", vector_json(map(base))},
                                   {"axis", vector_json(map(up))},
                                   {"radius", r}};
  std::string text =
      fmt::format("the infinite cylinder of radius {} around the axis through {} along {}", r,
                  point_text(map(base)), direction_text(map(up)));
  if (rng.below(2) && o != Outcome::kInside) {
    int height = top + rng.range(1, 2);
    bool capped = rng.below(2);
    object["height"] = height;
    if (capped) object["capped"] = true;
    text = fmt::format(
        "the {} cylinder of radius {} and height {} whose axis starts at {} along {}",
        capped ? "closed" : "open", r, height, point_text(map(base)), direction_text(map(up)));
  }
  for (auto& h : hits) h.point = map(h.point);
  return intersect_draft(map(origin), map(d), object, text, hits);
}

// Seed 000: (p_x + t v_x)² expanded as p_x² + 2t v_x + t² v_x², so b = 2v_x + 2v_y.
const std::vector<PrimitiveMistake>& Cylinder::mistakes() {
  static const std::vector<PrimitiveMistake> m = {
      {{"cylinder-b-no-origin", "algebra", "Origin terms missing from b",
        "(p_x + t v_x)² = p_x² + 2 p_x v_x t + v_x² t²: the middle term keeps p_x, so "
        "b = 2(p_x v_x + p_y v_y), not 2v_x + 2v_y.",
        0},
       [](std::string_view step, const E& f) -> std::optional<E> {
         if (step != "b" || !mentions_symbol(f, "vx") || !mentions_symbol(f, "vy"))
           return std::nullopt;
         return 2 * sym("vx", "v_x") + 2 * sym("vy", "v_y");
       }},
  };
  return m;
}

}  // namespace raygrade
