// Grading kinds without a grader of their own: the answer is compared with the reference
// answer leaf by leaf (numbers by tolerance, strings exactly, arrays in order).
#include <fmt/format.h>

#include "grading/kind_grader.h"

namespace raygrade {
namespace {

class GenericGrader final : public KindGrader {
 public:
  explicit GenericGrader(const Problem& p) : reference_(p.task->answer()) {
    context_.problem = &p;
    context_.tolerance = read_tolerance_policy(p);
    context_.points = read_points_policy(p, {{"answer", 1}});
  }

  void grade(const AnswerReader& a, GradeResult& out) const override {
    int total = 0, right = 0;
    std::vector<std::string> fb;
    compare(a, reference_, total, right, fb);
    if (total == right && fb.empty()) fb.push_back("Right.");
    out.parts.push_back(make_part(context_, "answer", total ? double(right) / total : 1, fb));
  }

 private:
  void compare(const AnswerReader& s, const nlohmann::json& r, int& total, int& right,
               std::vector<std::string>& fb) const {
    if (r.is_object()) {
      for (const auto& [key, v] : r.items()) {
        if (s.has(key)) {
          compare(s.at(key), v, total, right, fb);
        } else {
          total += leaves(v);
        }
      }
    } else if (r.is_array()) {
      std::size_t n = s.json().is_array() ? s.json().size() : 0;
      for (std::size_t i = 0; i < r.size(); ++i) {
        if (i < n) {
          compare(s.items()[i], r[i], total, right, fb);
        } else {
          total += leaves(r[i]);
        }
      }
    } else if (r.is_number()) {
      ++total;
      if (s.json().is_number() || s.json().is_string()) {
        auto n = s.number();
        double ref = r.get<double>();
        if (n.value &&
            compare_number(*n.value, ref, ref, context_.tolerance.base).match == Match::kRight) {
          ++right;
        } else if (!n.value) {
          fb.push_back(fmt::format("{}: {}", s.path(), n.fault));
        }
      }
    } else {
      ++total;
      if (s.json() == r) ++right;
    }
  }

  static int leaves(const nlohmann::json& v) {
    if (!v.is_structured()) return 1;
    int n = 0;
    for (const auto& x : v) n += leaves(x);
    return n;
  }

  nlohmann::json reference_;
};

}  // namespace

std::shared_ptr<const KindGrader> make_generic_grader(const Problem& p) {
  return std::make_shared<GenericGrader>(p);
}

}  // namespace raygrade
