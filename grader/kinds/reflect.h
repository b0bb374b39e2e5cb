// Kind `reflect`: the mirror direction of a ray at a surface, r = d − 2(d·n̂)n̂.
#pragma once

#include "problems/problem.h"

namespace raygrade {

class ReflectTask final : public Task {
 public:
  ReflectTask(Vec3d direction, Vec3d normal) : d_(direction), n_(normal) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return "reflect"; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"vector"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;

 private:
  Vec3d d_, n_;
};

}  // namespace raygrade
