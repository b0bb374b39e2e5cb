// Kind `refract`: Snell's law n1 sin θi = n2 sin θt at a surface, in vector form, with total
// internal reflection beyond the critical angle.
#pragma once

#include "problems/problem.h"

namespace raygrade {

class RefractTask final : public Task {
 public:
  RefractTask(Vec3d direction, Vec3d normal, double n1, double n2)
      : d_(direction), n_(normal), n1_(n1), n2_(n2) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return "refract"; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"vector"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;

 private:
  Vec3d facing_normal() const;  // unit, against d
  Vec3d d_, n_;
  double n1_, n2_;
};

}  // namespace raygrade
