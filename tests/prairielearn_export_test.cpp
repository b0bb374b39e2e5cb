// The PrairieLearn questions of an assignment: their layout, and text from the bank kept inert
// in question.html (tests/prairielearn_export.py drives their server.py).
#include <gtest/gtest.h>

#include <map>

#include "assignments/lms_export.h"
#include "run_binary.h"

namespace raygrade {
namespace {

using testing::TempDir;
using testing::write_text;

// An assignment of one first-hit problem whose object names carry markup and mustache tags.
std::map<std::string, ZipEntry> export_hostile_names(const TempDir& dir) {
  write_text(dir.path() / "bank.json", R"({"problems": [{
    "id": "names", "kind": "first-hit", "title": "Which is hit first?",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "objects": [
      {"name": "<script>alert(1)</script>", "type": "sphere", "center": [5, 0, 0], "radius": 1},
      {"name": "{{params.secret}}", "type": "sphere", "center": [9, 0, 0], "radius": 1}]}]})");
  write_text(dir.path() / "hw.json",
             R"({"assignment": "hw", "bank": "bank.json", "problems": ["names"]})");
  write_text(dir.path() / "raygrade", "not really a binary");
  AssignmentSpec spec = load_assignment((dir.path() / "hw.json").string());
  AssignmentBank bank = load_assignment_bank(spec);
  EXPECT_TRUE(bank.errors.empty());
  std::map<std::string, ZipEntry> files;
  for (auto& e : prairielearn_course(spec, bank.problems, bank.bank, dir.path() / "raygrade"))
    files[e.name] = e;
  return files;
}

TEST(PrairieLearnExport, WritesOneQuestionPerProblemAndTheServerFiles) {
  TempDir dir("pl-export");
  auto files = export_hostile_names(dir);
  for (const char* name : {"questions/hw/names/info.json", "questions/hw/names/question.html",
                           "questions/hw/names/server.py", "questions/hw/names/raygrade.json",
                           "serverFilesCourse/raygrade/hw/assignment.json",
                           "serverFilesCourse/raygrade/hw/bank/bank.json"}) {
    EXPECT_TRUE(files.count(name)) << name;
  }
  ASSERT_TRUE(files.count("serverFilesCourse/raygrade/raygrade"));
  EXPECT_TRUE(files["serverFilesCourse/raygrade/raygrade"].executable);
  EXPECT_EQ(files["serverFilesCourse/raygrade/raygrade"].bytes, "not really a binary");
  nlohmann::json info = nlohmann::json::parse(files["questions/hw/names/info.json"].bytes);
  EXPECT_EQ(info["type"], "v3");
  // Without per-student variants every seed gives the same problem.
  EXPECT_EQ(info["singleVariant"], true);
}

TEST(PrairieLearnExport, ObjectNamesAreTextInQuestionHtml) {
  TempDir dir("pl-names");
  std::string html = export_hostile_names(dir)["questions/hw/names/question.html"].bytes;
  EXPECT_EQ(html.find("<script>"), std::string::npos) << html;
  EXPECT_EQ(html.find("{{params.secret}}"), std::string::npos) << html;
  EXPECT_NE(html.find("<pl-answer>&lt;script&gt;alert(1)&lt;/script&gt;</pl-answer>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<pl-answer>&#123;&#123;params.secret&#125;&#125;</pl-answer>"),
            std::string::npos)
      << html;
  // The statement and the title come from generate() through mustache, which escapes them.
  EXPECT_NE(html.find("{{params.statement}}"), std::string::npos);
}

}  // namespace
}  // namespace raygrade
