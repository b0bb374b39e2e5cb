// Grading the kind `camera-ray`: the ray's origin and direction (any positive multiple), and
// the mistakes of the pixel convention and of the order of the cross product d × u.
#include <fmt/format.h>

#include "derivation/number_format.h"
#include "grading/kind_grader.h"
#include "grading/mistakes.h"
#include "grading/parts.h"
#include "grading/steps.h"
#include "kinds/camera_ray.h"
#include "kinds/part_names.h"

namespace raygrade {
namespace {

struct Variant {
  std::string id;
  Vec3d direction;
};

class CameraGrader final : public KindGrader {
 public:
  explicit CameraGrader(const Problem& p) : task_(dynamic_cast<const CameraRayTask&>(*p.task)) {
    context_.problem = &p;
    context_.tolerance = read_tolerance_policy(p);
    context_.points =
        read_points_policy(p, default_points(p.kind, {part_names::kRay, part_names::kSteps}));
    if (p.precision >= 0) numbers_.decimals = p.precision;
    direction_ =
        camera_ray_direction(task_.camera(), task_.pixel_x(), task_.pixel_y(), task_.convention());
    methods_ = solutions_by_method(task_);
    mistaken_ = mistaken_solutions(task_);
    // The mistakes of this kind, recomputed through the derivation with a changed formula.
    bool corner = task_.convention() == PixelConvention::kCorner;
    add_variant(corner ? "pixel-centre" : "pixel-corner",
                [corner](std::string_view step, const E& f) -> std::optional<E> {
                  if (step != "x_diff" && step != "y_diff") return std::nullopt;
                  return corner ? f + 0.5 : f - 0.5;
                });
    add_variant("cross-order", [](std::string_view step, const E& f) -> std::optional<E> {
      // not a part: the derivation's step v, the camera's up vector
      if (step != "v") return std::nullopt;
      return -f;
    });
  }

  void grade(const AnswerReader& a, GradeResult& out) const override {
    a.allow_only({part_names::kRay, part_names::kUnitDirection, part_names::kSteps});
    if (a.has(part_names::kSteps)) {
      StepsGrade s = grade_steps(context_, task_, methods_, mistaken_, a.at(part_names::kSteps));
      out.parts.push_back(s.part);
      for (auto& m : s.mistakes) out.mistakes.push_back(m);
    }
    std::optional<AnswerReader::Vector> origin, direction;
    if (a.has(part_names::kRay)) {
      AnswerReader r = a.at(part_names::kRay);
      r.allow_only({part_names::kOrigin, part_names::kDirection});
      if (r.has(part_names::kOrigin)) origin = r.at(part_names::kOrigin).vector();
      if (r.has(part_names::kDirection)) direction = r.at(part_names::kDirection).vector();
    }
    if (!direction && a.has(part_names::kUnitDirection))
      direction = a.at(part_names::kUnitDirection).vector();
    if (!direction) {
      out.parts.push_back(missing_part(context_, part_names::kRay, "No ray direction given."));
      return;
    }
    const Tolerance& tol = context_.tolerance.for_field(part_names::kRay);
    std::vector<std::string> fb;
    double credit = 0;
    if (!direction->ok) {
      fb.push_back("direction: " + direction->fault);
    } else if (length(direction->value()) == 0) {
      fb.emplace_back("A direction cannot be the zero vector.");
    } else if (NumberVerdict dv =
                   compare_part(Comparison::kDirection, direction->c, direction_, tol).verdict;
               dv.match != Match::kWrong) {
      credit = dv.match == Match::kRight ? 1 : tol.precision_credit;
      if (dv.match == Match::kInsufficientPrecision) fb.push_back("direction: " + dv.message);
    } else {
      bool named = false;
      for (const auto& v : variants_) {
        if (!same_direction(direction->value(), v.direction, tol)) continue;
        out.mistakes.push_back(make_mistake(
            v.id, part_names::kRay,
            fmt::format("your direction {} is what that gives; the ray through pixel ({}, {}) "
                        "has direction {}.",
                        format_vector(direction->value(), numbers_), format_number(task_.pixel_x()),
                        format_number(task_.pixel_y()), format_vector(direction_, numbers_))));
        credit = mistake_info(v.id).credit;
        fb.push_back(out.mistakes.back().message);
        named = true;
        break;
      }
      if (!named) {
        fb.push_back(fmt::format("The direction is {} (or any positive multiple).",
                                 format_vector(direction_, numbers_)));
      }
    }
    if (origin) {
      if (!origin->ok) {
        fb.push_back("origin: " + origin->fault);
        credit = 0;
      } else if (compare_vector(origin->c, task_.camera().eye, tol).match != Match::kRight) {
        fb.push_back(fmt::format("The ray starts at the eye {}.",
                                 format_vector(task_.camera().eye, numbers_)));
        credit *= 0.5;
      }
    }
    if (credit >= 1 && fb.empty()) fb.emplace_back("Right.");
    out.parts.push_back(make_part(context_, part_names::kRay, credit, std::move(fb)));
  }

 private:
  template <typename F>
  void add_variant(std::string id, F rewrite) {
    Overrides o;
    o.formula = rewrite;
    auto parts = task_.derive("", &o);
    const Step* dr = parts.empty() ? nullptr : parts.front().derivation.find("d_r");
    if (dr && dr->value.is_vector() && length(dr->value.vector - direction_) > 0) {
      variants_.push_back({std::move(id), dr->value.vector});
    }
  }

  // Directions compared as unit vectors: any positive multiple names the same ray.
  static bool same_direction(const Vec3d& a, const Vec3d& b, const Tolerance& t) {
    Vec3d ua = normalized(a), ub = normalized(b);
    StudentNumber s[3];
    for (int k = 0; k < 3; ++k) s[k] = {ua[k], {}, ""};
    return compare_vector(s, ub, t).match == Match::kRight;
  }

  const CameraRayTask& task_;
  Vec3d direction_;
  std::vector<Variant> variants_;
  std::vector<MethodDerivation> methods_;
  std::vector<MistakenSolution> mistaken_;
  NumberFormat numbers_;
};

}  // namespace

std::shared_ptr<const KindGrader> make_camera_grader(const Problem& p) {
  return std::make_shared<CameraGrader>(p);
}

}  // namespace raygrade
