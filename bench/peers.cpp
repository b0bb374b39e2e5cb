// The peers: GLM (a dependency of the benchmark only) and Möller–Trumbore.
#include "bench/peers.h"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtx/intersect.hpp>

namespace raygrade {
namespace {

glm::dvec3 g(const Vec3d& v) { return {v.x, v.y, v.z}; }

// GLM wants a unit direction and returns the distance along it: t = distance / |d|.
bool glm_sphere(const AccuracyCase& c, double& t) {
  double len = length(c.direction);
  double distance = 0;
  if (!glm::intersectRaySphere(g(c.origin), g(c.direction / len), g(c.points[0]),
                               c.radius * c.radius, distance)) {
    return false;
  }
  t = distance / len;
  return true;
}

bool glm_triangle(const AccuracyCase& c, double& t) {
  glm::dvec2 bary;
  return glm::intersectRayTriangle(g(c.origin), g(c.direction), g(c.points[0]), g(c.points[1]),
                                   g(c.points[2]), bary, t) &&
         t >= 0;
}

bool glm_plane(const AccuracyCase& c, double& t) {
  return glm::intersectRayPlane(g(c.origin), g(c.direction), g(c.points[1]), g(c.points[0]), t);
}

// Möller and Trumbore (1997), both faces, no epsilon: det = 0 is the only rejection.
bool moller_trumbore(const AccuracyCase& c, double& t) {
  const Vec3d &a = c.points[0], &b = c.points[1], &cc = c.points[2];
  Vec3d e1 = b - a, e2 = cc - a;
  Vec3d p = cross(c.direction, e2);
  double det = dot(e1, p);
  if (det == 0) return false;
  double inv = 1 / det;
  Vec3d s = c.origin - a;
  double u = dot(s, p) * inv;
  if (u < 0 || u > 1) return false;
  Vec3d q = cross(s, e1);
  double v = dot(c.direction, q) * inv;
  if (v < 0 || u + v > 1) return false;
  t = dot(e2, q) * inv;
  return t >= 0;
}

}  // namespace

const std::vector<Peer>& peers() {
  static const std::vector<Peer> list = {
      {"GLM intersectRaySphere", primitive_of<Sphere>(), glm_sphere},
      {"GLM intersectRayPlane", primitive_of<Plane>(), glm_plane},
      {"GLM intersectRayTriangle", primitive_of<Triangle>(), glm_triangle},
      {"Möller–Trumbore", primitive_of<Triangle>(), moller_trumbore},
  };
  return list;
}

}  // namespace raygrade
