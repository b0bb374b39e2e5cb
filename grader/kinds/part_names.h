// The names of the answer parts that code above the kinds reads: each is declared here once, the
// kinds' parts() list them (kinds/*.cpp), and the graders, checks, exports and pages take them
// from here, never as strings of their own (the test part_names). A part's name is also its key
// in an answer ({"t": ..., "point": ...}, docs/submission-format.md).
#pragma once

namespace raygrade::part_names {

// A hit: intersect, first-hit, a ray tree's "hit".
inline constexpr char kT[] = "t";
inline constexpr char kPoint[] = "point";
inline constexpr char kNormal[] = "normal";
inline constexpr char kBarycentric[] = "barycentric";
// u and v: a hit's barycentric weights given as u = w_b and v = w_c; interpolate's texture
// coordinates.
inline constexpr char kU[] = "u";
inline constexpr char kV[] = "v";
inline constexpr char kObject[] = "object";
inline constexpr char kHit[] = "hit";
// A ray: camera-ray's, view-ray's origin and direction, and a reflected or refracted one.
inline constexpr char kRay[] = "ray";
inline constexpr char kOrigin[] = "origin";
inline constexpr char kDirection[] = "direction";
inline constexpr char kUnitDirection[] = "unit_direction";
// A ray tree's, and shade's.
inline constexpr char kTree[] = "tree";
inline constexpr char kShadows[] = "shadows";
inline constexpr char kTerms[] = "terms";
inline constexpr char kIntensity[] = "intensity";
inline constexpr char kMedia[] = "media";
inline constexpr char kLights[] = "lights";
inline constexpr char kDiffuse[] = "diffuse";
inline constexpr char kSpecular[] = "specular";
// The derivation's named steps, of every kind that has them.
inline constexpr char kSteps[] = "steps";

}  // namespace raygrade::part_names
