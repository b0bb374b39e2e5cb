// Fresnel reflectance: the exact equations and Schlick's approximation.
#include "scenes/fresnel.h"

#include <cmath>

namespace raygrade {

std::string to_string(FresnelModel m) {
  switch (m) {
    case FresnelModel::kSchlick: return "schlick";
    case FresnelModel::kExact: return "exact";
    case FresnelModel::kNone: break;
  }
  return "";
}

Reflectance fresnel_reflectance(FresnelModel model, double cos_i, double n1, double n2) {
  Reflectance r;
  r.cos_i = cos_i;
  double eta = n1 / n2;
  double k = 1 - eta * eta * (1 - cos_i * cos_i);  // cos²θt
  r.r0 = (n1 - n2) / (n1 + n2) * ((n1 - n2) / (n1 + n2));
  if (k < 0) {
    r.total_internal_reflection = true;
    r.cos_t = 0;
    return r;  // every reflectance 1
  }
  r.cos_t = std::sqrt(k);
  if (model == FresnelModel::kSchlick) {
    double c = n1 > n2 ? r.cos_t : cos_i;
    r.reflectance = r.r0 + (1 - r.r0) * std::pow(1 - c, 5);
    return r;
  }
  double s = (n1 * cos_i - n2 * r.cos_t) / (n1 * cos_i + n2 * r.cos_t);
  double p = (n1 * r.cos_t - n2 * cos_i) / (n1 * r.cos_t + n2 * cos_i);
  r.r_s = s * s;
  r.r_p = p * p;
  r.reflectance = (r.r_s + r.r_p) / 2;
  return r;
}

void fresnel_steps(Deriver& d, FresnelModel model, bool total_internal_reflection) {
  E n1 = d.sym("n1"), n2 = d.sym("n2");
  if (model == FresnelModel::kSchlick) {
    d.step("R0", "R_0", square(n1 - n2) / square(n1 + n2),
           "the reflectance at normal incidence, ((n₁ − n₂)/(n₁ + n₂))²");
  }
  if (total_internal_reflection) {
    d.given("F", "F", 1.0,
            "total internal reflection (k < 0): all the light is reflected, the reflectance is 1");
    return;
  }
  d.step("cos_t", "cos_t", sqrt(d.sym("k")), "cos θt = √k");
  E ci = d.sym("cos_i"), ct = d.sym("cos_t");
  if (model == FresnelModel::kSchlick) {
    bool denser_first = d.scalar("n1") > d.scalar("n2");
    E c = ci;
    if (denser_first) {
      // θt in degrees first, then its cosine in radians, as Snell's law gives it: an angle
      // in degrees read as radians is then one change.
      d.step("theta_t", "theta_t", arccos_degrees(ct), "the angle of refraction");
      c = cos(d.sym("theta_t") * pi() / 180);
    }
    E x = 1 - c;
    d.step("F", "F", d.sym("R0") + (1 - d.sym("R0")) * square(square(x)) * x,
           denser_first ? "Schlick: R₀ + (1 − R₀)(1 − cos θt)⁵, with θt, the angle on the less "
                          "dense side, since the light leaves the denser medium"
                        : "Schlick: R₀ + (1 − R₀)(1 − cos θi)⁵");
    return;
  }
  // The amplitude ratios first, then their squares: a square left out is then one change,
  // made alike in both (r_s and r_p are one family, as S_1 and S_2 are).
  d.step("r_s", "r_s", (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct),
         "s-polarized (perpendicular) amplitude: (n₁cos θi − n₂cos θt)/(n₁cos θi + n₂cos θt)");
  d.step("R_s", "R_s", square(d.sym("r_s")), "the s-polarized reflectance, r_s²");
  d.step("r_p", "r_p", (n1 * ct - n2 * ci) / (n1 * ct + n2 * ci),
         "p-polarized (parallel) amplitude: (n₁cos θt − n₂cos θi)/(n₁cos θt + n₂cos θi)");
  d.step("R_p", "R_p", square(d.sym("r_p")), "the p-polarized reflectance, r_p²");
  d.step("F", "F", (d.sym("R_s") + d.sym("R_p")) / 2, "unpolarized light: the mean of the two");
}

}  // namespace raygrade
