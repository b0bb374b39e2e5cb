// Plane: reading, reference intersection, and the point-normal and implicit derivations.
#include "shapes/plane.h"

#include "math/unit_vector.h"
#include "sampling/draft.h"
#include "sampling/flats.h"
#include "sampling/split_mix.h"
#include "shapes/accuracy_case.h"
#include "shapes/describe.h"
#include "shapes/flat.h"

namespace raygrade {

std::unique_ptr<Shape> Plane::read(const Cursor& object) {
  std::vector<std::string> keys = common_object_keys();
  keys.insert(keys.end(), {"point", "normal", "d"});
  object.allow_only(keys);
  Vec3d n = object.at("normal").nonzero_vec3();
  bool has_point = object.has("point"), has_d = object.has("d");
  if (has_point == has_d) {
    object.fail(has_point ? "give either 'point' or 'd', not both"
                          : "missing 'point' (or 'd', for n·p + d = 0)",
                has_point ? "invalid" : "missing-key");
  }
  if (has_point) return std::make_unique<Plane>(n, object.at("point").vec3(), std::nullopt);
  return std::make_unique<Plane>(n, std::nullopt, object.at("d").number());
}

nlohmann::json Plane::to_json() const {
  nlohmann::json j = {{"type", "plane"}, {"normal", {normal_.x, normal_.y, normal_.z}}};
  if (point_) {
    j["point"] = {point_->x, point_->y, point_->z};
  } else {
    j["d"] = *d_;
  }
  return j;
}

std::vector<std::string> Plane::methods() const {
  if (point_) return {"point-normal", "implicit"};
  return {"implicit", "point-normal"};
}

Vec3d Plane::some_point() const {
  if (point_) return *point_;
  return (-*d_ / length_squared(normal_)) * normal_;
}

Vec3d Plane::center() const { return some_point(); }

Intersection Plane::intersect(const Ray& ray) const {
  if (std::optional<Intersection> x = intersect_rescaled(*this, ray)) return *x;
  Intersection out;
  Vec3d q = some_point();
  if (parallel_to_plane(normal_, ray.direction)) {
    out.contained = point_ ? in_plane(normal_, q, ray.origin)
                           : std::abs(dot(normal_, ray.origin) + *d_) <=
                                 kParallelRelative * (length(normal_) * (std::abs(ray.origin.x) +
                                                                         std::abs(ray.origin.y) +
                                                                         std::abs(ray.origin.z)) +
                                                      std::abs(*d_));
    return out;
  }
  double t = 0;
  if (point_) {
    std::optional<double> tp = plane_t(ray.origin, ray.direction, normal_, *point_);
    if (!tp) return out;
    t = *tp;
  } else {
    t = -(dot_accurate(normal_, ray.origin) + *d_) / dot_accurate(normal_, ray.direction);
  }
  if (ray.accepts(t)) {
    Hit h;
    h.t = t;
    h.point = ray.at(t);
    h.normal = unit_rounded(Vec3dd(normal_));
    out.hits.push_back(h);
  }
  return out;
}

Derivation Plane::derive(const Ray& ray, std::string_view method,
                         const Overrides* overrides) const {
  bool implicit = method.empty() ? !point_ : method == "implicit";
  Deriver d(implicit ? "implicit" : "point-normal",
            implicit ? "Plane, implicit form N·P + D = 0" : "Plane, point-normal form", overrides);
  E O = d.given("O", "O", ray.origin, "the ray's origin");
  E R = d.given("R", "R", ray.direction, "the ray's direction");
  E N = d.given("N", "N", normal_, "the plane's normal");
  double t = 0, denominator = 0;
  bool through_origin = false;
  if (implicit) {
    if (point_) {
      E V0 = d.given("V0", "V_0", *point_, "a point of the plane");
      d.step("D", "D", -dot(N, V0), "N·V0 + D = 0 since V0 lies in the plane, so D = −N·V0");
    } else {
      d.given("D", "D", *d_, "the plane's constant in N·P + D = 0");
    }
    denominator = d.step("NR", dot(N, R), dot(N, R)).scalar;
    if (denominator == 0) {
      double s = d.step("NO_D", dot(N, O) + d.sym("D"), dot(N, O) + d.sym("D")).scalar;
      through_origin = s == 0;
    } else {
      t = d.step("t", "t", -(dot(N, O) + d.sym("D")) / d.sym("NR"), "from N·(O + tR) + D = 0")
              .scalar;
    }
  } else {
    E P0 = d.given("P0", "P_0", *point_, "a point of the plane");
    denominator = d.step("denominator", dot(N, R), dot(N, R)).scalar;
    double numerator = d.step("numerator", dot(N, P0 - O), dot(N, P0 - O)).scalar;
    if (denominator == 0) {
      through_origin = numerator == 0;
    } else {
      t = d.step("t", "t", d.sym("numerator") / d.sym("denominator"), "from N·(O + tR − P0) = 0")
              .scalar;
    }
  }
  if (denominator == 0) {
    d.note("N·R = 0: the ray is parallel to the plane.");
    if (through_origin) {
      d.conclude(
          "The ray lies in the plane (N·R = 0 and the origin satisfies the plane's "
          "equation): it meets the plane along a whole line, not at a point.");
    } else {
      d.conclude("The ray is parallel to the plane and off it: no intersection.");
    }
    return std::move(d).finish();
  }
  Value P = d.step("P", "P", O + d.sym("t") * R);
  conclude_candidates(d, "plane", ray, {{t, P.vector, range_reason(ray, t)}}, false);
  return std::move(d).finish();
}

void Plane::sketch(Sketch& figure, const std::string& label) const {
  // Unnamed (the lone object of an intersect problem), it is labelled by its type.
  figure.plane(some_point(), normal_, Ink::kObject, label.empty() ? std::string(kType) : label);
}

nlohmann::ordered_json Plane::schema() {
  return nlohmann::ordered_json::parse(R"json(
{
  "description": "{point, normal} or {normal, d} with n·p + d = 0",
  "required": [
    "normal"
  ],
  "properties": {
    "normal": {
      "$ref": "#/$defs/nonzero_vec3"
    },
    "point": {
      "$ref": "#/$defs/vec3"
    },
    "d": {
      "anyOf": [
        {
          "type": "number"
        },
        {
          "$ref": "#/$defs/expression"
        }
      ]
    }
,
    "half_space": {
      "type": "boolean",
      "description": "scenes only: true makes a transparent plane the boundary of the half-space its normal points away from (its inside), instead of a thin sheet"
    }
  },
  "oneOf": [
    {
      "required": [
        "point"
      ]
    },
    {
      "required": [
        "d"
      ]
    }
  ],
  "examples": [
    {
      "type": "plane",
      "point": [
        0,
        0,
        4
      ],
      "normal": [
        0,
        0,
        -1
      ]
    },
    {
      "type": "plane",
      "normal": [
        0,
        1,
        0
      ],
      "d": -3
    }
  ]
}
)json");
}

// The accuracy study's cases of planes.

void Plane::Ladder::random_case(SplitMix& rng, std::vector<Vec3d>& points, double& /*radius*/) {
  Vec3d n = rng.unit_vector();
  points = {n, rng.point(0.5)};
}

void Plane::Ladder::hard_cases(int round, SplitMix& rng, std::vector<AccuracyCase>& out) {
  if (round != 3) return;
  for (int i = 0; i < 60; ++i) {
    double length = rng.uniform(0.5, 3);
    Vec3d n = rng.unit_vector() * length;
    Vec3d p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d aside = rng.unit_vector();
    double off = rng.uniform(-2, 2);
    Vec3d o = p + off * normalized(n) + 0.5 * aside;
    Vec3d along = perpendicular(normalized(n), rng);
    Vec3d d = along + offset(rng, 10, 16) * normalized(n);
    out.push_back(make_case(fmt::format("near-parallel-{}", i), "near-parallel",
                            primitive_of<Plane>(), o, d, {n, p}));
  }
}

// The plane's normal at a point: the given one, the same everywhere.

SurfacePoint Plane::nearest_surface(const Vec3d& p, double /*tie*/) const {
  Vec3d on = some_point();
  return SurfacePoint{p - dot(p - on, normal_) / length_squared(normal_) * normal_, normal_, "",
                      ""};
}

void Plane::derive_normal(Deriver& d, const E& /*P*/, const SurfacePoint& /*s*/,
                          const NormalNames& n) const {
  E given = d.given("n", "n", normal_, "the plane's normal as given");
  d.step(n.name, n.display, given / norm(given), "the same at every point of the plane");
}

// The plane's generator: puts the hit at a lattice point of its plane and builds the ray backwards
// from it.

const std::vector<Outcome>& Plane::outcomes() { return kFlatOutcomes; }

Draft Plane::generate(Prng& rng, std::optional<Outcome> asked) {
  Outcome o = choose_outcome(rng, asked, kFlatOutcomes);
  Frame f = random_frame(rng);
  Vec3d n = reduced(f.normal());
  int py = rng.range(-2, 2), px = rng.range(-2, 2);
  Vec3d p = f.at(px, py);
  nlohmann::ordered_json object = {{"type", "plane"}};
  std::string text;
  if (rng.below(2)) {
    int ay = rng.range(-2, 2), ax = rng.range(-2, 2);
    Vec3d a = f.at(ax, ay);
    object["point"] = vector_json(a);
    object["normal"] = vector_json(n);
    text = fmt::format("the plane through {} with normal {}", point_text(a), point_text(n));
  } else {
    double dd = -dot(n, p);
    object["normal"] = vector_json(n);
    object["d"] = number_json(dd);
    text = fmt::format("the plane n·p + d = 0 with n = {} and d = {}", point_text(n),
                       number_json(dd).dump());
  }
  if (o == Outcome::kHit || o == Outcome::kBehind) return flat_draft(rng, o, p, n, object, text);
  // Parallel rays: in the plane (the tangent case: contained) or one or two normals off it.
  double side = rng.sign(), steps = rng.range(1, 2);
  Vec3d d = reduced(steps * f.e1 + side * f.e2);
  int s = rng.range(1, 3);
  Vec3d origin = p - double(s) * d;
  if (o == Outcome::kMiss)
    return intersect_draft(origin + double(rng.sign()) * n, d, object, text, {});
  return intersect_draft(origin, d, object, text, {}, true);
}

const std::vector<PrimitiveMistake>& Plane::mistakes() {
  static const std::vector<PrimitiveMistake> m = {
      {{"plane-d-sign", "sign", "Sign slip in the plane's D",
        "In N·P + D = 0 a point V0 of the plane gives N·V0 + D = 0, so D = −N·V0 (not +N·V0).", 0},
       [](std::string_view step, const E& f) -> std::optional<E> {
         if (step != "D" || f.empty()) return std::nullopt;
         return -f;
       }},
  };
  return m;
}

}  // namespace raygrade
