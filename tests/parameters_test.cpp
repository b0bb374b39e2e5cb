// Problems with parameters: defaults, draws, expressions in numbers and text, and their faults.
#include "problems/parameters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "assignments/variants.h"
#include "test_util.h"

namespace raygrade {
namespace {

using testing::problem;

// A sphere of radius 5 at (0, 0, cz) met by a ray from (ox, 0, 0) along (0, 0, dz): worked by
// hand, t = (cz ± sqrt(25 − ox²)) / dz.
constexpr const char* kSphere = R"({"id": "v", "title": "Sphere at z = {cz}",
  "statement": "From ({ox}, 0, 0) along (0, 0, {dz}); radius 5 at (0, 0, {cz}); {{braces}}.",
  "parameters": {"ox": {"choices": [0, 3, 4], "default": 3},
                 "cz": {"integer": [7, 12], "default": 10},
                 "dz": {"choices": [1, 2], "default": 1}},
  "nice_numbers": {"decimals": 1},
  "ray": {"origin": ["=ox", 0, 0], "direction": [0, 0, "=dz"]},
  "object": {"type": "sphere", "center": [0, 0, "=cz"], "radius": 5},
  "expected": {"hits": [{"t": "=(cz - sqrt(25 - ox^2))/dz"}, {"t": "=(cz + sqrt(25 - ox^2))/dz"}]}})";

std::string error_of(const std::string& text) {
  try {
    (void)problem(text);
  } catch (const Error& e) {
    return e.diagnostic().path + ": " + e.diagnostic().message;
  }
  return "no error";
}

TEST(Parameters, DefaultsGiveTheProblemAsWritten) {
  Problem p = problem(kSphere);
  ASSERT_TRUE(p.parameters);
  EXPECT_EQ(p.statement, "From (3, 0, 0) along (0, 0, 1); radius 5 at (0, 0, 10); {braces}.");
  EXPECT_EQ(p.title, "Sphere at z = 10");
  auto hits = p.task->answer()["hits"];
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_DOUBLE_EQ(hits[0]["t"].get<double>(), 6);  // 10 − 4
  EXPECT_DOUBLE_EQ(hits[1]["t"].get<double>(), 14);
  EXPECT_FALSE(p.source.contains("parameters"));
  EXPECT_EQ(p.source["ray"]["origin"][0], 3);
}

TEST(Parameters, EveryDrawIsSolvedAsItsNumbersSay) {
  Problem base = problem(kSphere);
  std::set<std::string> seen;
  for (int s = 0; s < 40; ++s) {
    Problem v = draw_variant(base, variant_seed("a", 1, fmt::format("student-{}", s), "v"));
    double ox = v.values.at("ox").get<double>(), cz = v.values.at("cz").get<double>(),
           dz = v.values.at("dz").get<double>();
    double h = std::sqrt(25 - ox * ox);
    auto hits = v.task->answer()["hits"];
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0]["t"].get<double>(), (cz - h) / dz, 1e-12);
    EXPECT_NEAR(hits[1]["t"].get<double>(), (cz + h) / dz, 1e-12);
    EXPECT_EQ(v.id, "v");
    EXPECT_NE(v.statement.find(fmt::format("at (0, 0, {})", cz)), std::string::npos) << v.statement;
    seen.insert(v.statement);
  }
  EXPECT_GT(seen.size(), 10u);  // 36 combinations: forty students do not all get the same
}

TEST(Parameters, TheSeedIsFnv1aOfItsParts) {
  // Computed independently (Python): FNV-1a 64 over "raygrade variant", "homework-rays",
  // "2026", "s001", "variant-sphere", each followed by the byte 0xFF.
  EXPECT_EQ(variant_seed("homework-rays", 2026, "s001", "variant-sphere"), 0x46b4aeb4f3949f49ULL);
  EXPECT_NE(variant_seed("homework-rays", 2026, "s001", "variant-sphere"),
            variant_seed("homework-rays", 2026, "s00", "1variant-sphere"));
}

TEST(Parameters, TheSameStudentGetsTheSameVariant) {
  Problem base = problem(kSphere);
  std::uint64_t seed = variant_seed("hw", 7, "s001", "v");
  Problem a = draw_variant(base, seed), b = draw_variant(base, seed);
  EXPECT_EQ(a.source.dump(), b.source.dump());
}

TEST(Parameters, DrawsThatFailTheChecksAreReplaced) {
  // ox = 5 makes the ray tangent to the sphere of radius 5 (a near-tie of the two hits) and
  // ox = 4.9999 nearly so; only ox = 3 passes the boundary checks.
  std::string text =
      R"({"id": "t", "parameters": {"ox": {"choices": [3, 4.99999999], "default": 3}},
    "ray": {"origin": ["=ox", 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 10], "radius": 5}})";
  Problem base = problem(text);
  for (int s = 0; s < 20; ++s) {
    Problem v = draw_variant(base, variant_seed("a", 0, std::to_string(s), "t"));
    EXPECT_EQ(v.values.at("ox"), 3) << "student " << s;
  }
}

