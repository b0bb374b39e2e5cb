// Whitted-style tracing that builds the ray tree as data and does only the work the scene and
// the question call for: no shadow rays without lights, no reflection ray from a surface that
// does not reflect, no refraction ray from one that is opaque, no shading when only the hit
// is asked.
#pragma once

#include <string>
#include <vector>

#include "problems/problem.h"
#include "scenes/media.h"
#include "scenes/optics.h"
#include "scenes/scene.h"

namespace raygrade {

// The most ray nodes one tree may hold. max_depth 16 alone allows 65,535 hit nodes; a tree of
// thousands of nodes is no exercise, and its worked solution would run to hundreds of
// megabytes. Past this, no more secondary rays are spawned and the nodes that stop say so.
constexpr int kMaxTreeNodes = 2000;

enum class RayKind { kPrimary, kReflection, kRefraction, kShadow };
const char* to_string(RayKind k);

// How much a question asks for.
enum class Ask {
  kHit,        // the primary ray's hit only: no shading, no shadow rays, no secondary rays
  kTree,       // the tree: hits, shadow rays, which Phong terms apply
  kIntensity,  // the tree and every node's intensity
  kMedia,      // the boundaries along the primary ray's line: n1 and n2 at each, no shading
};

// Whether the question shades the hit points (and so casts shadow and secondary rays).
inline bool shades(Ask a) { return a == Ask::kTree || a == Ask::kIntensity; }

enum class LightStatus {
  kVisible,      // the shadow ray reaches the light
  kBlocked,      // an object lies between the point and the light
  kTransmitted,  // only transparent objects lie between (transparent_shadows "transmit")
  kBehind,       // the surface faces away from the light: self-shadowed, no shadow ray cast
};
const char* to_string(LightStatus s);

// One light seen from one hit point: its shadow ray and the Phong terms it gives.
struct ShadowCheck {
  int light = -1;
  std::string light_name;
  LightStatus status = LightStatus::kVisible;
  Vec3d l{};       // unit direction to the light
  Vec3d normal{};  // the normal on the light's side used for shading (see lit_normal)
  Ray ray;         // the shadow ray as cast (offset origin; a point light sits at t = 1)
  bool cast = false;
  std::vector<int> blockers;  // objects between the point and the light, nearest first
  // When the surface faces away (kBehind) no shadow ray is needed, but a student may cast one:
  // the other objects it would meet, nearest first (the point's own object left out).
  std::vector<int> behind_blockers;
  double transmission = 1;  // the fraction of the light's intensity that arrives
  PhongLight phong;         // filled when the intensity is asked and the light arrives

  bool reaches() const {
    return status == LightStatus::kVisible || status == LightStatus::kTransmitted;
  }
};

struct TreeNode {
  int index = 0;
  int parent = -1;
  RayKind kind = RayKind::kPrimary;
  int depth = 1;      // generation: the primary ray is 1
  std::string path;   // "P", "P.R", "P.T.R": stable identity for grading and drawing
  std::string label;  // "I1" for hit nodes (or the problem's own label); the path otherwise
  Ray ray;            // as cast: the origin is moved off the surface it leaves
  Vec3d from{};       // where it starts: the eye or the parent's hit point
  double offset = 0;  // how far the origin was moved off the surface
  double weight = 1;  // k_r or k_t of the parent (1 for the primary ray)
  bool total_internal_reflection = false;  // this reflection ray replaces a refraction ray

  bool hit = false;
  int object = -1;
  double t = 0;
  Vec3d point{};
  Vec3d normal{};         // the object's normal (outward for solids), world space
  Vec3d facing_normal{};  // the normal turned to face the incoming ray
  bool inside = false;    // the ray arrives from inside a solid
  Vec3d point_error{};

  bool shaded = false;  // Phong terms were decided (false when only the hit is asked)
  std::vector<ShadowCheck> lights;
  bool diffuse = false, specular = false;  // the terms that apply (ambient always applies)

  int reflection = -1, refraction = -1;  // children, or -1
  std::vector<std::string> notes;        // why a secondary ray was not cast, and other remarks
  Refraction refraction_math;            // when a refraction was attempted
  double n1 = 1, n2 = 1;
  std::vector<int> media;         // the media the ray travels in (objects, innermost last)
  std::optional<double> fresnel;  // the reflectance F, when the material mixes by a Fresnel model

  // Intensities (when asked): local = ambient + Σ lights; total = local + k_r·I_r + k_t·I_t.
  double ambient_term = 0, local = 0, reflected = 0, transmitted = 0, intensity = 0;
};

struct RayCounts {
  int primary = 0, reflection = 0, refraction = 0, shadow = 0;
  int total() const { return primary + reflection + refraction + shadow; }
};

// One effect of Whitted's model and whether it was simulated, with the reason.
struct Effect {
  std::string name;  // "shading", "shadow rays", "reflection", "refraction", "intensity"
  bool simulated = false;
  std::string reason;
  int rays = -1;  // for the kinds of ray that are cast when simulated: how many; else -1
};

struct RayTree {
  Ask ask = Ask::kTree;
  std::vector<TreeNode> nodes;  // nodes[0] is the primary ray; parents come before children
  RayCounts counts;
  std::vector<Effect> effects;
  std::vector<Crossing> crossings;  // ask kMedia: every boundary along the primary ray's line
  // The course's reading of a point that faces away from a light whose shadow ray is blocked
  // anyway (the problem's conventions): shadow_reading() applies it.
  Conventions::FacingAway facing_away = Conventions::FacingAway::kEither;

  const TreeNode* find(std::string_view path) const;
  std::vector<int> children(int node) const;  // reflection first, then refraction
};

// The normal used for shading at a node toward a light: the facing normal for an opaque
// surface; for a transparent one, the normal on the light's side, since light passes through
// the surface (the exit point of a glass sphere is lit by a light outside it).
Vec3d lit_normal(const TreeNode& node, const Material& m, const Vec3d& l);

// Traces `primary` through the scene and builds the tree.
RayTree trace(const Scene& scene, const Ray& primary, Ask ask);

}  // namespace raygrade
