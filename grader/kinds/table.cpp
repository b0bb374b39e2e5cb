// The table of problem kinds: adding one is one line here plus its own file pair.
#include "kinds/camera_ray.h"
#include "kinds/derive.h"
#include "kinds/fresnel.h"
#include "kinds/intersect.h"
#include "kinds/normal_at.h"
#include "kinds/ray_tree.h"
#include "kinds/reflect.h"
#include "kinds/refract.h"
#include "kinds/shade.h"
#include "kinds/view_ray.h"
#include "problems/problem.h"

namespace raygrade {

const std::vector<KindEntry>& kind_table() {
  static const std::vector<KindEntry> table = {
      {"intersect", "every hit of a ray with one object", {"ray", "object"}, &IntersectTask::read},
      {"first-hit", "the object a ray hits first", {"ray", "objects"}, &FirstHitTask::read},
      {"camera-ray",
       "the ray a perspective camera shoots through a pixel",
       {"camera", "pixel", "convention"},
       &CameraRayTask::read},
      {"view-ray",
       "the ray through a pixel of a look-at camera: u, v, w, the image plane (bounds or field "
       "of view), perspective or orthographic",
       {"camera", "pixel", "convention"},
       &ViewRayTask::read},
      {"ray-tree",
       "the tree of rays one ray spawns in a scene: shadows, reflection, refraction, Phong",
       {"scene", "ray", "camera", "pixel", "convention", "ask", "labels", "components"},
       &RayTreeTask::read},
      {"reflect",
       "the mirror direction of a ray at a surface",
       {"direction", "normal"},
       &ReflectTask::read},
      {"refract",
       "Snell's law at a surface, with total internal reflection",
       {"direction", "normal", "n1", "n2"},
       &RefractTask::read},
      {"shade",
       "the Phong intensity at a point, term by term",
       {"point", "normal", "eye", "material", "lights", "ambient_light", "object_transform"},
       &ShadeTask::read},
      {"fresnel",
       "the share of light a boundary reflects: the Fresnel equations or Schlick's approximation",
       {"n1", "n2", "model", "angle", "direction", "normal"},
       &FresnelTask::read},
      {"normal",
       "the unit normal of an object at a point of its surface",
       {"object", "point"},
       &NormalTask::read},
      {"derive",
       "quantities of a derivation as formulas",
       {"ray", "object", "find"},
       &DeriveTask::read},
  };
  return table;
}

}  // namespace raygrade
