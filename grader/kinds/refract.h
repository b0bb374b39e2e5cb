// Kind `refract`: Snell's law n1 sin θi = n2 sin θt at a surface, in vector form, with total
// internal reflection beyond the critical angle.
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"

namespace raygrade {

// The kind `refract` (kinds/kind.h).
struct RefractKind {
  static constexpr std::string_view kName = "refract";
  static constexpr std::string_view kSummary =
      "Snell's law at a surface, with total internal reflection";
  static constexpr GraderFamily kGrader = GraderFamily::kFields;
  static std::vector<std::string> keys() { return {"direction", "normal", "n1", "n2"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

class RefractTask final : public Task {
 public:
  RefractTask(Vec3d direction, Vec3d normal, double n1, double n2)
      : d_(direction), n_(normal), n1_(n1), n2_(n2) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return RefractKind::kName; }
  nlohmann::json answer() const override;
  // "vector": t = η·d̂ + (η·cos θi − √k)·n̂; "angles": Snell's law on the angles, sin θt =
  // η·sin θi, and t from θt (not for a ray along the normal, nor past the critical angle).
  // The angles' method needs a refracted ray: under total internal reflection, or along the
  // normal, the vector method alone works the problem.
  std::vector<std::string> methods() const override;
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

 private:
  Vec3d facing_normal() const;  // unit, against d
  std::vector<SolutionPart> derive_angles(const Overrides* overrides) const;
  Vec3d d_, n_;
  double n1_, n2_;
};

}  // namespace raygrade
