// Scene: objects of every primitive with materials and transforms, lights, and the settings
// of Whitted-style tracing (maximum depth, shadows through transparent objects).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "json/cursor.h"
#include "scenes/colour.h"
#include "scenes/fresnel.h"
#include "shapes/shape.h"
#include "shapes/transform.h"

namespace raygrade {

// Phong coefficients and the Whitted coefficients of secondary rays. k_a, k_d and k_s may be
// colours (scenes/colour.h): then the number is the largest channel, which decides whether the
// term applies, and the colour is kept beside it; a scene is shaded channel by channel.
struct Material {
  double ambient = 0.1;         // k_a
  double diffuse = 0.7;         // k_d
  double specular = 0.2;        // k_s
  double shininess = 10;        // n, the Phong exponent
  double reflectivity = 0;      // k_r: weight of the reflection ray; 0 spawns none
  double transparency = 0;      // k_t: weight of the refraction ray; 0 spawns none
  double refractive_index = 1;  // η of the object's inside (used when transparency > 0)
  // How reflection and refraction share the light: by k_r and k_t alone (kNone), or weighted
  // by the reflectance F of a Fresnel model, F·k_r and (1 − F)·k_t.
  FresnelModel fresnel = FresnelModel::kNone;
  std::optional<Vec3d> ambient_rgb, diffuse_rgb, specular_rgb;  // when given as colours

  bool has_colour() const { return ambient_rgb || diffuse_rgb || specular_rgb; }
  bool reflects() const { return reflectivity > 0; }
  bool transmits() const { return transparency > 0; }
};

// The deepest tree a scene may ask for: 2^16 − 1 hit nodes at most with both secondary rays,
// far beyond any exercise, and a bound on the work one problem can cause.
constexpr int kMaxTreeDepth = 16;

enum class LightType { kPoint, kDirectional };

struct Light {
  std::string name;
  LightType type = LightType::kPoint;
  Vec3d position{};             // point lights
  Vec3d direction{};            // directional lights: the direction the light travels
  double intensity = 1;         // I_p
  std::optional<Vec3d> colour;  // I_p as [r, g, b], when given so (`intensity` is its largest)
};

struct SceneObject {
  std::string name;
  std::unique_ptr<Shape> shape;  // in object space when transformed
  Material material;
  Transform transform;
  bool solid = false;  // encloses a volume (sphere, box, capped cylinder): a ray can be inside
  // A plane that bounds a medium: the half-space its normal points away from is its inside
  // (then `solid` is true too, and the normal is the outward one of that half-space).
  bool half_space = false;
};

// What a shadow ray does when the object between the point and the light is transparent.
enum class TransparentShadows {
  kBlock,     // every object blocks the light (the course model: "the shadow ray hits an object")
  kTransmit,  // transparent objects let k_t of the light through; opaque ones block it
};

struct Scene {
  std::vector<SceneObject> objects;
  std::vector<Light> lights;
  double ambient_light = 1;  // I_a
  double background = 0;     // the intensity of a ray that hits nothing
  std::optional<Vec3d> ambient_light_rgb, background_rgb;  // when given as colours
  double refractive_index = 1;                             // of the space between the objects
  int max_depth = 5;  // generations of rays in the tree; the primary ray is generation 1
  bool internal_reflection = true;  // reflection rays inside transparent solids
  TransparentShadows transparent_shadows = TransparentShadows::kBlock;
};

// The nearest hit of a world ray among the scene's objects.
struct SceneHit {
  int object = -1;      // index into the objects; -1 for a miss
  Hit hit;              // in world space: t of the world ray, world point, unit world normal
  Ray object_ray;       // the ray in the object's space (the world ray when not transformed)
  Vec3d point_error{};  // a bound on the rounding error of each coordinate of hit.point
};

// The nearest hit in [ray.t_min, ray.t_max]; on a tie, the object listed first.
SceneHit nearest_hit(const Scene& scene, const Ray& ray);

// Every object hit between the ray's origin and t_max, nearest first (for shadow rays).
std::vector<SceneHit> all_hits(const Scene& scene, const Ray& ray);

// Every hit of every object in [t_min, t_max] (both of a sphere's roots), nearest first; on a
// tie, the object listed first.
std::vector<SceneHit> every_hit(const Scene& scene, const Ray& ray);

// Reads a `scene` object; object names must be unique (unnamed objects are named by type and
// position: "sphere 1"). Materials may name an entry of the scene's `materials`.
Scene read_scene(const Cursor& scene);

// Reads one material object (unknown keys and coefficients below 0 are errors).
Material read_material(const Cursor& material);
Light read_light(const Cursor& light, int index);

nlohmann::json material_json(const Material& m);

// Whether any intensity of the material, the light or the scene is a colour.
bool has_colour(const Material& m);
bool has_colour(const Light& l);
bool has_colour(const Scene& s);

// One channel (0 r, 1 g, 2 b) of a colour material, light or scene: every colour replaced by
// that channel's number (numbers stay as they are), so that a scalar trace computes it.
Material channel(const Material& m, int c);
Light channel(const Light& l, int c);
void keep_channel(Scene& s, int c);

}  // namespace raygrade
