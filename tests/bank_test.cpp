// The bundled bank: every problem reads, and every answer agrees with the `expected` its
// author derived by hand (or took from the seeds).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "problems/problem.h"

namespace raygrade {
namespace {

// Hand-derived answers are exact or short decimals; the reference agrees to rounding.
constexpr double kBankRelative = 1e-9;
// The seed documents print rounded answers (seed 001: t ≈ 7.27, stated as 7.2679).
constexpr double kSeedRelative = 1e-4;

bool near(double got, double want, double relative) {
  return std::abs(got - want) <= relative * std::max(1.0, std::abs(want));
}

// Compares every number of `want` with the same place in `got`; keys absent from `want` are
// not checked (an author may state only t and the point). Returns the first difference.
std::string compare(const nlohmann::json& got, const nlohmann::json& want, const std::string& at,
                    double relative) {
  if (want.is_number()) {
    if (!got.is_number() || !near(got.get<double>(), want.get<double>(), relative)) {
      return fmt::format("{}: {} instead of {}", at, got.dump(), want.dump());
    }
    return "";
  }
  if (want.is_array()) {
    if (!got.is_array() || got.size() != want.size()) {
      return fmt::format("{}: {} instead of {}", at, got.dump(), want.dump());
    }
    for (std::size_t i = 0; i < want.size(); ++i) {
      std::string why = compare(got[i], want[i], fmt::format("{}/{}", at, i), relative);
      if (!why.empty()) return why;
    }
    return "";
  }
  if (want.is_object()) {
    for (const auto& [key, value] : want.items()) {
      if (!got.contains(key)) {
        if (value == false) continue;  // "contained": false and "tie": false are the defaults
        return fmt::format("{}/{}: missing", at, key);
      }
      std::string why = compare(got[key], value, fmt::format("{}/{}", at, key), relative);
      if (!why.empty()) return why;
    }
    return "";
  }
  return got == want ? "" : fmt::format("{}: {} instead of {}", at, got.dump(), want.dump());
}

TEST(Bank, EveryProblemReadsAndMatchesItsExpectedAnswer) {
  Bank bank = load_bank({RAYGRADE_SOURCE_DIR "/problems"});
  for (const auto& e : bank.errors) ADD_FAILURE() << format_diagnostic(e);
  int checked = 0;
  for (const auto& p : bank.problems) {
    if (!p.expected) continue;
    nlohmann::json answer = p.task->answer();
    double relative = p.file.find("/seeds/") != std::string::npos ? kSeedRelative : kBankRelative;
    std::string why = compare(answer, *p.expected, "", relative);
    EXPECT_EQ(why, "") << p.id << " (" << p.file << ")";
    // A stated miss must not be answered with hits, nor "contained" be left out.
    if (p.expected->contains("contained")) {
      EXPECT_EQ(answer.value("contained", false), (*p.expected)["contained"].get<bool>()) << p.id;
    }
    ++checked;
  }
  EXPECT_GE(checked, 60);
}

// At least five problems for each primitive, and some of every kind.
TEST(Bank, CoversEveryPrimitiveAndKind) {
  Bank bank = load_bank({RAYGRADE_SOURCE_DIR "/problems"});
  std::map<std::string, int> count;
  for (const auto& p : bank.problems) {
    if (p.kind == "intersect") {
      count[p.source["object"]["type"].get<std::string>()]++;
    } else {
      count[p.kind]++;
    }
  }
  for (const char* type : {"sphere", "plane", "triangle", "polygon", "cylinder", "box"}) {
    EXPECT_GE(count[type], 5) << type;
  }
  EXPECT_GE(count["first-hit"], 3);
  EXPECT_GE(count["camera-ray"], 3);
}

}  // namespace
}  // namespace raygrade
