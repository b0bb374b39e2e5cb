// Outputs: Gradescope's and PrairieLearn's results.json against their published field lists
// (names and JSON types), the CSV gradebook and the HTML page's escaping.
#include <gtest/gtest.h>

#include "assignments/platforms/gradescope.h"
#include "assignments/platforms/prairielearn.h"
#include "grading/outputs.h"
#include "test_util.h"

namespace raygrade {
namespace {

using nlohmann::json;

SubmissionGrade sample(const std::string& student, const char* answer) {
  static Problem p = testing::problem(R"({"id": "s1", "title": "Sphere <1>",
    "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]},
    "object": {"type": "sphere", "center": [2, 0, 0], "radius": 1}})");
  SubmissionGrade g;
  g.file = student + ".json";
  g.student = student;
  g.results.push_back(grade_answer(p, json::parse(answer)));
  g.score = g.results[0].score;
  g.max_score = g.results[0].max_score;
  return g;
}

SubmissionGrade rejected() {
  SubmissionGrade g;
  g.file = "bad.json";
  g.student = "bad";
  g.gradable = false;
  g.fault =
      Diagnostic{"bad.json", "/answers", 3, 5, Severity::kError, "expected an object", "type"};
  return g;
}

// Gradescope autograder results.json: top-level score (number), execution_time (number),
// output (string), visibility (string), tests (array); each test name (string), score and
// max_score (numbers), status ("passed" or "failed"), output (string), visibility ("hidden",
// "after_due_date", "after_published" or "visible").
TEST(Lms, GradescopeFieldList) {
  for (const SubmissionGrade& g : {sample("ada", R"({"hits": [{"t": 1}, {"t": 3}]})"),
                                   sample("bob", R"({"hits": [{"t": 1}]})"), rejected()}) {
    json j = gradescope_json(g, 0.25);
    EXPECT_TRUE(j.at("score").is_number());
    EXPECT_TRUE(j.at("execution_time").is_number());
    EXPECT_TRUE(j.at("output").is_string());
    EXPECT_TRUE(j.at("visibility").is_string());
    ASSERT_TRUE(j.at("tests").is_array());
    for (const auto& t : j.at("tests")) {
      EXPECT_TRUE(t.at("name").is_string());
      EXPECT_TRUE(t.at("score").is_number());
      EXPECT_TRUE(t.at("max_score").is_number());
      EXPECT_TRUE(t.at("output").is_string());
      std::string status = t.at("status");
      EXPECT_TRUE(status == "passed" || status == "failed");
      std::string vis = t.at("visibility");
      EXPECT_TRUE(vis == "hidden" || vis == "after_due_date" || vis == "after_published" ||
                  vis == "visible");
      for (const auto& [key, v] : t.items()) {
        static const std::vector<std::string> known = {
            "score",  "max_score",     "status", "name",       "name_format", "number",
            "output", "output_format", "tags",   "visibility", "extra_data"};
        EXPECT_NE(std::find(known.begin(), known.end(), key), known.end()) << key;
      }
    }
  }
  json right = gradescope_json(sample("ada", R"({"hits": [{"t": 1}, {"t": 3}]})"), 0.1);
  EXPECT_DOUBLE_EQ(right["score"].get<double>(), 3 - 1);  // t 2 of 2, point missing (1)
  EXPECT_EQ(right["tests"][0]["status"], "failed");
  EXPECT_EQ(right["tests"][0]["name"], "s1: Sphere <1>");
}

// PrairieLearn external grader results.json: gradable (boolean), score (number in [0, 1]),
// message (string), output (string), tests (array); each test name (string), description
// (string), points and max_points (numbers), message and output (strings).
TEST(Lms, PrairieLearnFieldList) {
  for (const SubmissionGrade& g : {sample("ada", R"({"hits": [{"t": 1, "point": [1,0,0]},
      {"t": 3, "point": [3,0,0]}]})"),
                                   sample("bob", R"({"hits": []})"), rejected()}) {
    json j = prairielearn_json(g);
    EXPECT_TRUE(j.at("gradable").is_boolean());
    ASSERT_TRUE(j.at("score").is_number());
    double s = j["score"];
    EXPECT_GE(s, 0);
    EXPECT_LE(s, 1);
    EXPECT_TRUE(j.at("message").is_string());
    EXPECT_TRUE(j.at("output").is_string());
    ASSERT_TRUE(j.at("tests").is_array());
    for (const auto& t : j.at("tests")) {
      EXPECT_TRUE(t.at("name").is_string());
      EXPECT_TRUE(t.at("description").is_string());
      EXPECT_TRUE(t.at("points").is_number());
      EXPECT_TRUE(t.at("max_points").is_number());
      EXPECT_TRUE(t.at("message").is_string());
      EXPECT_TRUE(t.at("output").is_string());
    }
  }
  EXPECT_FALSE(prairielearn_json(rejected())["gradable"].get<bool>());
  json full = prairielearn_json(sample("ada", R"({"hits": [{"t": 1, "point": [1,0,0]},
      {"t": 3, "point": [3,0,0]}]})"));
  EXPECT_DOUBLE_EQ(full["score"].get<double>(), 1);
}

TEST(Lms, GradebookRowsAndEscaping) {
  std::string csv = gradebook_csv(
      {sample("=cmd|' /C calc'!A0", R"({"hits": [{"t": 1}]})"), rejected()}, {"s1", "other"});
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "student,id,email,file,s1,other,total,max,status");
  EXPECT_NE(csv.find("'=cmd|"), std::string::npos);  // a formula neutralised
  EXPECT_EQ(csv.find("\n=cmd"), std::string::npos);
  EXPECT_NE(csv.find(",1,,1,3,graded"), std::string::npos);
  EXPECT_NE(csv.find("rejected: bad.json:3:5"), std::string::npos);
}

TEST(Lms, DirectJsonTextMatchesTheJsonValue) {
  SubmissionGrade g = sample("a \"quoted\"\tname", R"({"hits": [{"t": "1/0"}, {"t": 3}]})");
  std::string text;
  append_result_json(text, g.results[0]);
  EXPECT_EQ(json::parse(text), result_json(g.results[0]));
}

TEST(Lms, HtmlEscapesEverything) {
  std::string html = feedback_html(sample("<script>alert(1)</script>", R"({"hits": [{"t": 1}]})"));
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;"), std::string::npos);
  EXPECT_NE(html.find("Sphere &lt;1&gt;"), std::string::npos);
}

}  // namespace
}  // namespace raygrade
