// A kind of problem as a type: what kinds/table.cpp lists, one line each. The concept says what
// a kind must declare; the table's rows (problems/kind.h), the grading of its parts, its answer
// form, its case of the problem schema and the docs' table of kinds all come from it.
#pragma once

#include <concepts>

#include "json/cursor.h"
#include "problems/kind.h"
#include "problems/problem.h"

namespace raygrade {

template <typename K>
concept KindType = requires(const Cursor& c, const Problem& p) {
  { K::kName } -> std::convertible_to<std::string_view>;
  { K::kSummary } -> std::convertible_to<std::string_view>;
  { K::kGrader } -> std::convertible_to<GraderFamily>;
  { K::keys() } -> std::same_as<std::vector<std::string>>;
  { K::read(c) } -> std::same_as<std::unique_ptr<Task>>;
  { K::parts() } -> std::same_as<std::vector<PartSpec>>;
  { K::answer_form(p) } -> std::same_as<nlohmann::json>;
  { K::schema() } -> std::same_as<std::string_view>;
};

template <KindType K>
KindEntry kind_entry() {
  return {K::kName,   K::kSummary, K::keys(),       &K::read,
          K::parts(), K::kGrader,  &K::answer_form, K::schema()};
}

// The kinds, in order: KindList<A, B>::entries() is the table.
template <KindType... Ks>
struct KindList {
  static std::vector<KindEntry> entries() { return {kind_entry<Ks>()...}; }
};

}  // namespace raygrade
