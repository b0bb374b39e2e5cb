// The table of problem kinds: a kind is its own file pair (a type that kinds/kind.h's concept
// checks) and one line here. Grading, answer forms, the problem schema and the docs' table of
// kinds come from this list.
#include "kinds/camera_ray.h"
#include "kinds/derive.h"
#include "kinds/fresnel.h"
#include "kinds/interpolate.h"
#include "kinds/intersect.h"
#include "kinds/kind.h"
#include "kinds/normal_at.h"
#include "kinds/ray_tree.h"
#include "kinds/reflect.h"
#include "kinds/refract.h"
#include "kinds/shade.h"
#include "kinds/view_ray.h"

namespace raygrade {

// The first is the kind of a problem that names none. One kind a line:
// clang-format off
using Kinds = KindList<
    IntersectKind,
    FirstHitKind,
    CameraRayKind,
    ViewRayKind,
    RayTreeKind,
    ReflectKind,
    RefractKind,
    ShadeKind,
    FresnelKind,
    NormalKind,
    InterpolateKind,
    DeriveKind>;
// clang-format on

const std::vector<KindEntry>& kind_table() {
  static const std::vector<KindEntry> table = Kinds::entries();
  return table;
}

const KindEntry* find_kind(std::string_view name) {
  for (const KindEntry& k : kind_table()) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

}  // namespace raygrade
