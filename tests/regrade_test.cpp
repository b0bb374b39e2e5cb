// raygrade regrade against a new bank whose problems moved, were added or were removed: the
// grades are paired by problem id, never by position.
#include "grading/regrade.h"

#include <gtest/gtest.h>

#include <string>

#include "run_binary.h"

namespace raygrade {
// Named rather than anonymous: a unity batch of tests shares one anonymous namespace.
namespace regrade_test {

using testing::run_raygrade;
using testing::TempDir;
using testing::write_text;

// A sphere of radius 1 at (0, 0, c) seen from the origin along +z: hits at t = c − 1, c + 1.
std::string sphere(const std::string& id, int c) {
  return R"({"id": ")" + id + R"(", "title": ")" + id +
         R"(", "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
  "object": {"type": "sphere", "center": [0, 0, )" +
         std::to_string(c) + R"(], "radius": 1}})";
}

std::string bank(const std::vector<std::string>& problems) {
  std::string out = R"({"problems": [)";
  for (std::size_t i = 0; i < problems.size(); ++i) out += (i ? ",\n" : "") + problems[i];
  return out + "]}";
}

// pa is answered right (its sphere at z = 5: t = 4 and 6), pb wrong (its sphere at z = 10:
// t = 9 and 11, answered 1 and 2).
void write_submission(const TempDir& dir) {
  write_text(dir.path() / "subs" / "s1.json", R"({"student": {"id": "s1"}, "answers": {
    "pa": {"hits": [{"t": 4, "point": [0, 0, 4]}, {"t": 6, "point": [0, 0, 6]}]},
    "pb": {"hits": [{"t": 1, "point": [0, 0, 1]}, {"t": 2, "point": [0, 0, 2]}]}}})");
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

TEST(Regrade, AProblemInsertedFirstIsListedAsAddedAndTheOthersUnchanged) {
  TempDir dir("regrade-insert");
  std::filesystem::create_directories(dir.path() / "subs");
  write_text(dir.path() / "old.json", bank({sphere("pa", 5), sphere("pb", 10)}));
  write_text(dir.path() / "new.json",
             bank({sphere("pnew", 20), sphere("pa", 5), sphere("pb", 10)}));
  write_submission(dir);
  auto r = run_raygrade("regrade --problems old.json --bank new.json subs", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 1u) << r.out;
  EXPECT_EQ(rows[0].substr(0, rows[0].find('\t', 3)), "s1\tpnew") << rows[0];
  EXPECT_NE(rows[0].find("added"), std::string::npos) << rows[0];
  EXPECT_EQ(rows[0].find("points 2"), std::string::npos) << rows[0];
  EXPECT_NE(r.err.find("1 of 1 students"), std::string::npos) << r.err;
}

TEST(Regrade, AProblemRemovedIsListedAsRemovedAndTheOthersUnchanged) {
  TempDir dir("regrade-remove");
  std::filesystem::create_directories(dir.path() / "subs");
  write_text(dir.path() / "old.json", bank({sphere("pa", 5), sphere("pb", 10)}));
  write_text(dir.path() / "new.json", bank({sphere("pb", 10)}));
  write_submission(dir);
  auto r = run_raygrade("regrade --problems old.json --bank new.json subs", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 1u) << r.out;
  EXPECT_EQ(rows[0].substr(0, rows[0].find('\t', 3)), "s1\tpa") << rows[0];
  EXPECT_NE(rows[0].find("removed"), std::string::npos) << rows[0];
}

TEST(Regrade, ReorderedProblemsChangeNothing) {
  TempDir dir("regrade-reorder");
  std::filesystem::create_directories(dir.path() / "subs");
  write_text(dir.path() / "old.json", bank({sphere("pa", 5), sphere("pb", 10)}));
  write_text(dir.path() / "new.json", bank({sphere("pb", 10), sphere("pa", 5)}));
  write_submission(dir);
  auto r = run_raygrade("regrade --problems old.json --bank new.json subs", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("0 of 1 students"), std::string::npos) << r.err;
}

GradeResult result(const std::string& id, double score, double max_score) {
  GradeResult r;
  r.problem_id = id;
  r.score = score;
  r.max_score = max_score;
  return r;
}

TEST(Regrade, ChangesArePairedByProblemId) {
  std::vector<GradeResult> before = {result("pa", 2, 2), result("pb", 0, 2), result("pc", 1, 2)};
  std::vector<GradeResult> after = {result("pnew", 0, 3), result("pb", 0, 2), result("pa", 2, 2)};
  auto changes = grade_changes(before, after);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_EQ(changes[0].problem_id, "pnew");
  EXPECT_EQ(changes[0].what, "added (0 of 3 points)");
  EXPECT_EQ(changes[1].problem_id, "pc");
  EXPECT_EQ(changes[1].what, "removed (was 1 of 2 points)");
  // The same id on both sides with a different score is a change of points.
  changes = grade_changes({result("pa", 2, 2)}, {result("pa", 0, 2)});
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].what, "points 2 → 0");
}

TEST(Regrade, ADuplicatedIdIsPairedInOrderOfOccurrence) {
  std::vector<GradeResult> before = {result("p", 1, 2), result("p", 2, 2)};
  std::vector<GradeResult> after = {result("p", 1, 2), result("p", 2, 2), result("p", 0, 2)};
  auto changes = grade_changes(before, after);
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].what, "added (0 of 2 points)");
}

}  // namespace regrade_test
}  // namespace raygrade
