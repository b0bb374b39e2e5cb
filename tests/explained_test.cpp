// No silent deduction: every part of every graded sample that earns less than its points
// says why. The samples are the bundled submissions and, for every problem of the bundled
// bank, its reference answer, the empty answer, and the reference answer with each value
// changed or each key left out in turn.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "grading/grade.h"
#include "grading/submission.h"
#include "test_util.h"

namespace raygrade {
namespace {

using nlohmann::json;

using testing::kSource;

// Every answer one change away from `answer`: each number moved (x·1.1 + 0.3), each key of an
// object left out, each array element left out.
void variants(const json& answer, const std::function<void(const json&)>& each) {
  std::function<void(json&, const std::function<void()>&)> walk =
      [&](json& node, const std::function<void()>& emit) {
        if (node.is_number()) {
          json keep = node;
          node = node.get<double>() * 1.1 + 0.3;
          emit();
          node = keep;
        } else if (node.is_object()) {
          std::vector<std::string> keys;
          for (const auto& [k, v] : node.items()) keys.push_back(k);
          for (const auto& k : keys) {
            json keep = node[k];
            node.erase(k);
            emit();
            node[k] = keep;
            walk(node[k], emit);
          }
        } else if (node.is_array()) {
          for (std::size_t i = 0; i < node.size(); ++i) {
            json keep = node;
            node.erase(i);
            emit();
            node = keep;
            walk(node[i], emit);
          }
        }
      };
  json copy = answer;
  walk(copy, [&] { each(copy); });
}

// Counts the parts checked; fails for each part below full credit without a sentence.
void expect_explained(const GradeResult& r, const std::string& where, std::size_t& checked) {
  for (const auto& p : r.parts) {
    ++checked;
    if (p.points < p.max_points || p.status != PartStatus::kRight) {
      bool said = false;
      for (const auto& f : p.feedback) said |= !f.empty();
      EXPECT_TRUE(said) << where << ": part " << p.name << " earns " << p.points << " of "
                        << p.max_points << " without a reason";
    }
  }
}

TEST(Explained, EveryDeductionInTheBankSaysWhy) {
  Bank bank = load_bank({kSource + "/problems"});
  ASSERT_TRUE(bank.errors.empty());
  std::size_t checked = 0, answers = 0;
  for (const auto& p : bank.problems) {
    Grader g(p);
    json reference = p.task->answer();
    auto grade_one = [&](const json& answer) {
      ++answers;
      try {
        expect_explained(g.grade(answer), p.id + " " + answer.dump(), checked);
      } catch (const Error&) {
        // A changed answer of the wrong JSON type is bad input, reported as such.
      }
    };
    grade_one(reference);
    grade_one(json::object());
    variants(reference, grade_one);
  }
  EXPECT_GT(answers, 1000u);
  EXPECT_GT(checked, 3000u);
}

TEST(Explained, EveryDeductionInTheSamplesSaysWhy) {
  Bank bank = load_bank({kSource + "/problems"});
  Assignment a(bank.problems, AssignmentOptions{true});
  std::size_t checked = 0, files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/submissions")) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    SubmissionGrade g = a.grade_file(entry.path().string());
    ASSERT_TRUE(g.gradable) << entry.path();
    for (const auto& r : g.results) expect_explained(r, r.problem_id, checked);
  }
  EXPECT_GE(files, 4u);
  EXPECT_GT(checked, 20u);
}

}  // namespace
}  // namespace raygrade
