// Kind `normal`: the unit normal of an object at a given point of its surface, with no ray.
// A transformed object's point goes into object space (P' = M⁻¹P), the primitive's normal is
// taken there and comes back by the inverse transpose. A point off the surface is an error
// that says how far off it is.
#pragma once

#include <optional>
#include <string_view>

#include "problems/kind.h"
#include "problems/problem.h"
#include "shapes/shape.h"
#include "shapes/surface_point.h"
#include "shapes/transform.h"

namespace raygrade {

// The kind `normal` (kinds/kind.h).
struct NormalKind {
  static constexpr std::string_view kName = "normal";
  static constexpr std::string_view kSummary =
      "the unit normal of an object at a point of its surface";
  static constexpr GraderFamily kGrader = GraderFamily::kFields;
  static std::vector<std::string> keys() { return {"object", "point"}; }
  static std::unique_ptr<Task> read(const Cursor& problem);
  static std::vector<PartSpec> parts();
  static nlohmann::json answer_form(const Problem& p);
  static std::string_view schema();
};

// The part of `primitive`'s surface nearest to `p` (object space), with its outward normal
// there: the primitive's own nearest_surface (in shapes/<name>.cpp).
SurfacePoint nearest_surface(const Shape& primitive, const Vec3d& p);

class NormalTask final : public Task {
 public:
  NormalTask(std::unique_ptr<Shape> object, Vec3d point)
      : object_(std::move(object)), point_(point) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return NormalKind::kName; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"gradient"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;
  std::optional<SceneGivens> scene_givens() const override;

  // A transformed object's normal taken to the world by its matrix A instead of (A⁻¹)ᵀ, when
  // the two differ (an uneven scale): the normal-not-inverse-transpose mistake.
  std::optional<Vec3d> normal_by_matrix() const;
  // Whether the object's normal points out of it, so that the opposite one is the named mistake
  // inward-normal: its primitive's normal rule says so (a sphere, cylinder, box, cone, capsule).
  bool solid() const;

 private:
  const Shape& primitive() const;
  const Transform* transform() const;
  Vec3d world_normal() const;

  std::unique_ptr<Shape> object_;
  Vec3d point_;
};

}  // namespace raygrade
