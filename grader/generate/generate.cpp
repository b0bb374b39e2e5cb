// The generator's driver: the table of generators, and each draft read back and checked
// before it is kept.
#include "generate/generate.h"

#include <set>

#include "check/geometry_key.h"
#include "check/problem_checks.h"
#include "core/error.h"
#include "generate/kinds.h"
#include "json/cursor.h"
#include "kinds/camera_ray.h"
#include "kinds/intersect.h"
#include "shapes/primitives.h"

namespace raygrade {
namespace {

// Drafts tried per problem before giving up. A draft is rejected only when it repeats an
// earlier problem's geometry or fails a check; with the generators' ranges that is rare, so
// this bound is never reached in practice.
constexpr int kMaxAttempts = 200;

const std::vector<Outcome> kAllOutcomes = {Outcome::kHit, Outcome::kMiss, Outcome::kTangent,
                                           Outcome::kInside, Outcome::kBehind};

}  // namespace

const char* outcome_name(Outcome o) {
  switch (o) {
    case Outcome::kHit: return "hit";
    case Outcome::kMiss: return "miss";
    case Outcome::kTangent: return "tangent";
    case Outcome::kInside: return "inside";
    case Outcome::kBehind: return "behind";
  }
  return "hit";
}

std::optional<Outcome> parse_outcome(std::string_view name) {
  for (Outcome o : kAllOutcomes) {
    if (name == outcome_name(o)) return o;
  }
  return std::nullopt;
}

const std::vector<GeneratorEntry>& generator_table() {
  static const std::vector<GeneratorEntry> table = [] {
    // The primitives' rows, from the list of primitives in its order; then the kinds'.
    std::vector<GeneratorEntry> rows;
    for_each_primitive([&]<typename T>() {
      rows.push_back({T::kType, IntersectKind::kName, T::outcomes(), &T::generate});
    });
    rows.push_back({FirstHitKind::kName,
                    FirstHitKind::kName,
                    {Outcome::kHit, Outcome::kMiss},
                    &make_first_hit});
    rows.push_back({CameraRayKind::kName, CameraRayKind::kName, {}, &make_camera_ray});
    return rows;
  }();
  return table;
}

std::vector<GeneratedProblem> generate_problems(const GenerateOptions& options) {
  auto usage = [](std::string message) {
    throw Error(Diagnostic{"", "", 0, 0, Severity::kError, std::move(message), "usage"});
  };
  // The generators to cycle through: those named (all by default) that can build the outcome.
  std::vector<const GeneratorEntry*> chosen;
  std::vector<std::string> names;
  for (const auto& g : generator_table()) names.emplace_back(g.name);
  for (const auto& k : options.kinds) {
    if (std::find(names.begin(), names.end(), k) == names.end()) {
      std::string hint = closest_match(k, names);
      usage(hint.empty() ? fmt::format("unknown kind '{}' (known: {})", k, fmt::join(names, ", "))
                         : fmt::format("unknown kind '{}' (did you mean '{}'?)", k, hint));
    }
  }
  for (const auto& g : generator_table()) {
    bool named = options.kinds.empty() || std::find(options.kinds.begin(), options.kinds.end(),
                                                    g.name) != options.kinds.end();
    bool fits = !options.outcome || std::find(g.outcomes.begin(), g.outcomes.end(),
                                              *options.outcome) != g.outcomes.end();
    if (named && fits) chosen.push_back(&g);
  }
  if (chosen.empty()) {
    usage(fmt::format("no chosen kind can build the outcome '{}'", outcome_name(*options.outcome)));
  }
  Prng rng(options.seed);
  std::set<std::string> geometries;
  std::vector<GeneratedProblem> out;
  for (int i = 0; i < options.count; ++i) {
    const GeneratorEntry& g = *chosen[static_cast<std::size_t>(i) % chosen.size()];
    std::string id = fmt::format("{}{}-{:04}-{}", options.id_prefix, options.seed, i + 1, g.name);
    bool kept = false;
    for (int attempt = 0; attempt < kMaxAttempts && !kept; ++attempt) {
      Draft draft = g.make(rng, options.outcome);
      nlohmann::ordered_json problem;
      problem["id"] = id;
      problem["title"] =
          fmt::format("Generated {} problem {} (seed {})", g.name, i + 1, options.seed);
      problem["kind"] = std::string(g.kind);
      for (auto& [key, value] : draft.fields.items()) problem[key] = value;
      auto file = parse_json_text(id + ".json", problem.dump(2));
      std::string key;
      try {
        Problem p = read_problem(Cursor(file));
        key = geometry_key(p);
        if (geometries.count(key) || !problem_findings(p, scan_number_literals(file->text)).empty())
          continue;
      } catch (const Error&) {
        continue;  // a draft the format rejects is discarded like any other failed draft
      }
      geometries.insert(key);
      out.push_back(GeneratedProblem{id, std::move(problem)});
      kept = true;
    }
    if (!kept) usage(fmt::format("could not build a valid {} problem for {}", g.name, id));
  }
  return out;
}

std::string bank_text(const std::vector<GeneratedProblem>& problems) {
  nlohmann::ordered_json bank;
  bank["problems"] = nlohmann::ordered_json::array();
  for (const auto& p : problems) bank["problems"].push_back(p.json);
  std::string text = bank.dump(2) + "\n";
  JsonLimits limits;
  if (text.size() > limits.max_bytes || problems.size() > limits.max_items) {
    throw Error(Diagnostic{
        "", "", 0, 0, Severity::kError,
        fmt::format("{} problems make a bank file of {} bytes, over the {} bytes (or {} "
                    "problems) one bank file may hold: write them with --out DIR (one file per "
                    "problem), or fewer at a time (-n) with different seeds",
                    problems.size(), text.size(), limits.max_bytes, limits.max_items),
        "limit"});
  }
  return text;
}

}  // namespace raygrade
