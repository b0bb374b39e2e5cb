// The list of primitives: every primitive is one type in `Primitives`, and the concept
// PrimitiveType says what each provides. The shape table (and through it reading, the schema's
// object types and the docs' table) is derived from this list.
#pragma once

#include <concepts>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sampling/outcome.h"
#include "shapes/box.h"
#include "shapes/capsule.h"
#include "shapes/cone.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/plane.h"
#include "shapes/polygon.h"
#include "shapes/shape.h"
#include "shapes/sphere.h"
#include "shapes/surface_point.h"
#include "shapes/triangle.h"

namespace raygrade {

// What a primitive provides beside Shape's virtual functions (the reference intersection, the
// derivations, the sketch, solidity, the normal rule, the quadratic's steps): its `type` key and
// a one-line summary of its parameters, its reader, and its fragment of the problem schema
// (docs/problem.schema.json, written by `raygrade schema`), its generator, a row of
// `raygrade generate`'s table, and its normal at a point of its surface (the normal kind).
template <typename T>
concept PrimitiveType = std::derived_from<T, Shape> && std::is_final_v<T> &&
    requires(const T& shape, const Cursor& object, Prng& rng, std::optional<Outcome> outcome,
             const Vec3d& p, Deriver& d, const E& P, const SurfacePoint& s, const NormalNames& n) {
  { T::kType } -> std::convertible_to<std::string_view>;
  { T::kSummary } -> std::convertible_to<std::string_view>;
  { T::read(object) } -> std::same_as<std::unique_ptr<Shape>>;
  { T::schema() } -> std::same_as<nlohmann::ordered_json>;
  // Its generator (in the primitive's own .cpp): the outcomes it can build (Outcome,
  // sampling/outcome.h), and a problem with nice numbers for one of them.
  { T::outcomes() } -> std::same_as<const std::vector<Outcome>&>;
  { T::generate(rng, outcome) } -> std::same_as<Draft>;
  // The normal kind (in its own .cpp; shapes/surface_point.h): the part of its
  // surface nearest to a point with the outward normal there, and the steps that derive it.
  { shape.nearest_surface(p, 0.0) } -> std::same_as<SurfacePoint>;
  { shape.derive_normal(d, P, s, n) } -> std::same_as<void>;
};

template <typename... Ts>
struct TypeList {
  static constexpr std::size_t size = sizeof...(Ts);
};

// Every primitive, in the order the docs list them. Adding one is its file pair and one name
// here.
using Primitives = TypeList<Sphere, Plane, Triangle, Polygon, Cylinder, Box, Disk, Cone, Capsule>;

template <typename... Ts>
constexpr bool every_primitive_type(TypeList<Ts...>) {
  return (PrimitiveType<Ts> && ...);
}
static_assert(every_primitive_type(Primitives{}),
              "each type of Primitives must satisfy PrimitiveType (shapes/primitives.h)");

// Calls f.template operator()<T>() for each type T of a list, in its order.
template <typename F, typename... Ts>
void for_each_type(F&& f, TypeList<Ts...> /*list*/) {
  (f.template operator()<Ts>(), ...);
}

// The same for each primitive.
template <typename F>
void for_each_primitive(F&& f) {
  for_each_type(f, Primitives{});
}

// Whether the hits of the primitive whose `type` key is `type` carry barycentric weights (its
// kBarycentric, where it has one): an answer form asks for them then.
inline bool hits_have_barycentric(std::string_view type) {
  bool yes = false;
  for_each_primitive([&]<typename T>() {
    if constexpr (requires { T::kBarycentric; }) yes = yes || (type == T::kType && T::kBarycentric);
  });
  return yes;
}

// Whether the primitive whose `type` key is `type` may bound a half-space in a scene (its
// kHalfSpace, where it has one): the side its normal points away from is inside.
inline bool bounds_half_space(std::string_view type) {
  bool yes = false;
  for_each_primitive([&]<typename T>() {
    if constexpr (requires { T::kHalfSpace; }) yes = yes || (type == T::kType && T::kHalfSpace);
  });
  return yes;
}

// What grading says of a normal that points the wrong way on the primitive whose `type` key is
// `type`: the named mistake (its kNormalMistake: "inward-normal" on a solid, "cross-order" on a
// triangle or polygon; empty: none) and the sentence, led by a space, that explains the outward
// normal (its kNormalSentence; empty: none). Teaching, not geometry: no part of Shape.
struct NormalRule {
  std::string mistake;
  std::string sentence;
};
inline NormalRule normal_rule(std::string_view type) {
  NormalRule rule;
  for_each_primitive([&]<typename T>() {
    if (type != T::kType) return;
    if constexpr (requires { T::kNormalMistake; }) rule.mistake = T::kNormalMistake;
    if constexpr (requires { T::kNormalSentence; }) rule.sentence = T::kNormalSentence;
  });
  return rule;
}

// What a ray that meets the primitive whose `type` key is `type` along a whole line does, for a
// problem whose answer is "contained": its kContainedLine, else the flat objects' sentence (the
// ray lies in the object's plane).
std::string contained_line(std::string_view type);

}  // namespace raygrade
