// Fresnel reflectance at a boundary between two indices: the exact Fresnel equations for
// unpolarized light and Schlick's approximation, both with total internal reflection; and the
// worked steps of each.
#pragma once

#include <optional>
#include <string>

#include "derivation/derivation.h"

namespace raygrade {

enum class FresnelModel { kNone, kSchlick, kExact };

// "schlick", "exact" ("" for kNone).
std::string to_string(FresnelModel m);

struct Reflectance {
  bool total_internal_reflection = false;
  double cos_i = 1;  // cos θi
  double cos_t = 1;  // cos θt (0 under total internal reflection)
  double r0 = 0;     // Schlick: ((n1 − n2)/(n1 + n2))²
  double r_s = 1;    // exact: the s-polarized (perpendicular) reflectance
  double r_p = 1;    // exact: the p-polarized (parallel) reflectance
  double reflectance = 1;
};

// The reflectance for light arriving at cos θi from index n1 onto index n2.
// Exact: R_s = ((n1 cos θi − n2 cos θt)/(n1 cos θi + n2 cos θt))², R_p = ((n1 cos θt −
// n2 cos θi)/(n1 cos θt + n2 cos θi))², R = (R_s + R_p)/2.
// Schlick: R = R0 + (1 − R0)(1 − cos θ)⁵ with cos θ = cos θi going into a higher (or equal)
// index and cos θt going into a lower one (the angle on the denser side, as Schlick's
// approximation requires); R = 1 under total internal reflection.
Reflectance fresnel_reflectance(FresnelModel model, double cos_i, double n1, double n2);

// The steps of fresnel_reflectance, from the steps `n1`, `n2`, `cos_i` and `k` (= cos²θt)
// already in `d`: `cos_t`, then `R0` and `F` (Schlick) or `R_s`, `R_p` and `F` (exact), with
// F the reflectance. Under total internal reflection (k < 0) F is 1 with a note.
void fresnel_steps(Deriver& d, FresnelModel model, bool total_internal_reflection);

}  // namespace raygrade
