// Malformed input through the real binary: exit code 2, a message naming the file, the JSON
// path and the fault, and every other problem of the run still solved and printed.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_binary.h"

namespace raygrade {
namespace {

using testing::run_raygrade;
using testing::TempDir;
using testing::write_text;

struct BadCase {
  const char* name;
  const char* ray;     // the bad problem's ray
  const char* object;  // and its object
  const char* path;    // the JSON path the message must name
  const char* fault;   // words the message must contain
};

constexpr const char* kGoodRay = R"({"origin": [0, 0, 0], "direction": [1, 0, 0]})";
constexpr const char* kGoodSphere = R"({"type": "sphere", "center": [2, 0, 0], "radius": 1})";

const BadCase kCases[] = {
    {"ZeroDirection", R"({"origin": [0, 0, 0], "direction": [0, 0, 0]})", kGoodSphere,
     "/problems/1/ray/direction", "zero vector"},
    {"ZeroRadius", kGoodRay, R"({"type": "sphere", "center": [2, 0, 0], "radius": 0})",
     "/problems/1/object/radius", "must be positive"},
    {"NegativeRadius", kGoodRay, R"({"type": "sphere", "center": [2, 0, 0], "radius": -1})",
     "/problems/1/object/radius", "must be positive"},
    {"CylinderZeroRadius", kGoodRay, R"({"type": "cylinder", "base": [0, 0, 0], "radius": 0})",
     "/problems/1/object/radius", "must be positive"},
    {"CollinearTriangle", kGoodRay,
     R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [3, 3, 3]]})",
     "/problems/1/object/vertices", "degenerate triangle"},
    {"CoincidentTriangle", kGoodRay,
     R"({"type": "triangle", "vertices": [[1, 2, 3], [1, 2, 3], [0, 0, 1]]})",
     "/problems/1/object/vertices", "degenerate triangle"},
    // The fourth vertex lifts a unit square's corner by 1: clearly not planar.
    {"NonPlanarPolygon", kGoodRay,
     R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 1], [0, 1, 0]]})",
     "/problems/1/object/vertices/", "non-planar polygon"},
    {"ZeroNormal", kGoodRay, R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0]})",
     "/problems/1/object/normal", "zero vector"},
    {"ZeroNormalDForm", kGoodRay, R"({"type": "plane", "normal": [0, 0, 0], "d": 1})",
     "/problems/1/object/normal", "zero vector"},
    {"ZeroAxis", kGoodRay,
     R"({"type": "cylinder", "base": [0, 0, 0], "axis": [0, 0, 0], "radius": 1})",
     "/problems/1/object/axis", "zero vector"},
    {"OverflowingNumber", R"({"origin": [0, 0, 1e400], "direction": [1, 0, 0]})", kGoodSphere,
     "/problems/1/ray/origin/2", "out of range"},
    {"NegativeOverflow", kGoodRay, R"({"type": "sphere", "center": [2, 0, 0], "radius": -1e400})",
     "/problems/1/object/radius", "out of range"},
    {"OverflowingLength", R"({"origin": [0, 0, 0], "direction": [1e200, 1e200, 0]})", kGoodSphere,
     "/problems/1/ray/direction", "overflows"},
    {"FlatBox", kGoodRay, R"({"type": "box", "min": [0, 0, 0], "max": [1, 0, 1]})",
     "/problems/1/object/max", "degenerate box"},
    // A name labels an object among others; an intersect problem has one.
    {"NameOnTheOnlyObject", kGoodRay,
     R"({"type": "sphere", "name": "ball", "center": [2, 0, 0], "radius": 1})",
     "/problems/1/object/name", "this kind has one object"},
};

// Test names and failure messages show the case's name, not its bytes.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, ExitsTwoNamingFilePathAndFaultAndSolvesTheRest) {
  const BadCase& c = GetParam();
  TempDir dir("bad-input");
  std::string text = fmt::format(
      R"({{"problems": [
  {{"id": "good-1", "ray": {0}, "object": {1}}},
  {{"id": "bad", "ray": {2}, "object": {3}}},
  {{"id": "good-2", "ray": {0}, "object": {1}}}
]}})",
      kGoodRay, kGoodSphere, c.ray, c.object);
  write_text(dir.path() / "bank.json", text);
  auto r = run_raygrade("solve bank.json --format json", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  // The message: "bank.json:LINE:COLUMN: /problems/1/...: error: ...fault...".
  EXPECT_NE(r.err.find("bank.json:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(c.path), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(c.fault), std::string::npos) << r.err;
  // The good problems are solved: the ray along +x meets the sphere at t = 1 and 3.
  auto out = nlohmann::json::parse(r.out);
  ASSERT_EQ(out["solutions"].size(), 2u) << r.out;
  for (int i = 0; i < 2; ++i) {
    const auto& s = out["solutions"][i];
    EXPECT_EQ(s["id"], i == 0 ? "good-1" : "good-2");
    ASSERT_EQ(s["answer"]["hits"].size(), 2u);
    EXPECT_EQ(s["answer"]["hits"][0]["t"], 1.0);
    EXPECT_EQ(s["answer"]["hits"][1]["t"], 3.0);
  }
  // The fault is also listed in the output's errors, with its path.
  ASSERT_EQ(out["errors"].size(), 1u);
  EXPECT_EQ(out["errors"][0]["file"], "bank.json");
  EXPECT_NE(out["errors"][0]["path"].get<std::string>().find(c.path), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Faults, BadInput, ::testing::ValuesIn(kCases),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// A file that is not JSON at all (NaN is no JSON number) fails alone: the other file of the
// run is still solved, and the message names the file, line and column.
TEST(BadInput, UnparsableFileDoesNotStopTheRun) {
  TempDir dir("bad-json");
  write_text(dir.path() / "a.json",
             R"({"id": "nan", "ray": {"origin": [0, 0, 0], "direction": [NaN, 0, 0]},
 "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  write_text(dir.path() / "b.json",
             fmt::format(R"({{"id": "good", "ray": {}, "object": {}}})", kGoodRay, kGoodSphere));
  auto r = run_raygrade("solve a.json b.json --format json", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a.json:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("invalid JSON"), std::string::npos) << r.err;
  auto out = nlohmann::json::parse(r.out);
  ASSERT_EQ(out["solutions"].size(), 1u);
  EXPECT_EQ(out["solutions"][0]["id"], "good");
}

TEST(BadInput, CleanRunExitsZero) {
  TempDir dir("good");
  write_text(dir.path() / "b.json",
             fmt::format(R"({{"id": "good", "ray": {}, "object": {}}})", kGoodRay, kGoodSphere));
  auto r = run_raygrade("solve b.json --format json", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

}  // namespace
}  // namespace raygrade
