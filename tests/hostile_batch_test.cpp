// A batch of hostile submissions graded in one run of `raygrade grade` together with good
// ones (tests/fixtures/hostile): every hostile file is rejected with a clean error that names
// it and says what is wrong, every good one is graded right, the exit code says some inputs
// were rejected, and text a student controls comes out escaped in every format.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "run_binary.h"

namespace raygrade {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_text;
using testing::run_raygrade;
using testing::TempDir;
using testing::write_text;

const fs::path kFixtures = fs::path(RAYGRADE_SOURCE_DIR) / "tests/fixtures/hostile";

// The fault each hostile file must be rejected with (docs/hardening.md lists the codes).
const std::map<std::string, std::string> kExpectedFault = {
    {"bad-answers-is-array.json", "type"},
    {"bad-binary.json", "bad-json"},  // a NUL byte: "is this a text file?"
    {"bad-comment.json", "bad-json"},
    {"bad-deep-nesting.json", "limit"},
    {"bad-duplicate-answer.json", "duplicate-key"},
    {"bad-duplicate-key-in-hit.json", "duplicate-key"},
    {"bad-empty.json", "bad-json"},
    {"bad-hits-is-string.json", "type"},
    {"bad-huge-string.json", "limit"},
    {"bad-infinity-token.json", "bad-json"},
    {"bad-invalid-utf8.json", "bad-encoding"},
    {"bad-lone-surrogate.json", "bad-encoding"},
    {"bad-missing-answers.json", "missing-key"},
    {"bad-nan-token.json", "bad-json"},
    {"bad-nul-byte.json", "bad-json"},
    {"bad-number-1e400.json", "range"},
    {"bad-number-1e99999.json", "range"},
    {"bad-number-huge-integer.json", "range"},
    {"bad-raw-control-character.json", "bad-json"},
    {"bad-root-array.json", "type"},
    {"bad-root-null.json", "type"},
    {"bad-root-string.json", "type"},
    {"bad-student-is-number.json", "type"},
    {"bad-t-is-boolean.json", "type"},
    {"bad-t-is-object.json", "type"},
    {"bad-trailing-garbage.json", "bad-json"},
    {"bad-truncated.json", "bad-json"},
    {"bad-unknown-key.json", "unknown-key"},
    {"bad-utf16.json", "bad-encoding"},
    {"bad-whitespace-only.json", "bad-json"},
    // Made by the test: too large or too odd to keep as files.
    {"bad-over-1-mib.json", "limit"},
    {"bad-10001-answers.json", "limit"},
};

// Answers to problems the assignment does not have: graded (nothing to grade), each unknown
// id a finding with its JSON path, never a rejection of the file.
const std::set<std::string> kFindings = {"finding-path-traversal-problem.json",
                                         "finding-unknown-problem.json"};

// A typed number beyond the parser's limits: that answer alone is wrong, with the limit in its
// feedback; the file is graded.
const std::map<std::string, std::string> kWrongAnswer = {
    {"wrong-formula-too-deep.json", "20 parentheses"},
    {"wrong-formula-too-long.json", "1000 characters"},
};

// A right answer to both problems of problems.json: the ray along +x meets the unit sphere at
// (2, 0, 0) at t = 1 and 3, and the plane x = 2 at t = 2.
const char* kRightAnswers =
    R"({"sphere-1": {"hits": [{"t": 1, "point": [1, 0, 0]}, {"t": 3, "point": [3, 0, 0]}]},
        "plane-1": {"hits": [{"t": 2, "point": [2, 0, 0]}]}})";

// The fixtures copied beside the cases the test makes, in a fresh folder.
class HostileBatch : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::copy(kFixtures / "submissions", subs_);
    // 1 MiB and a little more, in one long run of spaces: valid JSON, too large.
    write_text(subs_ / "bad-over-1-mib.json", std::string(R"({"student": "big", "answers": {}})") +
                                                  std::string((1u << 20) + 10, ' '));
    std::string many = R"({"student": "many", "answers": {)";
    for (int i = 0; i < 10001; ++i) {
      many += (i ? ", " : "") + ("\"p" + std::to_string(i) + "\": {\"hits\": []}");
    }
    write_text(subs_ / "bad-10001-answers.json", many + "}}");
    // A right submission whose file name is Latin-1, not UTF-8.
    write_text(subs_ / std::string("good-latin1-name-\xe9t\xe9.json"),
               std::string(R"({"student": "latin1", "answers": )") + kRightAnswers + "}");
  }

  testing::RunResult grade(const std::string& args) {
    return run_raygrade("grade --problems '" + (kFixtures / "problems.json").string() + "' '" +
                            subs_.string() + "' " + args,
                        dir_.path());
  }

  TempDir dir_{"hostile"};
  fs::path subs_ = dir_.path() / "submissions";
};

