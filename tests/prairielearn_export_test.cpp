// The PrairieLearn questions of an assignment: their layout, and text from the bank kept inert
// in question.html (tests/prairielearn_export.py drives their server.py).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "assignments/platforms/prairielearn.h"
#include "problems/kind.h"
#include "run_binary.h"

namespace raygrade {
namespace {

using testing::TempDir;
using testing::write_text;

// An assignment whose id climbs out of its folder, of one first-hit problem whose object names
// carry markup and mustache tags.
std::map<std::string, ZipEntry> export_hostile_names(const TempDir& dir) {
  write_text(dir.path() / "bank.json", R"({"problems": [{
    "id": "names", "kind": "first-hit", "title": "Which is hit first?",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "objects": [
      {"name": "<script>alert(1)</script>", "type": "sphere", "center": [5, 0, 0], "radius": 1},
      {"name": "{{params.secret}}", "type": "sphere", "center": [9, 0, 0], "radius": 1}]}]})");
  write_text(dir.path() / "hw.json",
             R"({"assignment": "../hw", "bank": "bank.json", "problems": ["names"]})");
  write_text(dir.path() / "raygrade", "not really a binary");
  AssignmentSpec spec = load_assignment((dir.path() / "hw.json").string());
  AssignmentBank bank = load_assignment_bank(spec);
  EXPECT_TRUE(bank.errors.empty());
  std::map<std::string, ZipEntry> files;
  for (auto& e : prairielearn_course(spec, bank.problems, bank.bank, dir.path() / "raygrade"))
    files[e.name] = e;
  return files;
}

// Every problem of the bank as a PrairieLearn question: none asks for JSON (no multi-line box,
// no input that says JSON), every input is one server.py reads, and every kind is there.
TEST(PrairieLearnExport, NoQuestionOfAnyKindAsksForJson) {
  TempDir dir("pl-every-kind");
  std::string bank_dir = std::string(RAYGRADE_SOURCE_DIR) + "/problems";
  Bank bundled = load_bank({bank_dir});
  nlohmann::json spec_json = {{"assignment", "every-kind"}, {"bank", bank_dir}};
  for (const auto& p : bundled.problems) spec_json["problems"].push_back(p.id);
  write_text(dir.path() / "all.json", spec_json.dump());
  write_text(dir.path() / "raygrade", "not really a binary");
  AssignmentSpec spec = load_assignment((dir.path() / "all.json").string());
  AssignmentBank bank = load_assignment_bank(spec);
  ASSERT_TRUE(bank.errors.empty());
  // The inputs server.py reads: a value's word of the table of field types, or a ray tree's
  // blockers.
  const std::set<std::string> read = {"typed-number", "typed-three", "typed-formula", "flag",
                                      "one-of",       "some-of",     "names"};
  std::set<std::string> kinds;
  int questions = 0;
  for (auto& e : prairielearn_course(spec, bank.problems, bank.bank, dir.path() / "raygrade")) {
    if (e.name.ends_with("/question.html")) {
      ++questions;
      EXPECT_EQ(e.bytes.find("JSON"), std::string::npos) << e.name;
      EXPECT_EQ(e.bytes.find("multiline"), std::string::npos) << e.name;
      EXPECT_EQ(e.bytes.find("textarea"), std::string::npos) << e.name;
    } else if (e.name.ends_with("/info.json")) {
      nlohmann::json info = nlohmann::json::parse(e.bytes);
      kinds.insert(info["tags"].back().get<std::string>());
    } else if (e.name.ends_with("/raygrade.json")) {
      nlohmann::json q = nlohmann::json::parse(e.bytes);
      EXPECT_FALSE(q["inputs"].empty()) << e.name;
      for (const auto& in : q["inputs"]) {
        EXPECT_TRUE(read.count(in["type"].get<std::string>())) << e.name << ": " << in.dump();
      }
    }
  }
  EXPECT_EQ(questions, static_cast<int>(bundled.problems.size()));
  for (const auto& entry : kind_table()) EXPECT_TRUE(kinds.count(std::string(entry.name)));
}

TEST(PrairieLearnExport, WritesOneQuestionPerProblemAndTheServerFiles) {
  TempDir dir("pl-export");
  auto files = export_hostile_names(dir);
  for (const char* name :
       {"questions/_._hw/names/info.json", "questions/_._hw/names/question.html",
        "questions/_._hw/names/server.py", "questions/_._hw/names/raygrade.json",
        "serverFilesCourse/raygrade/_._hw/assignment.json",
        "serverFilesCourse/raygrade/_._hw/bank/bank.json", "serverFilesCourse/raygrade/raygrade"}) {
    EXPECT_TRUE(files.count(name)) << name;
  }
  EXPECT_EQ(files.size(), 7u);
  nlohmann::json question =
      nlohmann::json::parse(files["questions/_._hw/names/raygrade.json"].bytes);
  EXPECT_EQ(question["assignment"], "_._hw");  // server.py's folder under serverFilesCourse
  EXPECT_EQ(question["problem"], "names");
  ASSERT_TRUE(files.count("serverFilesCourse/raygrade/raygrade"));
  EXPECT_TRUE(files["serverFilesCourse/raygrade/raygrade"].executable);
  EXPECT_EQ(files["serverFilesCourse/raygrade/raygrade"].bytes, "not really a binary");
  nlohmann::json info = nlohmann::json::parse(files["questions/_._hw/names/info.json"].bytes);
  EXPECT_EQ(info["type"], "v3");
  // Without per-student variants every seed gives the same problem.
  EXPECT_EQ(info["singleVariant"], true);
}

TEST(PrairieLearnExport, ObjectNamesAreTextInQuestionHtml) {
  TempDir dir("pl-names");
  std::string html = export_hostile_names(dir)["questions/_._hw/names/question.html"].bytes;
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

// The example assignment's questions as students and instructors read them: titles in the
// instructor's list name the parameters, not one student's numbers (the bank writes "A ray
// meets the plane y = {h}" and "The camera ray through pixel ({x}, {y})"); inputs take the
// line's width whatever their label, with no popover about PrairieLearn's own grader; and a
// right part says nothing after its status.
TEST(PrairieLearnExport, WhatStudentsAndInstructorsRead) {
  TempDir dir("pl-read");
  write_text(dir.path() / "raygrade", "not really a binary");
  AssignmentSpec spec =
      load_assignment(std::string(RAYGRADE_SOURCE_DIR) + "/assignments/homework-rays.json");
  AssignmentBank bank = load_assignment_bank(spec);
  ASSERT_TRUE(bank.errors.empty());
  std::map<std::string, ZipEntry> files;
  for (auto& e : prairielearn_course(spec, bank.problems, bank.bank, dir.path() / "raygrade"))
    files[e.name] = e;
  auto title = [&](const std::string& q) {
    return nlohmann::json::parse(files["questions/homework-rays/" + q + "/info.json"].bytes)
        .at("title")
        .get<std::string>();
  };
  EXPECT_EQ(title("variant-plane"), "A ray meets the plane y = h");
  EXPECT_EQ(title("variant-camera-ray"), "The camera ray through pixel (x, y)");
  std::string html = files["questions/homework-rays/variant-sphere/question.html"].bytes;
  EXPECT_NE(html.find("display=\"block\""), std::string::npos) << html;
  EXPECT_NE(html.find("show-help-text=\"false\""), std::string::npos) << html;
  EXPECT_EQ(html.find("size=\"40\""), std::string::npos) << html;
  EXPECT_NE(html.find("({{status}}){{#feedback}}: {{feedback}}{{/feedback}}"), std::string::npos)
      << html;
}

}  // namespace
}  // namespace raygrade
