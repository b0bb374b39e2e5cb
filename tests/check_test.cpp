// The bank check: every fault of the broken-bank fixtures reported at its place, the bundled
// bank clean, and the pieces (printed digits, answer comparison, probes) on hand-made cases.
#include "check/check.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "check/compare.h"
#include "check/literals.h"
#include "check/problem_checks.h"
#include "check/self_tests.h"
#include "test_util.h"

namespace raygrade {
namespace {

using testing::kSource;
const std::string kBroken = kSource + "/tests/fixtures/broken-bank";
const std::string kBrokenSolutions = kSource + "/tests/fixtures/broken-bank-solutions";

CheckReport check_broken() {
  CheckOptions o;
  o.solutions_dir = kBrokenSolutions;
  o.solutions_required = true;
  return check_bank({kBroken}, o);
}

// Each fixture holds one fault: its file, the code it must be reported with, and the line
// of the faulty value, read off the fixture by hand.
struct Fault {
  const char* file;
  const char* code;
  int line;
};
const Fault kFaults[] = {
    {"bad-json.json", "bad-json", 4},
    {"unknown-key.json", "unknown-key", 4},
    {"type.json", "type", 4},
    {"missing-key.json", "missing-key", 4},
    {"degenerate-triangle.json", "degenerate", 4},
    {"degenerate-direction.json", "degenerate", 3},
    {"unknown-kind.json", "unknown-kind", 3},
    {"unknown-type.json", "unknown-type", 4},
    {"unknown-method.json", "unknown-method", 3},
    {"invalid-t-range.json", "invalid", 3},
    {"range.json", "range", 3},
    {"duplicate-id.json", "duplicate-id", 10},
    {"duplicate-name.json", "duplicate-name", 7},
    {"wrong-expected.json", "wrong-expected", 6},
    {"unknown-answer-key.json", "unknown-key", 5},
    {"negative-t.json", "negative-t", 6},
    {"beyond-t-max.json", "beyond-t-max", 5},
    {"nearly-tangent.json", "nearly-tangent", 4},
    {"ill-conditioned.json", "ill-conditioned", 4},
    {"near-tie.json", "near-tie", 5},
    {"duplicate-geometry.json", "duplicate-geometry", 9},
    {"self-test.json", "self-test", 7},
    {"no-solution.json", "no-solution", 2},
    {"undefined-normal.json", "undefined-normal", 5},
    {"underflowing-normal.json", "undefined-normal", 5},
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

TEST(CheckBank, ReportsEveryFixtureFaultAtItsLine) {
  CheckReport report = check_broken();
  auto all = report.diagnostics();
  std::set<std::string> codes;
  for (const auto& f : kFaults) {
    bool found = false;
    for (const auto& d : all) {
      if (ends_with(d.file, std::string("/") + f.file) && d.code == f.code) {
        EXPECT_EQ(d.line, f.line) << f.file << ": " << format_diagnostic(d);
        EXPECT_GT(d.column, 0) << f.file;
        EXPECT_EQ(d.severity, Severity::kError) << f.file;
        found = true;
      }
    }
    EXPECT_TRUE(found) << f.file << " should be reported as " << f.code;
    codes.insert(f.code);
  }
  EXPECT_GE(codes.size(), 15u);
  EXPECT_FALSE(report.unreadable);
}

// Each file fails for its own fault only: no fixture trips a second check by accident
// (wrong-expected beside negative-t and beyond-t-max is the one expected companion).
TEST(CheckBank, FixturesReportOnlyTheirOwnFault) {
  CheckReport report = check_broken();
  for (const auto& d : report.diagnostics()) {
    bool expected = d.code == "wrong-expected";
    for (const auto& f : kFaults) {
      if (ends_with(d.file, std::string("/") + f.file) && d.code == f.code) expected = true;
    }
    EXPECT_TRUE(expected) << "unexpected: " << format_diagnostic(d) << " [" << d.code << "]";
  }
}

TEST(CheckBank, BundledBankPasses) {
  CheckOptions o;  // solutions are checked by the command's own test, once they exist
  CheckReport report = check_bank({kSource + "/problems"}, o);
  EXPECT_GT(report.problems.size(), 10u);
  // Warnings are allowed (the bank has a deliberate tie); errors are not.
  for (const auto& d : report.diagnostics()) {
    if (d.severity == Severity::kError) ADD_FAILURE() << format_diagnostic(d);
  }
}

TEST(CheckBank, MissingPathIsUnreadable) {
  CheckReport report = check_bank({kSource + "/tests/fixtures/no-such-folder"}, {});
  EXPECT_TRUE(report.unreadable);
}

// docs/check.md documents every code the check reports.
TEST(CheckBank, DocsListEveryCode) {
  std::ifstream f(kSource + "/docs/check.md");
  std::stringstream text;
  text << f.rdbuf();
  for (const auto& c : check_codes()) {
    EXPECT_NE(text.str().find(fmt::format("| `{}` |", c.code)), std::string::npos) << c.code;
  }
}

int run_command(const std::string& args) {
  int status =
      std::system((std::string(RAYGRADE_BINARY) + " " + args + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CheckCommand, ExitCodes) {
  EXPECT_EQ(run_command("check " + kBroken + " --solutions " + kBrokenSolutions), 1);
  EXPECT_EQ(run_command("check " + kSource + "/problems --no-solutions"), 0);
  EXPECT_EQ(run_command("check " + kSource + "/tests/fixtures/no-such-folder"), 2);
}

TEST(Literals, PrintedDecimalsAndHalfUnits) {
  EXPECT_EQ(printed_decimals("0.8"), 1);
  EXPECT_EQ(printed_decimals("7.2679"), 4);
  EXPECT_EQ(printed_decimals("1e-3"), 3);
  EXPECT_EQ(printed_decimals("1.5e2"), -1);
  EXPECT_EQ(printed_decimals("-2.50"), 2);
  EXPECT_EQ(significant_digits("0.8"), 1);
  EXPECT_EQ(significant_digits("0.00125"), 3);
  EXPECT_EQ(significant_digits("1.50"), 3);
  EXPECT_EQ(significant_digits("-7.2679e2"), 5);
  EXPECT_DOUBLE_EQ(half_unit("0.8"), 0.05);
  EXPECT_DOUBLE_EQ(half_unit("7.2679"), 0.00005);
}

TEST(Literals, ScanFindsNonIntegersByPointer) {
  NumberLiterals l = scan_number_literals(
      R"({"problems": [{"a": [1, 0.50, {"b~/c": 2e-1}], "t": 3}], "x": -7.25})");
  EXPECT_EQ(l.size(), 3u);
  EXPECT_EQ(l["/problems/0/a/1"], "0.50");
  EXPECT_EQ(l["/problems/0/a/2/b~0~1c"], "2e-1");
  EXPECT_EQ(l["/x"], "-7.25");
}

const auto kNoDigits = [](const std::string&) { return 0.0; };

TEST(CompareStated, StatedDigitsSetTheDefaultTolerance) {
  // Seed 001: t = 9 − √3 = 7.26795 stated as 7.2679 (inside half a unit of the 4th decimal),
  // and as 7.2681 (outside it).
  nlohmann::json reference = {{"t", 9 - std::sqrt(3.0)}};
  auto digits4 = [](const std::string&) { return 0.00005; };
  EXPECT_TRUE(compare_stated({{"t", 7.2679}}, reference, {}, digits4).empty());
  EXPECT_EQ(compare_stated({{"t", 7.2681}}, reference, {}, digits4).size(), 1u);
  // An absolute tolerance of 0.01 accepts 7.27.
  EXPECT_TRUE(compare_stated({{"t", 7.27}}, reference, {0.01, 0}, kNoDigits).empty());
}

TEST(CompareStated, CountsUnknownKeysAndDefaults) {
  nlohmann::json reference = {{"hits", nlohmann::json::array()}};
  auto m = compare_stated({{"hit", nlohmann::json::array()}}, reference, {}, kNoDigits);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].code, "unknown-key");
  EXPECT_NE(m[0].message.find("did you mean 'hits'"), std::string::npos);
  // "contained": false matches its absence; true does not.
  EXPECT_TRUE(compare_stated({{"contained", false}}, reference, {}, kNoDigits).empty());
  EXPECT_EQ(compare_stated({{"contained", true}}, reference, {}, kNoDigits).size(), 1u);
}

// The probes on hand-made spheres: the ray along x at height y over a unit sphere at x = 5.
Problem sphere_at_height(const std::string& y) {
  return testing::problem(R"({"id": "p", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [5, )" +
                          y + R"(, 0], "radius": 1}})");
}

TEST(ProbeBoundaries, ExactTangentIsADesignedCase) {
  BoundaryProbe probe = probe_boundaries(sphere_at_height("1"));
  EXPECT_TRUE(probe.exact_boundary);
  EXPECT_TRUE(probe.diagnostics.empty());
}

// The default tolerance on t is 0.1% (docs/grading.md): 0.005 at t = 5, where the ray passes
// the sphere. A ray 0.003 above it misses by less than that.
TEST(ProbeBoundaries, MissByLessThanTheToleranceIsNearlyTangent) {
  BoundaryProbe probe = probe_boundaries(sphere_at_height("1.003"));
  EXPECT_FALSE(probe.exact_boundary);
  ASSERT_EQ(probe.diagnostics.size(), 1u);
  EXPECT_EQ(probe.diagnostics[0].code, "nearly-tangent");
}

TEST(ProbeBoundaries, HitsCloserThanTwiceTheToleranceAreNearlyTangent) {
  // y = 0.99999: the half chord is √(1 − 0.99999²) ≈ 0.0045, so the hits are 0.009 apart,
  // within twice the tolerance 0.005.
  BoundaryProbe probe = probe_boundaries(sphere_at_height("0.99999"));
  ASSERT_EQ(probe.diagnostics.size(), 1u);
  EXPECT_EQ(probe.diagnostics[0].code, "nearly-tangent");
}

TEST(ProbeBoundaries, ClearMissAndClearHitPass) {
  EXPECT_TRUE(probe_boundaries(sphere_at_height("1.5")).diagnostics.empty());
  EXPECT_TRUE(probe_boundaries(sphere_at_height("0.5")).diagnostics.empty());
}

// Shadow rays as courses set them up: leaving P = (0, 1, 0) on the unit sphere with
// t_min = 1e-9. The sideways probe moves P into or out of the sphere, which is not the ray
// grazing anything.
Problem shadow_ray_from_sphere(const std::string& direction, const std::string& objects) {
  return testing::problem(R"({"id": "p", "kind": "first-hit",
    "ray": {"origin": [0, 1, 0], "direction": )" +
                          direction + R"(, "t_min": 1e-9, "t_max": 1},
    "objects": [{"name": "ball", "type": "sphere", "center": [0, 0, 0], "radius": 1})" +
                          objects + "]}");
}

TEST(ProbeBoundaries, ShadowRayLeavingASurfaceIsNotNearlyTangent) {
  // Toward a light at (4, 5, 0), 45° off the surface, past a blocker at (2, 3, 0) that the ray
  // meets through its centre.
  auto blocked = shadow_ray_from_sphere(
      "[4, 4, 0]",
      R"(, {"name": "blocker", "type": "sphere", "center": [2, 3, 0], "radius": 0.5})");
  EXPECT_TRUE(probe_boundaries(blocked).diagnostics.empty());
  // Nothing in the way: the light is visible.
  EXPECT_TRUE(probe_boundaries(shadow_ray_from_sphere("[4, 4, 0]", "")).diagnostics.empty());
  // The same ray as an intersect problem with the sphere it leaves.
  auto own = testing::problem(R"({"id": "p", "ray": {"origin": [0, 1, 0], "direction": [1, 1, 0],
    "t_min": 1e-9}, "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  EXPECT_TRUE(probe_boundaries(own).diagnostics.empty());
}

TEST(ProbeBoundaries, GrazingDepartureIsStillNearlyTangent) {
  // Leaving the top of the sphere at 0.06° above its tangent plane (slope 0.001): a ray moved
  // sideways by the tolerance re-enters the sphere far from the start.
  auto grazing = testing::problem(R"({"id": "p", "ray": {"origin": [0, 1, 0],
    "direction": [1, 0.001, 0], "t_min": 1e-9}, "object": {"type": "sphere",
    "center": [0, 0, 0], "radius": 1}})");
  BoundaryProbe probe = probe_boundaries(grazing);
  ASSERT_EQ(probe.diagnostics.size(), 1u);
  EXPECT_EQ(probe.diagnostics[0].code, "nearly-tangent");
}

// A floor z = 4 and a ball resting on it, both met at t = 4 by the ray along +z.
Problem exact_tie(const std::string& expected) {
  return testing::problem(R"({"id": "p", "kind": "first-hit",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "objects": [{"name": "floor", "type": "plane", "point": [0, 0, 4], "normal": [0, 0, -1]},
                {"name": "ball", "type": "sphere", "center": [0, 0, 5], "radius": 1}])" +
                          expected + "}");
}