TEST_F(HostileBatch, EveryHostileFileRejectedEveryGoodOneGradedRight) {
  auto r = grade("--format json");
  EXPECT_EQ(r.exit_code, 2) << "some inputs were rejected";
  json report = json::parse(r.out);
  std::set<std::string> seen;
  std::size_t good = 0;
  for (const json& s : report.at("submissions")) {
    std::string name = fs::path(s.at("file").get<std::string>()).filename().string();
    seen.insert(name);
    if (name.rfind("bad-", 0) == 0) {
      ASSERT_TRUE(kExpectedFault.count(name)) << "an unlisted fixture: " << name;
      EXPECT_FALSE(s.at("gradable").get<bool>()) << name;
      ASSERT_TRUE(s.contains("fault")) << name << ": a rejection says why";
      const json& f = s["fault"];
      EXPECT_EQ(f.at("code"), kExpectedFault.at(name)) << name << ": " << f.dump();
      EXPECT_NE(f.at("file").get<std::string>().find(name), std::string::npos) << name;
      EXPECT_FALSE(f.at("message").get<std::string>().empty()) << name;
      // Where the fault is inside a well-formed document, the JSON path is named.
      static const std::set<std::string> kInside = {"duplicate-key", "range", "unknown-key"};
      bool inside = kInside.count(f["code"].get<std::string>()) ||
                    (f["code"] == "type" && name.rfind("bad-root-", 0) != 0) ||
                    name.rfind("bad-formula-", 0) == 0;
      if (inside) {
        EXPECT_FALSE(f.at("path").get<std::string>().empty()) << name;
      }
      // The message speaks of the input, not of the parser's internals.
      EXPECT_EQ(f["message"].get<std::string>().find("nlohmann"), std::string::npos) << name;
      EXPECT_EQ(f["message"].get<std::string>().find("[json.exception"), std::string::npos) << name;
    } else if (kWrongAnswer.count(name)) {
      ASSERT_TRUE(s.at("gradable").get<bool>()) << name << ": " << s.dump();
      bool said = false;
      for (const json& result : s.at("problems")) {
        if (!result.at("answered").get<bool>()) continue;
        EXPECT_LT(result.at("score").get<double>(), result.at("max_score").get<double>()) << name;
        said = said || result.dump().find(kWrongAnswer.at(name)) != std::string::npos;
      }
      EXPECT_TRUE(said) << name << " does not name its limit: " << s.dump();
    } else if (kFindings.count(name)) {
      ASSERT_TRUE(s.at("gradable").get<bool>()) << name;
      ASSERT_EQ(s.at("findings").size(), 1u) << name;
      const json& f = s["findings"][0];
      EXPECT_EQ(f.at("code"), "unknown-problem") << name;
      EXPECT_EQ(f.at("path").get<std::string>().rfind("/answers/", 0), 0u) << name;
      if (name == "finding-unknown-problem.json") {
        EXPECT_NE(f.at("message").get<std::string>().find("did you mean 'sphere-1'"),
                  std::string::npos);
      }
    } else {
      ++good;
      ASSERT_TRUE(s.at("gradable").get<bool>()) << name << ": " << s.dump();
      // Every problem the file answers earns full marks.
      int answered = 0;
      for (const json& result : s.at("problems")) {
        if (!result.at("answered").get<bool>()) continue;
        ++answered;
        EXPECT_DOUBLE_EQ(result.at("score").get<double>(), result.at("max_score").get<double>())
            << name << " " << result["problem"];
      }
      EXPECT_GE(answered, 1) << name;
    }
  }
  EXPECT_EQ(good, 11u);  // ten fixtures and the Latin-1 file name
  for (const auto& [name, code] : kExpectedFault) EXPECT_TRUE(seen.count(name)) << name;
  for (const auto& name : kFindings) EXPECT_TRUE(seen.count(name)) << name;
  // Each rejection is also on standard error, one line naming the file.
  for (const auto& [name, code] : kExpectedFault)
    EXPECT_NE(r.err.find(name), std::string::npos) << name;
}

