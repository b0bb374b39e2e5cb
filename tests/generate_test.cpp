// The generator: reproducible bytes, every problem passing the bank check, short answers,
// and each outcome doing what its name says.
#include "generate/generate.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "check/check.h"
#include "json/source.h"
#include "run_binary.h"
#include "sampling/prng.h"
#include "test_util.h"

namespace raygrade {
namespace {

// xoshiro256** seeded by SplitMix64 from 42: the first outputs, computed with an independent
// implementation of the published algorithms (whose SplitMix64(0) gives the published
// 0xe220a8397b1dcdaf).
TEST(Prng, MatchesThePublishedAlgorithm) {
  Prng rng(42);
  EXPECT_EQ(rng.next(), 0x15780b2e0c2ec716ULL);
  EXPECT_EQ(rng.next(), 0x6104d9866d113a7eULL);
  EXPECT_EQ(rng.next(), 0xae17533239e499a1ULL);
}

TEST(Prng, RangeStaysInBoundsAndCoversThem) {
  Prng rng(7);
  int seen[5] = {};
  for (int i = 0; i < 1000; ++i) {
    int v = rng.range(-2, 2);
    ASSERT_GE(v, -2);
    ASSERT_LE(v, 2);
    ++seen[v + 2];
  }
  for (int n : seen) EXPECT_GT(n, 100);  // each of 5 values about 200 times
}

std::string dump_all(const std::vector<GeneratedProblem>& problems) {
  std::string out;
  for (const auto& p : problems) out += p.json.dump(2) + "\n";
  return out;
}

GenerateOptions options(std::uint64_t seed, int n) {
  GenerateOptions o;
  o.seed = seed;
  o.count = n;
  return o;
}

TEST(Generate, SameSeedSameBytes) {
  std::string a = dump_all(generate_problems(options(42, 200)));
  std::string b = dump_all(generate_problems(options(42, 200)));
  EXPECT_EQ(a, b);
  EXPECT_NE(a, dump_all(generate_problems(options(43, 200))));
}

// What generate writes on standard output, a bank file check and grade read: a bank within
// the limits is written and reads back; one over 16 MiB (300 problems, each with a statement
// of 60,000 characters: 18 MB) is refused, as check would refuse it.
TEST(Generate, BankTextIsWhatABankFileMayHold) {
  auto problems = generate_problems(options(42, 20));
  std::string text = bank_text(problems);
  EXPECT_EQ(parse_json_text("bank.json", text)->root["problems"].size(), 20u);
  std::vector<GeneratedProblem> big;
  for (int i = 0; i < 300; ++i) {
    big.push_back(problems[static_cast<std::size_t>(i) % problems.size()]);
    big.back().json["statement"] = std::string(60000, 'x');
  }
  try {
    bank_text(big);
    ADD_FAILURE() << "an 18 MB bank was written";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().code, "limit");
    EXPECT_NE(e.diagnostic().message.find("--out"), std::string::npos) << e.what();
  }
  nlohmann::ordered_json bank;
  for (const auto& p : big) bank["problems"].push_back(p.json);
  try {
    parse_json_text("bank.json", bank.dump(2));
    ADD_FAILURE() << "check would read an 18 MB bank file";
  } catch (const Error& e) {
    EXPECT_EQ(e.diagnostic().code, "limit");
  }
}

int run_command(const std::string& args) {
  // Built with append rather than operator+ on a temporary, which GCC 12 at -O2 warns about
  // wrongly (-Wrestrict, in char_traits) in some unity batches.
  std::string command = RAYGRADE_BINARY;
  command.append(" ").append(args);
  int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

using testing::read_all;

// The acceptance run: `generate --seed 42 -n 200` twice gives the same bytes, and the bank it
// writes passes `check` with its solutions.
TEST(GenerateCommand, Seed42TwiceSameBytesAndPassesCheck) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / fmt::format("raygrade-generate-{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  ASSERT_EQ(run_command(fmt::format("generate --seed 42 -n 200 > {}/a.json", dir.string())), 0);
  ASSERT_EQ(run_command(fmt::format("generate --seed 42 -n 200 > {}/b.json", dir.string())), 0);
  EXPECT_EQ(read_all(dir / "a.json"), read_all(dir / "b.json"));
  EXPECT_GT(read_all(dir / "a.json").size(), 10000u);
  ASSERT_EQ(run_command(fmt::format("generate --seed 42 -n 200 --out {} > /dev/null",
                                    (dir / "bank").string())),
            0);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir / "bank" / "problems"))
    files += e.is_regular_file();
  EXPECT_EQ(files, 200u);
  CheckOptions o;
  o.solutions_dir = (dir / "bank" / "solutions").string();
  o.solutions_required = true;
  CheckReport report = check_bank({(dir / "bank" / "problems").string()}, o);
  EXPECT_EQ(report.problems.size(), 200u);
  for (const auto& d : report.diagnostics()) ADD_FAILURE() << format_diagnostic(d);
  fs::remove_all(dir);
}

// Every regular file under `root`, by its path relative to `root`, with its bytes.
std::map<std::string, std::string> tree(const std::filesystem::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file()) files[e.path().lexically_relative(root).string()] = read_all(e.path());
  }
  return files;
}