TEST(Parameters, NiceNumbersKeepOnlyDrawsWithFewDecimals) {
  // t = 10 / d: d = 3 gives 3.333..., d = 4 gives 2.5, d = 8 gives 1.25.
  std::string text = R"({"id": "n", "parameters": {"d": {"choices": [3, 4, 8], "default": 4}},
    "nice_numbers": {"decimals": 1},
    "ray": {"origin": [0, 0, 0], "direction": [0, "=d", 0]},
    "object": {"type": "plane", "point": [0, 10, 0], "normal": [0, 1, 0]}})";
  Problem base = problem(text);
  for (int s = 0; s < 20; ++s) {
    Problem v = draw_variant(base, variant_seed("a", 0, std::to_string(s), "n"));
    EXPECT_EQ(v.values.at("d"), 4) << "student " << s;
  }
  EXPECT_TRUE(has_nice_numbers(nlohmann::json::parse(R"({"hits": [{"t": 2.5, "u": 0.123}]})"),
                               NiceNumbers{1, {"t"}}));
  EXPECT_FALSE(
      has_nice_numbers(nlohmann::json::parse(R"({"hits": [{"t": 2.25}]})"), NiceNumbers{1, {"t"}}));
}

TEST(Parameters, RangesStepAndExclude) {
  std::string text = R"({"id": "r", "parameters": {"x": {"range": [-1, 1], "step": 0.25,
    "exclude": [0], "default": 0.5}},
    "ray": {"origin": ["=x", 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "plane", "point": [0, 0, 4], "normal": [0, 0, 1]}})";
  Problem base = problem(text);
  std::set<double> values;
  for (int s = 0; s < 200; ++s) {
    Problem v = draw_variant(base, variant_seed("a", 0, std::to_string(s), "r"));
    values.insert(v.values.at("x").get<double>());
  }
  // −1, −0.75, ..., 1 without 0: eight values, each a multiple of 0.25 written exactly.
  EXPECT_EQ(values, (std::set<double>{-1, -0.75, -0.5, -0.25, 0.25, 0.5, 0.75, 1}));
}

TEST(Parameters, FaultsNameTheirPlace) {
  EXPECT_EQ(error_of(R"({"id": "u", "parameters": {"r": {"integer": [1, 3], "default": 2},
      "q": {"integer": [1, 3], "default": 1}},
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": "=r"}})")
                .substr(0, 18),
            "/parameters/q: the");
  EXPECT_NE(error_of(R"({"id": "u", "parameters": {"r": {"integer": [1, 3], "default": 2}},
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": "=rr"}})")
                .find("/object/radius: the expression 'rr' does not read: unknown symbol 'rr'"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"id": "u", "parameters": {"r": {"integer": [1, 3], "default": 5}},
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": "=r"}})")
                .find("/parameters/r/default: the default 5 is not one of"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"id": "u", "statement": "radius {r", "parameters": {"r": {"integer":
      [1, 3], "default": 2}}, "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": "=r"}})")
                .find("/statement: a '{' without its '}'"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"id": "u", "parameters": {"r": {"integer": [1, 3], "default": 2,
      "stepp": 1}}, "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": "=r"}})")
                .find("unknown key 'stepp'"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"id": "u", "parameters": {"sqrt": {"integer": [1, 3], "default": 2}},
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": "=sqrt"}})")
                .find("is a function, not a parameter name"),
            std::string::npos);
  // A value the problem rejects (radius 0) is reported where the expression stands.
  EXPECT_NE(error_of(R"({"id": "u", "parameters": {"r": {"integer": [0, 3], "default": 0}},
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": "=r"}})")
                .find("/object/radius"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"id": "u", "nice_numbers": {"decimals": 1},
      "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
      "object": {"type": "sphere", "center": [0, 0, 5], "radius": 1}})")
                .find("'nice_numbers' goes with 'parameters'"),
            std::string::npos);
}

TEST(Parameters, VectorChoicesStandAlone) {
  std::string text = R"({"id": "d", "statement": "along {d}",
    "parameters": {"d": {"choices": [[0, 0, 1], [0, 0, 2]], "default": [0, 0, 2]}},
    "ray": {"origin": [0, 0, 0], "direction": "=d"},
    "object": {"type": "plane", "point": [0, 0, 4], "normal": [0, 0, 1]}})";
  Problem p = problem(text);
  EXPECT_EQ(p.statement, "along (0, 0, 2)");
  EXPECT_DOUBLE_EQ(p.task->answer()["hits"][0]["t"].get<double>(), 2);  // 4 / 2
}

}  // namespace
}  // namespace raygrade