TEST_F(HostileBatch, FilesStayInTheOutputFolderAndTextIsEscaped) {
  fs::path out = dir_.path() / "out";
  auto r = grade("--format html --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(fs::exists("/tmp/raygrade-escape.html"));
  std::size_t pages = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir_.path())) {
    if (entry.path().extension() != ".html") continue;
    EXPECT_EQ(entry.path().parent_path(), out) << entry.path();
    ++pages;
    std::string html = read_text(entry.path());
    EXPECT_EQ(html.find("<script"), std::string::npos) << entry.path();
    EXPECT_EQ(html.find('\x1b'), std::string::npos) << entry.path();
  }
  // One page per file, a rejection included, and the index of them all.
  EXPECT_EQ(pages, kExpectedFault.size() + kFindings.size() + kWrongAnswer.size() + 11 + 1);
}

// The cells of a CSV text (RFC 4180: quoted cells, "" for a quote inside one).
std::vector<std::string> csv_cells(const std::string& text) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',' || c == '\n' || c == '\r') {
      if (c != '\n' || i == 0 || text[i - 1] != '\r') cells.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  if (!cell.empty()) cells.push_back(cell);
  return cells;
}

TEST_F(HostileBatch, GradebookNeutralisesFormulas) {
  auto r = grade("--format csv");
  EXPECT_EQ(r.exit_code, 2);
  std::vector<std::string> cells = csv_cells(r.out);
  bool saw_name = false;
  for (const std::string& cell : cells) {
    // No cell starts a spreadsheet formula, quoted or not (a number may carry its sign).
    if (cell.empty() || std::string("=+-@").find(cell[0]) == std::string::npos) {
      saw_name = saw_name || cell == "'=HYPERLINK(\"http://example.com/x\",\"grade\")";
      continue;
    }
    char* end = nullptr;
    std::strtod(cell.c_str(), &end);
    EXPECT_TRUE(end && *end == '\0') << "a cell starts a formula: " << cell;
  }
  EXPECT_TRUE(saw_name) << "the student named =HYPERLINK(...) is listed, neutralised";
}

// Threads change nothing a person reads: a batch larger than one window of files, graded on
// one, two and five threads, gives the same gradebook, report and errors, in the same order.
TEST_F(HostileBatch, ThreadsChangeNothing) {
  // Right answers for even students: 3 points a problem (t 2, point 1: the default weights of
  // docs/grading.md). Odd students say the ray misses the plane it meets at t = 2, and earn the
  // sphere's 3 points alone.
  std::string wrong = kRightAnswers;
  std::string plane_hit = R"([{"t": 2, "point": [2, 0, 0]}])";
  wrong.replace(wrong.find(plane_hit), plane_hit.size(), "[]");
  for (int i = 0; i < 300; ++i) {
    write_text(subs_ / ("batch-" + std::to_string(1000 + i) + ".json"),
               "{\"student\": \"batch " + std::to_string(i) +
                   "\", \"answers\": " + (i % 2 ? wrong : std::string(kRightAnswers)) + "}");
  }
  auto one = grade("--format csv --jobs 1");
  ASSERT_EQ(one.exit_code, 2);
  for (const char* jobs : {"2", "5"}) {
    auto many = grade(std::string("--format csv --jobs ") + jobs);
    EXPECT_EQ(many.exit_code, one.exit_code) << jobs;
    EXPECT_EQ(many.out, one.out) << jobs << " threads";
    EXPECT_EQ(many.err, one.err) << jobs << " threads";
  }
  EXPECT_EQ(grade("--format json --jobs 1").out, grade("--format json --jobs 2").out);
  // The rows themselves: each generated student's total, in the files' order.
  std::size_t seen = 0;
  std::size_t at = 0;
  for (int i = 0; i < 300; ++i) {
    std::string name = "batch " + std::to_string(i) + ",";
    at = one.out.find("\n" + name, at);
    ASSERT_NE(at, std::string::npos) << name;
    std::string row = one.out.substr(at + 1, one.out.find('\n', at + 1) - at - 1);
    EXPECT_NE(row.find(i % 2 ? ",3,0,3,6," : ",3,3,6,6,"), std::string::npos) << row;
    ++seen;
  }
  EXPECT_EQ(seen, 300u);
}

}  // namespace
}  // namespace raygrade
