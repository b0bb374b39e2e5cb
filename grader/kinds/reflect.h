// Kind `reflect`: the mirror direction of a ray at a surface, r = d − 2(d·n̂)n̂.
#pragma once

#include "problems/kind.h"
#include "problems/problem.h"

namespace raygrade {

// The kind `reflect` (kinds/kind.h).
struct ReflectKind {
  static constexpr std::string_view kName = "reflect";
  static constexpr std::string_view kSummary = "the mirror direction of a ray at a surface";
  static constexpr GraderFamily kGrader = GraderFamily::kFields;
  static std::vector<std::string> keys() { return {"direction", "normal"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

class ReflectTask final : public Task {
 public:
  ReflectTask(Vec3d direction, Vec3d normal) : d_(direction), n_(normal) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return ReflectKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"vector"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

 private:
  Vec3d d_, n_;
};

}  // namespace raygrade