// The same seed written to two folders gives the same tree, byte for byte: no header names the
// folder. `check DIR` and `check DIR/problems`, run from a folder without solutions of its own,
// find DIR/solutions and say so.
TEST(GenerateCommand, TwoFoldersSameTreeAndCheckFindsSolutionsBesideTheBank) {
  testing::TempDir dir("generate-two");
  std::filesystem::create_directories(dir.path() / "elsewhere");
  for (const char* out : {"A", "deeper/B"}) {
    testing::RunResult r = testing::run_raygrade(
        fmt::format("generate --seed 42 -n 50 --out '{}'", (dir.path() / out).string()),
        dir.path() / "elsewhere");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  auto a = tree(dir.path() / "A"), b = tree(dir.path() / "deeper" / "B");
  EXPECT_EQ(a.size(), 50u + 50u + 1u);  // problems, solutions, the solutions' README
  EXPECT_TRUE(a == b) << "the two trees differ";
  for (const auto& [name, bytes] : a) {
    EXPECT_EQ(bytes.find(dir.path().string()), std::string::npos) << name << " names its folder";
  }
  for (const std::string bank : {"A", "A/problems"}) {
    testing::RunResult r = testing::run_raygrade("check '" + (dir.path() / bank).string() + "'",
                                                 dir.path() / "elsewhere");
    EXPECT_EQ(r.exit_code, 0) << bank << ":\n" << r.out << r.err;
    EXPECT_NE(r.out.find("worked solutions read from " + (dir.path() / "A" / "solutions").string()),
              std::string::npos)
        << r.out;
  }
  // Worked solutions in JSON beside the problems are not read as problems.
  ASSERT_EQ(
      testing::run_raygrade("generate --seed 42 -n 5 --solution-format md,json --out C", dir.path())
          .exit_code,
      0);
  testing::RunResult c = testing::run_raygrade("check C", dir.path());
  EXPECT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_NE(c.out.find("Checked 5 problems in 5 files"), std::string::npos) << c.out;
  // Nowhere to be found: the warning lists every place looked in.
  std::filesystem::rename(dir.path() / "A" / "solutions", dir.path() / "A" / "moved");
  testing::RunResult r = testing::run_raygrade("check A/problems", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("looked in A/problems/solutions, A/solutions, solutions"), std::string::npos)
      << r.out;
}

// Significant digits of a number as a person writes it: 7 → 1, 0.25 → 2, 12.5 → 3, 1/3 → 15+.
int significant_digits(double v) {
  if (v == 0) return 1;
  for (int digits = 1; digits <= 15; ++digits) {
    double scale =
        std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(v)))));
    if (std::abs(std::round(v * scale) / scale - v) <= 1e-9 * std::abs(v)) return digits;
  }
  return 16;
}

void numbers_of(const nlohmann::json& j, std::vector<double>& out) {
  if (j.is_number()) out.push_back(j.get<double>());
  if (j.is_structured()) {
    for (const auto& v : j) numbers_of(v, out);
  }
}

TEST(Generate, SignificantDigitsHelperCountsByHand) {
  EXPECT_EQ(significant_digits(7), 1);
  EXPECT_EQ(significant_digits(0.25), 2);
  EXPECT_EQ(significant_digits(-12.5), 3);
  EXPECT_EQ(significant_digits(100), 1);
  EXPECT_GT(significant_digits(1.0 / 3), 3);
}

// The reference solver's answers (t and points; normals are unit vectors and not asked for)
// to generated problems: at least 80% have only numbers of at most three significant digits.
TEST(Generate, AnswersAreShort) {
  auto problems = generate_problems(options(42, 200));
  int short_answers = 0;
  for (const auto& g : problems) {
    Problem p = testing::problem(g.json.dump());
    nlohmann::json answer = p.task->answer();
    std::vector<double> numbers;
    if (answer.contains("hits")) {
      for (const auto& h : answer["hits"]) {
        numbers.push_back(h["t"].get<double>());
        numbers_of(h["point"], numbers);
      }
    }
    if (answer.contains("ray")) numbers_of(answer["ray"]["direction"], numbers);
    bool is_short = true;
    for (double v : numbers) is_short = is_short && significant_digits(v) <= 3;
    short_answers += is_short;
  }
  EXPECT_GE(short_answers, 160) << short_answers << " of 200";
}

int hit_count(const GeneratedProblem& g) {
  return static_cast<int>(testing::problem(g.json.dump()).task->answer()["hits"].size());
}

TEST(Generate, OutcomesDoWhatTheySay) {
  GenerateOptions o = options(5, 40);
  o.kinds = {"sphere", "cylinder"};
  o.outcome = Outcome::kTangent;
  for (const auto& g : generate_problems(o)) EXPECT_EQ(hit_count(g), 1) << g.id;
  o.outcome = Outcome::kMiss;
  for (const auto& g : generate_problems(o)) EXPECT_EQ(hit_count(g), 0) << g.id;
  o.outcome = Outcome::kBehind;
  for (const auto& g : generate_problems(o)) EXPECT_EQ(hit_count(g), 0) << g.id;
  o.outcome = Outcome::kHit;
  for (const auto& g : generate_problems(o)) EXPECT_EQ(hit_count(g), 2) << g.id;
  o.kinds = {"sphere", "cylinder", "box"};
  o.outcome = Outcome::kInside;
  for (const auto& g : generate_problems(o)) EXPECT_EQ(hit_count(g), 1) << g.id;
  o.kinds = {"triangle", "polygon", "plane"};
  o.outcome = Outcome::kMiss;
  for (const auto& g : generate_problems(o)) EXPECT_EQ(hit_count(g), 0) << g.id;
  o.outcome = Outcome::kHit;
  for (const auto& g : generate_problems(o)) EXPECT_EQ(hit_count(g), 1) << g.id;
}

TEST(Generate, UnknownKindAndImpossibleOutcomeAreErrors) {
  GenerateOptions o = options(1, 3);
  o.kinds = {"sphre"};
  EXPECT_THROW(generate_problems(o), Error);
  o.kinds = {"camera-ray"};
  o.outcome = Outcome::kTangent;
  EXPECT_THROW(generate_problems(o), Error);
}

}  // namespace
}  // namespace raygrade
