// Kind `normal`: the unit normal of an object at a given point of its surface, with no ray.
// A transformed object's point goes into object space (P' = M⁻¹P), the primitive's normal is
// taken there and comes back by the inverse transpose. A point off the surface is an error
// that says how far off it is.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "problems/problem.h"
#include "shapes/shape.h"
#include "shapes/transform.h"

namespace raygrade {

// A point within this fraction of the object's size (at least 1) of its surface is on it: a
// coordinate printed to four decimals, as exercises print √2/2 = 0.7071, is off by at most
// 5e-5. The same distance tells a rim or an edge (two parts of the surface as near) apart.
constexpr double kOnSurfaceRelative = 1e-4;

// The surface part nearest to an object-space point, with its outward normal there.
struct SurfacePoint {
  Vec3d nearest;      // the nearest point of that part of the surface
  Vec3d normal;       // the outward (or by vertex order, or as given) normal, not normalized
  std::string part;   // "side", "top cap", "face x = 1"; empty for one-part surfaces
  std::string other;  // a second part as near (a rim or an edge): the normal is not defined
};

// The primitives the normal kind takes.
inline constexpr std::array<std::string_view, 6> kNormalKindTypes = {
    "sphere", "plane", "triangle", "polygon", "cylinder", "box"};

// The part of `primitive`'s surface nearest to `p` (object space), read from its parameters;
// nothing for a primitive the normal kind does not take.
std::optional<SurfacePoint> nearest_surface(const Shape& primitive, const Vec3d& p);

class NormalTask final : public Task {
 public:
  NormalTask(std::unique_ptr<Shape> object, Vec3d point)
      : object_(std::move(object)), point_(point) {}
  static std::unique_ptr<Task> read(const Cursor& problem);

  std::string_view kind() const override { return "normal"; }
  nlohmann::json answer() const override;
  std::vector<std::string> methods() const override { return {"gradient"}; }
  std::vector<SolutionPart> derive(std::string_view method,
                                   const Overrides* overrides) const override;
  Sketch sketch() const override;

  // A transformed object's normal taken to the world by its matrix A instead of (A⁻¹)ᵀ, when
  // the two differ (an uneven scale): the normal-not-inverse-transpose mistake.
  std::optional<Vec3d> normal_by_matrix() const;
  // Whether the object is closed (its normal points out of it): a sphere, cylinder or box.
  bool solid() const;

 private:
  const Shape& primitive() const;
  const Transform* transform() const;
  Vec3d world_normal() const;

  std::unique_ptr<Shape> object_;
  Vec3d point_;
};

}  // namespace raygrade