TEST(ProbeBoundaries, ExactTieIsWarnedUnlessTheProblemSaysSo) {
  BoundaryProbe unsaid = probe_boundaries(exact_tie(""));
  ASSERT_EQ(unsaid.diagnostics.size(), 1u);
  EXPECT_EQ(unsaid.diagnostics[0].code, "tie");
  EXPECT_TRUE(probe_boundaries(exact_tie(R"(, "expected": {"object": "floor", "tie": true})"))
                  .diagnostics.empty());
}

TEST(Conditioning, ShortDecimalsAreExactAndWellPosedInputsPass) {
  // Seed 000's sphere case 4 has its centre at z = 0.8: exact, not perturbed. Printed as 0.800
  // it is perturbed by 0.0005, and t moves by about as much: well-conditioned.
  for (const char* z : {"0.8", "0.800"}) {
    Problem p = testing::problem(std::string(R"({"id": "s4", "ray": {"origin": [0, 0, 0],
      "direction": [1, 1, 1]}, "object": {"type": "sphere", "center": [1, 1, )") +
                                 z + R"(], "radius": 1}})");
    auto literals = scan_number_literals(p.source_file->text);
    EXPECT_TRUE(check_conditioning(p, p.task->answer(), literals, false).empty()) << z;
  }
}

TEST(Conditioning, OutcomeFlipWithinPrintedDigitsIsFlagged) {
  // A unit sphere 0.996 above the ray: a hit. Its radius printed as 1.00 may be 0.995, where
  // the ray misses it.
  Problem p = testing::problem(R"({"id": "c", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [5, 0.996, 0], "radius": 1.00}})");
  auto literals = scan_number_literals(p.source_file->text);
  auto d = check_conditioning(p, p.task->answer(), literals, false);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].code, "ill-conditioned");
  EXPECT_EQ(d[0].path, "/object/radius");
}

