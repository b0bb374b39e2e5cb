// The LTI tool's grading of stored submissions: the same points as `raygrade grade`, the class
// report and the gradebook of each student's last submission.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "serve/catalog.h"
#include "serve/instructor.h"

namespace serve_instructor_test {

using raygrade::serve::Catalog;
using raygrade::serve::SubmissionRecord;

SubmissionRecord record(const std::string& sub, const std::string& answers, double score) {
  SubmissionRecord r;
  r.issuer = "https://lms.example";
  r.sub = sub;
  r.assignment = "lab-ray-tree.json";
  r.answers = answers;
  r.score = score;
  r.max_score = 3;
  return r;
}

TEST(ServeCatalog, OffersTheFoldersAssignmentsWithTheirPoints) {
  Catalog c(RAYGRADE_SOURCE_DIR "/assignments");
  ASSERT_TRUE(c.find("lab-ray-tree.json"));
  ASSERT_TRUE(c.find("homework-rays.json"));
  EXPECT_FALSE(c.find("roster.csv"));
  // assignments/lab-ray-tree.json: one problem worth 3 points; homework-rays.json:
  // 3+2+3+2+2+1+2+3+1+2.
  EXPECT_DOUBLE_EQ(c.find("lab-ray-tree.json")->points(), 3);
  EXPECT_DOUBLE_EQ(c.find("homework-rays.json")->points(), 21);
}

TEST(ServeCatalog, AssignmentPointsOverrideTheBanks) {
  auto dir = std::filesystem::temp_directory_path() /
             ("raygrade-serve-catalog-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "one.json")
      << R"({"assignment": "one", "bank": ")" RAYGRADE_SOURCE_DIR
         R"(/problems", "problems": [{"id": "variant-sphere", "points": 7.5}]})";
  std::ofstream(dir / "notes.json") << R"({"not": "an assignment"})";
  Catalog c(dir.string());
  ASSERT_EQ(c.entries().size(), 1u);
  EXPECT_DOUBLE_EQ(c.find("one.json")->points(), 7.5);
  std::filesystem::remove_all(dir);
}

TEST(ServeInstructor, LastSubmissionOfEachStudentInFirstSubmissionOrder) {
  auto last = raygrade::serve::last_per_student(
      {record("b", "{}", 0), record("a", "{}", 1), record("b", "{}", 2)});
  ASSERT_EQ(last.size(), 2u);
  EXPECT_EQ(last[0].sub, "b");
  EXPECT_EQ(last[0].score, 2);
  EXPECT_EQ(last[1].sub, "a");
}

TEST(ServeInstructor, ReportAndGradebookOfStoredSubmissions) {
  Catalog c(RAYGRADE_SOURCE_DIR "/assignments");
  const auto* e = c.find("lab-ray-tree.json");
  ASSERT_TRUE(e);
  std::vector<SubmissionRecord> subs = {record("u1", "{}", 0), record("u2", "{}", 0)};
  std::string html = raygrade::serve::class_report_page(*e, subs);
  EXPECT_NE(html.find("<html"), std::string::npos);
  std::string csv = raygrade::serve::gradebook_of(*e, subs);
  // A header and one row per student, each unanswered: 0 of 3.
  EXPECT_NE(csv.find("https://lms.example u1"), std::string::npos);
  EXPECT_NE(csv.find("https://lms.example u2"), std::string::npos);
}

}  // namespace serve_instructor_test
