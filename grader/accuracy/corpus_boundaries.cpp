// The hard cases across primitives (huge coordinates, direction scales), and the corpus file.
#include <cmath>

#include "accuracy/corpus.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "json/source.h"

namespace raygrade {
namespace {

// The families across primitives cycle over the first six primitives of the list, the study's
// when the stored corpus was drawn: a primitive that joined later draws its own scale cases, so
// that these keep their values.
constexpr std::size_t kScaleFamilyPrimitives = 6;
static_assert(kPrimitiveCount >= kScaleFamilyPrimitives);

AccuracyCase random_case(int i, SplitMix& rng) {
  return random_cases(kAllPrimitives[i % kScaleFamilyPrimitives], 1, rng.next()).front();
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

void huge_coordinate_cases(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    Vec3d shift = 1e8 * rng.unit_vector();
    AccuracyCase c = random_case(i, rng);
    c.id = fmt::format("huge-coordinates-{}", i);
    c.group = "huge-coordinates";
    c.origin = c.origin + shift;
    int direction =
        visit_primitive(c.primitive, []<typename P>() { return int{P::Ladder::kDirectionPoint}; });
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      if (static_cast<int>(k) != direction) c.points[k] = c.points[k] + shift;
    }
    out.push_back(std::move(c));
  }
}

void direction_scale_cases(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 48; ++i) {
    AccuracyCase c = random_case(i, rng);
    double scale = i % 2 == 0 ? 1e-150 : 1e150;
    c.id = fmt::format("direction-scale-{}", i);
    c.group = "direction-scale";
    c.direction = scale * c.direction;
    out.push_back(std::move(c));
  }
}

// Directions scaled by 10^s, s in [−300, 148]. The problem format reads no direction whose
// squared length overflows a double (about 1.8e308); the solver itself is tested up to 1e+300
// (tests/solver_accuracy_test.cpp).
void extreme_scale_cases(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    AccuracyCase c = random_case(i, rng);
    c.id = fmt::format("extreme-scale-{}", i);
    c.group = "extreme-scale";
    c.direction = std::pow(10.0, rng.uniform(-300, 148)) * c.direction;
    out.push_back(std::move(c));
  }
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
  std::optional<std::string> text = read_whole_file(path);
  if (!text)
    throw Error(Diagnostic{path, "", 0, 0, Severity::kError, "cannot read the corpus", "io"});
  JsonLimits limits;
  limits.max_bytes = 64 << 20;
  auto file = parse_json_text(path, *text, limits);
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
