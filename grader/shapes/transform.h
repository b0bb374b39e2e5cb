// Transform: an object's placement in the world (translate, rotate, scale), and taking rays
// into the object's space and hits back out, as courses teach.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "json/cursor.h"
#include "shapes/ray.h"

namespace raygrade {

// p_world = A·p_object + b, with A a 3×3 matrix (rows) and b a translation.
struct Affine {
  std::array<Vec3d, 3> rows{Vec3d{1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, 0, 1}};
  Vec3d translation{};

  Vec3d linear(const Vec3d& v) const { return {dot(rows[0], v), dot(rows[1], v), dot(rows[2], v)}; }
  Vec3d point(const Vec3d& p) const { return linear(p) + translation; }
  Affine then(const Affine& next) const;  // next ∘ this: this applied first
  Affine inverse() const;                 // the matrix must be invertible
  Affine transpose_linear() const;        // Aᵀ, no translation
  double determinant() const;
  bool is_identity() const;
};

// One step of a transform as written: {"translate": v}, {"scale": v or s},
// {"rotate": {"axis": v, "degrees": a}}, {"matrix": [[a, b, c], [d, e, f], [g, h, i]]} (a
// linear map by its rows).
struct TransformStep {
  std::string op;  // "translate", "scale", "rotate", "matrix"
  Vec3d vector{};  // the translation, the scale factors, or the rotation axis
  double degrees = 0;
  std::array<Vec3d, 3> rows{};  // the matrix's rows
};

// An object's transform: the steps in the order they apply to the object (the first listed is
// applied first), the object-to-world matrix M and its inverse.
struct Transform {
  std::vector<TransformStep> steps;
  Affine to_world;
  Affine to_object;
  Affine normal_to_world;  // (A⁻¹)ᵀ: normals go back by the inverse transpose

  bool identity() const { return steps.empty(); }
  // The ray in object space: o' = M⁻¹o, d' = A⁻¹d (not normalized, so t is unchanged).
  Ray ray_to_object(const Ray& world) const;
  // A unit object-space normal back in the world, normalized.
  Vec3d normal_to_world_unit(const Vec3d& n) const;
  // An object-space intersection of ray_to_object(world) back in the world: t kept, each point
  // on the world ray at that t, each normal by the inverse transpose.
  Intersection hits_to_world(const Ray& world, Intersection object_hits) const;
  nlohmann::json to_json() const;
};

// A transform whose linear part, each row scaled to unit length, has |det| at most this is
// singular up to rounding: its rows lie in one plane to within about 1e-12 radians, and A⁻¹
// would have entries beyond any exercise's digits.
constexpr double kSingularRelative = 1e-12;

// Reads a `transform`: a list of steps. Zero scale factors, a zero rotation axis, a singular
// matrix, a singular product of the steps and unknown steps are errors naming their path.
Transform read_transform(const Cursor& list);

// The steps as a formula in words: "translate (1, 0, 0) · rotate 30° about (0, 1, 0)".
std::string describe_transform(const Transform& t);

}  // namespace raygrade