TEST(Conditioning, AmplifiedAnswerIsFlagged) {
  // Nearly parallel to the plane z = 1: t = 1/0.00125 = 800. The direction's z printed to
  // 5e-6 moves t by 3.2, 800 times its relative share of the direction.
  Problem p = testing::problem(R"({"id": "c", "ray": {"origin": [0, 0, 0],
    "direction": [1, 0, 0.00125]}, "object": {"type": "plane", "point": [0, 0, 1],
    "normal": [0, 0, 1]}})");
  auto literals = scan_number_literals(p.source_file->text);
  auto d = check_conditioning(p, p.task->answer(), literals, false);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].path, "/ray/direction/2");
}

TEST(Conditioning, GroupsCoverEveryInputOnce) {
  for (std::size_t n : {0u, 1u, 5u, 16u, 17u, 4000u}) {
    auto groups = conditioning_groups(n);
    // One group per input up to 16; never more than 16 groups, so never more than 32 solves
    // before the halving.
    EXPECT_EQ(groups.size(), std::min<std::size_t>(n, kConditioningGroups)) << n;
    std::vector<int> seen(n, 0);
    for (const auto& g : groups) {
      EXPECT_FALSE(g.empty());
      for (std::size_t i : g) ++seen.at(i);
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(n)) << n;
  }
}

