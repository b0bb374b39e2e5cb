// Submissions: the bundled samples (every student answer of the seeds) graded as an
// instructor would, malformed submissions reported with file, path and fault, and the grade
// command over a folder.
#include "grading/submission.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "test_util.h"

namespace raygrade {
namespace {

using testing::kSource;

struct Samples {
  Bank bank = load_bank({kSource + "/problems"});
  Assignment assignment{bank.problems, AssignmentOptions{true}};
};

const Samples& samples() {
  static Samples s;
  return s;
}

const GradeResult& result(const SubmissionGrade& g, const std::string& id) {
  for (const auto& r : g.results) {
    if (r.problem_id == id) return r;
  }
  throw std::runtime_error("no result for " + id);
}

std::vector<std::string> ids(const GradeResult& r) {
  std::vector<std::string> out;
  for (const auto& m : r.mistakes) out.push_back(m.id);
  return out;
}

// Seed 000: sphere case 1 (t = 1, 3 with L, t_ca, d², t_hc) and plane case 1 (t = 2) are
// right; the plane's D = −2 is a sign slip; the cylinder's b = 2v_x + 2v_y lacks the origin.
TEST(Samples, Seed000) {
  SubmissionGrade g = samples().assignment.grade_file(kSource + "/submissions/seed000.json");
  ASSERT_TRUE(g.gradable) << (g.fault ? format_diagnostic(*g.fault) : "");
  const auto& sphere = result(g, "seed000-sphere-1");
  EXPECT_DOUBLE_EQ(sphere.score, sphere.max_score);
  EXPECT_TRUE(sphere.mistakes.empty());
  const auto& plane = result(g, "seed000-plane-1");
  EXPECT_DOUBLE_EQ(plane.score, plane.max_score);
  EXPECT_EQ(ids(plane), std::vector<std::string>{"plane-d-sign"});
  const auto& cyl = result(g, "seed000-cylinder-derive-origin");
  EXPECT_EQ(ids(cyl), std::vector<std::string>{"cylinder-b-no-origin"});
  EXPECT_DOUBLE_EQ(cyl.score, 2);  // a and c right
  EXPECT_DOUBLE_EQ(cyl.max_score, 3);
}

// Seed 001: sphere 3 first, t = 7.27 at two decimals; n = ac × ab points the wrong way.
TEST(Samples, Seed001) {
  SubmissionGrade g = samples().assignment.grade_file(kSource + "/submissions/seed001.json");
  ASSERT_TRUE(g.gradable);
  const auto& first = result(g, "seed001-first-hit");
  EXPECT_DOUBLE_EQ(first.score, first.max_score);
  EXPECT_TRUE(first.mistakes.empty());
  const auto& tri = result(g, "seed001-triangle");
  EXPECT_TRUE(tri.has_mistake("cross-order"));
  EXPECT_DOUBLE_EQ(tri.score, 2.5);  // t and point right, the normal half
}

// Seed 004: the camera formula is the corner convention: right for the corner problem,
// recognised as such for the centre one; the plane (t = 3/2), box (t = 1, 2) and triangle
// (t = 1/6, q = (1/6, 1/3, 1/2)) answers are right.
TEST(Samples, Seed004) {
  SubmissionGrade g = samples().assignment.grade_file(kSource + "/submissions/seed004.json");
  ASSERT_TRUE(g.gradable);
  EXPECT_DOUBLE_EQ(result(g, "seed004-camera-ray").score, 1);
  const auto& centre = result(g, "seed004-camera-ray-centre");
  EXPECT_EQ(ids(centre), std::vector<std::string>{"pixel-corner"});
  for (const char* id : {"seed004-plane", "seed004-box", "seed004-triangle"}) {
    const auto& r = result(g, id);
    EXPECT_DOUBLE_EQ(r.score, r.max_score) << id;
    EXPECT_TRUE(r.mistakes.empty()) << id;
  }
}

std::string write_temp(const std::string& name, const std::string& text) {
  auto dir = std::filesystem::temp_directory_path() / "raygrade_submission_test";
  std::filesystem::create_directories(dir);
  auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

TEST(Submission, MalformedIsReportedWithPath) {
  const Assignment& a = samples().assignment;
  SubmissionGrade bad = a.grade_file(write_temp("bad.json",
                                                "{\"answers\": {\n"
                                                "  \"seed000-sphere-1\": {\"hits\": 3}}}"));
  EXPECT_FALSE(bad.gradable);
  ASSERT_TRUE(bad.fault);
  EXPECT_EQ(bad.fault->path, "/answers/seed000-sphere-1/hits");
  EXPECT_EQ(bad.fault->line, 2);
  // An unknown problem id is a finding; the rest of the file is graded.
  SubmissionGrade typo =
      a.grade_file(write_temp("typo.json", R"({"answers": {"seed000-sphere-9x": {}}})"));
  EXPECT_TRUE(typo.gradable);
  ASSERT_EQ(typo.findings.size(), 1u);
  EXPECT_EQ(typo.findings[0].code, "unknown-problem");
  SubmissionGrade broken = a.grade_file(write_temp("broken.json", "{\"answers\": "));
  EXPECT_FALSE(broken.gradable);
  EXPECT_FALSE(broken.fault->message.empty());
  SubmissionGrade named = a.grade_file(write_temp("x.json", R"({"student": {"name": "Ada"},
    "answers": {"seed000-sphere-2": {"hits": []}}})"));
  ASSERT_TRUE(named.gradable);
  EXPECT_EQ(named.student, "Ada");
  EXPECT_DOUBLE_EQ(named.score, named.max_score);
}

// A bank where a submission goes (`grade --problems a.json b.json` takes b.json as a
// submission) is named as a bank, at its problems, rather than as an unknown key.
TEST(Submission, ABankGivenAsASubmissionIsNamedAsOne) {
  const Assignment& a = samples().assignment;
  SubmissionGrade g =
      a.grade_file(write_temp("bank-as-submission.json", "{\"title\": \"t\",\n \"problems\": []}"));
  ASSERT_FALSE(g.gradable);
  EXPECT_EQ(g.fault->code, "not-a-submission");
  EXPECT_EQ(g.fault->path, "/problems");
  EXPECT_EQ(g.fault->line, 2);
  EXPECT_NE(g.fault->message.find("problem bank"), std::string::npos);
}

// A key spelled with escapes ("\u0062ogus" is "bogus") is named at its line and column, as
// one spelled plainly is: at the value under it (line 3, column 17 for the 1).
TEST(Submission, EscapedKeyIsLocated) {
  const Assignment& a = samples().assignment;
  SubmissionGrade g = a.grade_file(write_temp("escaped-key.json",
                                              "{\"student\": \"E\",\n"
                                              "  \"answers\": {},\n"
                                              "  \"\\u0062ogus\": 1}"));
  ASSERT_FALSE(g.gradable);
  EXPECT_EQ(g.fault->code, "unknown-key");
  EXPECT_EQ(g.fault->path, "/bogus");
  EXPECT_EQ(g.fault->line, 3);
  EXPECT_EQ(g.fault->column, 17);
  SubmissionGrade answer = a.grade_file(write_temp("escaped-answer-key.json",
                                                   "{\"answers\": {\"seed000-sphere-2\":\n"
                                                   "  {\"hits\": [], \"\\u0078yz\": 2}}}"));
  ASSERT_FALSE(answer.gradable);
  EXPECT_EQ(answer.fault->path, "/answers/seed000-sphere-2/xyz");
  EXPECT_EQ(answer.fault->line, 2);
  EXPECT_EQ(answer.fault->column, 28);
}

// A folder with a good and a malformed submission: both reported, exit code 2.
TEST(Submission, GradeCommandGoesOnAfterABadFile) {
  auto dir = std::filesystem::temp_directory_path() / "raygrade_grade_cli_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "in");
  std::ofstream(dir / "in" / "a.json")
      << R"({"student": "A", "answers": {"seed000-sphere-2": {"hits": []}}})";
  std::ofstream(dir / "in" / "b.json") << R"({"student": "B", "answers": [1, 2]})";
  std::string cmd =
      fmt::format("{} grade --problems {}/problems {} --format csv --out {} 2>/dev/null",
                  RAYGRADE_BINARY, kSource, (dir / "in").string(), (dir / "out").string());
  int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream csv(dir / "out" / "gradebook.csv");
  std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\nA,"), std::string::npos);
  EXPECT_NE(text.find("\nB,"), std::string::npos);
  EXPECT_NE(text.find("rejected"), std::string::npos);
  // One submission in PrairieLearn's form goes to standard output.
  std::string one =
      fmt::format("{} grade --problems {}/problems {} --format prairielearn > {}", RAYGRADE_BINARY,
                  kSource, (dir / "in" / "a.json").string(), (dir / "pl.json").string());
  EXPECT_EQ(WEXITSTATUS(std::system(one.c_str())), 0);
  std::ifstream pl(dir / "pl.json");
  nlohmann::json j = nlohmann::json::parse(pl);
  EXPECT_TRUE(j["gradable"].get<bool>());
}

}  // namespace
}  // namespace raygrade
