// The primitives of the accuracy study, derived from the list of primitives (shapes/primitives.h):
// every primitive whose type has a nested `Ladder` struct, in the list's order. `Primitive` is a
// primitive's index in that list, and every table of the accuracy module (level functions, names,
// reading and writing cases, corpus, settle, report rows) is built from it.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "shapes/primitives.h"

namespace raygrade {

struct AccuracyCase;
class SplitMix;

// What a primitive's `Ladder` provides, in the primitive's own files. The case's points and
// radius are the primitive's own parameters in an order it chooses (kPoints of them, or at least
// kPoints when kMorePoints; a radius when kRadius), and the kernels take them in any number type T
// (float, double, long double, DoubleDouble, Mpfr, SoftFloat and their intervals):
//   - reference<T>(o, d, points, radius, t): the stable formulation, the same template the
//     primitive's intersect runs in double; true with the nearest hit at t ≥ 0 in `t`. Forced
//     inline ([[gnu::always_inline]]), so that each level's per-primitive function (ladder.cpp)
//     holds the whole formula and hands t back through a register.
//   - naive<T>(o, d, points, radius): the textbook formulation a student writes.
//   - hits<T>(o, d, points, radius, add): every hit at t ≥ 0, as add(t, normal) with a normal not
//     yet of unit length (zero where it is ambiguous), for the ground truth.
//   - naive_normal(points, radius, p): the textbook normal at the rounded hit point p, if any.
//   - case_of(object, points, radius): the object as a case, false when the case cannot hold it
//     (a finite cylinder, a plane given by d); shape_of(points, radius) the inverse.
//   - kDirectionPoint: the index of the point that is a direction (−1 when none), which a shift
//     of the whole case leaves alone.
//   - random_case(rng, points, radius): the object of one ordinary case: unit-sized, near the
//     origin.
//   - hard_cases(round, rng, out): its hard cases of one round (see corpus.cpp).
// The round in which a primitive that joined the study after the stored corpus was drawn draws
// its hard cases, from a SplitMix of its own seed (accuracy/corpus.cpp).
inline constexpr int kOwnStreamRound = 9;

template <typename P>
concept AccuracyPrimitive = PrimitiveType<P> &&
    requires(const P& object, const Vec3d& v, const std::vector<Vec3d>& p, double r, double& t,
             std::vector<Vec3d>& points, double& radius, SplitMix& rng,
             std::vector<AccuracyCase>& out) {
  { P::Ladder::kPoints } -> std::convertible_to<std::size_t>;
  { P::Ladder::kMorePoints } -> std::convertible_to<bool>;
  { P::Ladder::kRadius } -> std::convertible_to<bool>;
  { P::Ladder::kDirectionPoint } -> std::convertible_to<int>;
  { P::Ladder::template reference<double>(v, v, p, r, t) } -> std::same_as<bool>;
  { P::Ladder::template naive<double>(v, v, p, r) } -> std::same_as<std::optional<double>>;
  { P::Ladder::naive_normal(p, r, v) } -> std::same_as<std::optional<Vec3d>>;
  { P::Ladder::case_of(object, points, radius) } -> std::same_as<bool>;
  { P::Ladder::shape_of(p, r) } -> std::same_as<std::unique_ptr<Shape>>;
  P::Ladder::random_case(rng, points, radius);
  P::Ladder::hard_cases(0, rng, out);
};

template <typename P>
concept HasLadder = requires {
  typename P::Ladder;
};

template <typename... A, typename... B>
TypeList<A..., B...> operator+(TypeList<A...> /*a*/, TypeList<B...> /*b*/);

template <typename... Ts>
auto ladder_types(TypeList<Ts...> /*list*/)
    -> decltype((TypeList<>{} + ... +
                 std::conditional_t<HasLadder<Ts>, TypeList<Ts>, TypeList<>>{}));

// The primitives of the accuracy study, in the order of Primitives.
using LadderPrimitives = decltype(ladder_types(Primitives{}));

template <typename... Ts>
constexpr bool every_ladder_primitive(TypeList<Ts...> /*list*/) {
  return (AccuracyPrimitive<Ts> && ...);
}
static_assert(
    every_ladder_primitive(LadderPrimitives{}),
    "a primitive with a Ladder must satisfy AccuracyPrimitive (shapes/ladder_primitives.h)");

// A primitive of the accuracy study: its index in LadderPrimitives.
enum class Primitive : std::uint8_t {};

inline constexpr std::size_t kPrimitiveCount = LadderPrimitives::size;

inline constexpr std::array<Primitive, kPrimitiveCount> kAllPrimitives = [] {
  std::array<Primitive, kPrimitiveCount> out{};
  for (std::size_t i = 0; i < kPrimitiveCount; ++i) out[i] = static_cast<Primitive>(i);
  return out;
}();

template <std::size_t I, typename T, typename... Ts>
struct TypeAt : TypeAt<I - 1, Ts...> {};
template <typename T, typename... Ts>
struct TypeAt<0, T, Ts...> {
  using type = T;
};
template <std::size_t I, typename List>
struct LadderAt;
template <std::size_t I, typename... Ts>
struct LadderAt<I, TypeList<Ts...>> : TypeAt<I, Ts...> {};

// The primitive at index I.
template <std::size_t I>
using LadderPrimitive = typename LadderAt<I, LadderPrimitives>::type;

// The index of P.
template <typename P>
constexpr Primitive primitive_of() {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    std::size_t index = 0;
    (void)((std::is_same_v<P, LadderPrimitive<I>> && (index = I, true)) || ...);
    return static_cast<Primitive>(index);
  }
  (std::make_index_sequence<kPrimitiveCount>{});
}

// Calls f.template operator()<P>() for the primitive P of index `p`, and returns its result.
template <typename F>
decltype(auto) visit_primitive(Primitive p, F&& f) {
  return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
    using Result = decltype(f.template operator()<LadderPrimitive<0>>());
    if constexpr (std::is_void_v<Result>) {
      static_cast<void>(
          ((static_cast<std::size_t>(p) == I ? (f.template operator()<LadderPrimitive<I>>(), true)
                                             : false) ||
           ...));
    } else {
      Result out{};
      static_cast<void>(((static_cast<std::size_t>(p) == I
                              ? (out = f.template operator()<LadderPrimitive<I>>(), true)
                              : false) ||
                         ...));
      return out;
    }
  }
  (std::make_index_sequence<kPrimitiveCount>{});
}

// Calls f.template operator()<P>() for each primitive of the study, in order.
template <typename F>
void for_each_ladder_primitive(F&& f) {
  for_each_type(f, LadderPrimitives{});
}

// The primitive's `type` key, as the list of primitives gives it.
constexpr std::string_view primitive_name(Primitive p) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    constexpr std::string_view names[] = {LadderPrimitive<I>::kType...};
    return names[static_cast<std::size_t>(p)];
  }
  (std::make_index_sequence<kPrimitiveCount>{});
}

}  // namespace raygrade