TEST(Conditioning, OneFlippingSphereAmongAThousandIsFound) {
  // 1,000 spheres of radius 1.25 centred 5.25 off the ray (missed by 4), and at index 700 a
  // unit sphere 0.996 off it: the first hit, but its radius printed as 1.00 may be 0.995,
  // where the ray misses it. Found through the groups and their halves.
  std::string objects;
  for (int i = 0; i < 1000; ++i) {
    objects += i ? ", " : "";
    objects += i == 700 ? R"({"name": "s700", "type": "sphere", "center": [5, 0.996, 0],
                          "radius": 1.00})"
                        : fmt::format(R"({{"name": "s{}", "type": "sphere", "center": [{}.5, )"
                                      R"(5.25, 0], "radius": 1.25}})",
                                      i, i + 10);
  }
  Problem p = testing::problem(R"({"id": "many", "kind": "first-hit", "ray": {"origin": [0, 0, 0],
    "direction": [1, 0, 0]}, "objects": [)" +
                               objects + "]}");
  auto literals = scan_number_literals(p.source_file->text);
  auto d = check_conditioning(p, p.task->answer(), literals, false);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].code, "ill-conditioned");
  EXPECT_EQ(d[0].path, "/objects/700/radius") << d[0].message;
}

Problem with_tests(const std::string& tests) {
  return testing::problem(R"({"id": "st", "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}, "tests": )" +
                          tests + "}");
}

