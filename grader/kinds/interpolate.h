// Kind `interpolate`: the smooth normal (and texture coordinate) at a point of a triangle, from
// its vertices' normals (and coordinates) weighted by the point's barycentric weights, as Phong
// shading interpolates them: n̂ = (w_a·N_a + w_b·N_b + w_c·N_c) / |…|, u = w_a·u_a + w_b·u_b +
// w_c·u_c. The point is given (a ray's hit found before); one off the triangle's plane, or
// outside it, is an error that says how far; so are vertex normals that blend to no direction
// there (they cancel, or one is too short to be made unit).
#pragma once

#include <array>
#include <optional>

#include "problems/kind.h"
#include "problems/problem.h"

namespace raygrade {

// The kind `interpolate` (kinds/kind.h).
struct InterpolateKind {
  static constexpr std::string_view kName = "interpolate";
  static constexpr std::string_view kSummary =
      "the smooth normal and texture coordinate at a triangle's point, from its vertices' by "
      "barycentric weights (Phong shading)";
  static constexpr GraderFamily kGrader = GraderFamily::kFields;
  static std::vector<std::string> keys() { return {"vertices", "normals", "texcoords", "point"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

class InterpolateTask final : public Task {
 public:
  using Texcoord = std::array<double, 2>;
  InterpolateTask(std::array<Vec3d, 3> vertices, std::array<Vec3d, 3> normals,
                  std::optional<std::array<Texcoord, 3>> texcoords, Vec3d point);
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return InterpolateKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"barycentric"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

  // The point's weights (w_a, w_b, w_c): P = w_a·A + w_b·B + w_c·C, summing to 1.
  const std::array<double, 3>& weights() const { return w_; }

 private:
  std::array<Vec3d, 3> v_, n_;
  std::optional<std::array<Texcoord, 3>> uv_;
  Vec3d p_;
  std::array<double, 3> w_{};

  // w_a·N̂_a + w_b·N̂_b + w_c·N̂_c, the unit vertex normals blended, before it is made unit.
  Vec3d blend() const;
};

}  // namespace raygrade
