// Kind `fresnel`: the share of light a boundary reflects, by the exact Fresnel equations or by
// Schlick's approximation, with total internal reflection past the critical angle.
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"
#include "scenes/fresnel.h"

namespace raygrade {

// The kind `fresnel` (kinds/kind.h).
struct FresnelKind {
  static constexpr std::string_view kName = "fresnel";
  static constexpr std::string_view kSummary =
      "the share of light a boundary reflects: the Fresnel equations or Schlick's approximation";
  static constexpr GraderFamily kGrader = GraderFamily::kFields;
  static std::vector<std::string> keys() {
    return {"n1", "n2", "model", "angle", "direction", "normal"};
  }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

class FresnelTask final : public Task {
 public:
  // The incidence as an angle in degrees, or as a direction and a normal.
  FresnelTask(FresnelModel model, double n1, double n2, std::optional<double> angle,
              Vec3d direction, Vec3d normal)
      : model_(model), n1_(n1), n2_(n2), angle_(angle), d_(direction), n_(normal) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return FresnelKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"fresnel"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

 private:
  double cos_i() const;
  FresnelModel model_;
  double n1_, n2_;
  std::optional<double> angle_;
  Vec3d d_, n_;
};

}  // namespace raygrade