TEST(SelfTests, RightAndEmptyAnswersGetTheScoresTheyState) {
  Problem p = with_tests(R"([
    {"answer": {"hits": [{"t": 1, "point": [1, 0, 0]}, {"t": 3, "point": [3, 0, 0]}]}, "score": 1},
    {"answer": {"hits": []}, "score": 0}])");
  for (const auto& d : run_self_tests(p, p.task->answer())) ADD_FAILURE() << format_diagnostic(d);
}

TEST(SelfTests, WrongScoreAndAbsentMistakeFail) {
  // A right answer scores 1, not 0.5, and has no mistake in it.
  Problem p = with_tests(R"([
    {"answer": {"hits": [{"t": 1, "point": [1, 0, 0]}, {"t": 3, "point": [3, 0, 0]}]},
     "score": 0.5},
    {"answer": {"hits": [{"t": 1, "point": [1, 0, 0]}, {"t": 3, "point": [3, 0, 0]}]},
     "score": 1, "mistake": "far-root"},
    {"answer": {"hits": []}, "scor": 0}])");
  auto d = run_self_tests(p, p.task->answer());
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0].code, "self-test");
  EXPECT_EQ(d[0].path, "/tests/0/score");
  EXPECT_EQ(d[1].code, "self-test");
  EXPECT_EQ(d[1].path, "/tests/1/mistake");
  EXPECT_EQ(d[2].code, "unknown-key");  // 'scor' (did you mean 'score'?)
  EXPECT_EQ(d[3].code, "missing-key");
}

}  // namespace
}  // namespace raygrade
