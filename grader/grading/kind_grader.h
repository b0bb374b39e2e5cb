// The grading of one kind of problem, and what every kind's grader shares: the problem's
// tolerances and points, and helpers that fill in parts.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "grading/answer_reader.h"
#include "grading/result.h"
#include "grading/tolerance.h"
#include "problems/problem.h"

namespace raygrade {

// When a later part is wrong but follows correctly from the student's own wrong earlier
// value, it earns this fraction of its points: the mistake costs where it was made, and
// consistent work after it still counts, as a human grader marks. A problem may set
// `points.carried_forward` (1 when its steps carry their own points).
constexpr double kCarriedForwardCredit = 0.5;

// Points per part. A problem's `points` is a number (the problem's total, shared in the
// proportions of the kind's defaults) or an object naming parts.
struct PointsPolicy {
  std::vector<std::pair<std::string, double>> parts;
  double carried_forward = kCarriedForwardCredit;
  double of(std::string_view part) const;
  double total() const;
};

PointsPolicy read_points_policy(const Problem& p,
                                const std::vector<std::pair<std::string, double>>& defaults);

struct GradingContext {
  const Problem* problem = nullptr;
  TolerancePolicy tolerance;
  PointsPolicy points;
};

class KindGrader {
 public:
  virtual ~KindGrader() = default;
  // Fills `out.parts` and `out.mistakes` from the answer.
  virtual void grade(const AnswerReader& answer, GradeResult& out) const = 0;
  const GradingContext& context() const { return context_; }

 protected:
  GradingContext context_;
};

// The grader for a problem's kind.
std::shared_ptr<const KindGrader> make_kind_grader(const Problem& p);

std::shared_ptr<const KindGrader> make_hits_grader(const Problem& p);      // intersect, first-hit
std::shared_ptr<const KindGrader> make_camera_grader(const Problem& p);    // camera-ray
std::shared_ptr<const KindGrader> make_formula_grader(const Problem& p);   // derive
std::shared_ptr<const KindGrader> make_ray_tree_grader(const Problem& p);  // ray-tree
std::shared_ptr<const KindGrader> make_fields_grader(const Problem& p);  // reflect, refract, shade

// A part with its points from `credit` (0 to 1) and its status from the credit. A part below
// full credit must say why: without feedback it is a bug of the grader (std::logic_error).
PartResult make_part(const GradingContext& c, const std::string& name, double credit,
                     std::vector<std::string> feedback);
PartResult missing_part(const GradingContext& c, const std::string& name, std::string why = "");

}  // namespace raygrade
