// Seeded, reproducible problem variants with "nice" numbers: hits at integer points and
// integer t, built backwards from lattice points on spheres and circles.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sampling/outcome.h"
#include "sampling/prng.h"

namespace raygrade {

const char* outcome_name(Outcome o);
std::optional<Outcome> parse_outcome(std::string_view name);

// One row of the table of generators: a primitive (its rows come from the list of primitives,
// each primitive's outcomes() and generate()) or a kind ("first-hit").
struct GeneratorEntry {
  std::string_view name;
  std::string_view kind;          // the kind of the problems it drafts
  std::vector<Outcome> outcomes;  // the outcomes it can build; empty: outcome does not apply
  Draft (*make)(Prng& rng, std::optional<Outcome> outcome);
};
const std::vector<GeneratorEntry>& generator_table();

struct GenerateOptions {
  std::uint64_t seed = 1;
  int count = 10;
  std::vector<std::string> kinds;  // names from the generator table; empty for all
  std::optional<Outcome> outcome;  // empty for a mix
  std::string id_prefix = "gen";
};

struct GeneratedProblem {
  std::string id;
  nlohmann::ordered_json json;  // the problem object, ready to write
};

// Generates `count` problems, each read back and checked (stated answer, boundaries,
// conditioning, unique geometry) before it is kept. Throws Error for an unknown kind or an
// outcome that none of the chosen kinds can build.
std::vector<GeneratedProblem> generate_problems(const GenerateOptions& options);

// The bank of `problems` as one JSON file ({"problems": [...]}, two-space indent), as
// `generate` writes it on standard output. Throws Error (code "limit") when the file would be
// over the limits of one bank file (JsonLimits: 16 MiB, 100,000 problems), which check and
// grade would refuse: what generate writes, they read.
std::string bank_text(const std::vector<GeneratedProblem>& problems);

}  // namespace raygrade
