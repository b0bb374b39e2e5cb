// The hard-case corpus and the random sets of the accuracy study.
#include "accuracy/corpus.h"

#include <cmath>

#include "core/error.h"
#include "json/source.h"

namespace raygrade {

std::uint64_t SplitMix::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double SplitMix::uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }

double SplitMix::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

int SplitMix::integer(int lo, int hi) {
  return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
}

Vec3d SplitMix::unit_vector() {
  double z = uniform(-1, 1), phi = uniform(0, 2 * M_PI), s = std::sqrt(1 - z * z);
  return {s * std::cos(phi), s * std::sin(phi), z};
}

Vec3d perpendicular(const Vec3d& u, SplitMix& rng) {
  return normalized(cross(u, rng.unit_vector()));
}

namespace {

AccuracyCase make(std::string id, std::string group, Primitive p, Vec3d o, Vec3d d,
                  std::vector<Vec3d> points, double radius = 0) {
  return AccuracyCase{std::move(id), std::move(group), p, o, d, std::move(points), radius};
}

// ±10^-k: the relative offset from a tangent of a grazing ray.
double offset(SplitMix& rng, int k_lo, int k_hi) {
  return (rng.uniform() < 0.5 ? -1 : 1) * std::pow(10.0, -rng.integer(k_lo, k_hi));
}

// A ray from `origin` that passes the center of a sphere at distance r·(1 + δ).
AccuracyCase sphere_pass(std::string id, std::string group, Vec3d origin, Vec3d center, double r,
                         double delta, SplitMix& rng) {
  Vec3d u = normalized(center - origin);
  Vec3d target = center + (r * (1 + delta)) * perpendicular(u, rng);
  return make(std::move(id), std::move(group), Primitive::kSphere, origin, target - origin,
              {center}, r);
}

void far_spheres(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 100; ++i) {
    Vec3d o{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    double dist = std::pow(10.0, rng.uniform(4, 9));
    out.push_back(sphere_pass(fmt::format("far-sphere-{}", i), "far-sphere", o,
                              o + dist * rng.unit_vector(), 1, offset(rng, 1, 12), rng));
  }
  for (int i = 0; i < 40; ++i) {
    double r = std::pow(10.0, -rng.uniform(3, 6)), dist = std::pow(10.0, rng.uniform(3, 6));
    out.push_back(sphere_pass(fmt::format("tiny-far-sphere-{}", i), "far-sphere", Vec3d{},
                              dist * rng.unit_vector(), r, offset(rng, 1, 10), rng));
  }
}

void huge_spheres(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    double r = std::pow(10.0, rng.uniform(6, 12));
    Vec3d c{rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
    Vec3d u = rng.unit_vector(), w = perpendicular(u, rng);
    double h = r * std::pow(10.0, -rng.uniform(6, 14));
    Vec3d o = c + (r + h) * u;
    // Just below the horizon (hits), just above it (misses), straight down, or away.
    double horizon = std::sqrt(2 * h / r);
    Vec3d d;
    switch (i % 4) {
      case 0: d = w - (horizon * (1 + offset(rng, 1, 6))) * u; break;
      case 1: d = w - (horizon * (1 - std::abs(offset(rng, 1, 6)))) * u; break;
      case 2: d = -1.0 * u + 0.3 * w; break;
      default: d = u + w;
    }
    out.push_back(
        make(fmt::format("huge-sphere-{}", i), "huge-sphere", Primitive::kSphere, o, d, {c}, r));
  }
}

void grazing(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 80; ++i) {
    Vec3d c{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    double r = rng.uniform(0.5, 2);
    out.push_back(sphere_pass(fmt::format("grazing-sphere-{}", i), "grazing",
                              c + 5.0 * rng.unit_vector(), c, r, offset(rng, 4, 15), rng));
  }
  for (int i = 0; i < 60; ++i) {
    Vec3d base{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d axis = i % 3 == 0 ? Vec3d{0, 0, 1} : rng.unit_vector();
    Vec3d e1 = perpendicular(axis, rng), e2 = normalized(cross(axis, e1));
    double r = rng.uniform(0.5, 2), p = r * (1 + offset(rng, 4, 15));
    double z0 = rng.uniform(-2, 2), z1 = rng.uniform(-2, 2);
    Vec3d o = base + p * e2 + 5.0 * e1 + z0 * axis;
    Vec3d d = -5.0 * e1 + (z1 - z0) * axis;
    out.push_back(make(fmt::format("grazing-cylinder-{}", i), "grazing", Primitive::kCylinder, o, d,
                       {base, axis}, r));
  }
  // Exact tangents: integer data, the discriminant is exactly zero.
  out.push_back(
      make("tangent-0", "tangent", Primitive::kSphere, {-5, 1, 0}, {1, 0, 0}, {{0, 0, 0}}, 1));
  out.push_back(
      make("tangent-1", "tangent", Primitive::kSphere, {-4, 6, 5}, {2, 0, 0}, {{3, 4, 5}}, 2));
  out.push_back(
      make("tangent-2", "tangent", Primitive::kSphere, {0, 0, 10}, {3, 4, 0}, {{0, 0, 15}}, 5));
  out.push_back(make("tangent-3", "tangent", Primitive::kCylinder, {-5, 1, 0}, {1, 0, 0.5},
                     {{0, 0, 0}, {0, 0, 1}}, 1));
  out.push_back(make("tangent-4", "tangent", Primitive::kCylinder, {3, -7, 2}, {0, 1, 0},
                     {{0, 0, 0}, {0, 0, 2}}, 3));
  // Beyond double-double: the discriminant is about 1e-32 of its terms, below the 2^-100
  // double-double can vouch for: only MPFR decides. With f = (−5, 1 − 2^-53, z):
  // Δ = 1 − (1 − 2^-53)² − z², which is −2^-106 for z = 2^-26 (a miss) and 3·2^-106 − 2^-158
  // for z = 2^-26 − 2^-79 (a hit; 53 bits, so exactly a double).
  out.push_back(make("beyond-double-double-0", "tangent", Primitive::kSphere,
                     {-5, 1 - 0x1p-53, 0x1p-26}, {1, 0, 0}, {{0, 0, 0}}, 1));
  out.push_back(make("beyond-double-double-1", "tangent", Primitive::kSphere,
                     {-5, 1 - 0x1p-53, 0x1p-26 - 0x1p-79}, {1, 0, 0}, {{0, 0, 0}}, 1));
  // Origins on the surface: exactly (t = 0) and to the nearest double.
  out.push_back(make("on-surface-0", "on-surface", Primitive::kSphere, {1, 0, 0}, {-1, 0.5, 0},
                     {{0, 0, 0}}, 1));
  out.push_back(make("on-surface-1", "on-surface", Primitive::kSphere, {1, 0, 0}, {1, 0.3, 0},
                     {{0, 0, 0}}, 1));
  out.push_back(make("on-surface-2", "on-surface", Primitive::kCylinder, {0, 2, 7}, {0, -1, 1},
                     {{0, 0, 0}, {0, 0, 1}}, 2));
  for (int i = 0; i < 30; ++i) {
    Vec3d c{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    double r = rng.uniform(0.5, 2);
    Vec3d u = rng.unit_vector();
    Vec3d d = i % 2 == 0 ? rng.unit_vector() - u : u + 0.5 * perpendicular(u, rng);
    out.push_back(make(fmt::format("on-surface-{}", i + 3), "on-surface", Primitive::kSphere,
                       c + r * u, d, {c}, r));
  }
}

void near_parallel_planes(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    Vec3d n = rng.unit_vector() * rng.uniform(0.5, 3);
    Vec3d p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d o = p + rng.uniform(-2, 2) * normalized(n) + 0.5 * rng.unit_vector();
    Vec3d along = perpendicular(normalized(n), rng);
    Vec3d d = along + offset(rng, 10, 16) * normalized(n);
    out.push_back(
        make(fmt::format("near-parallel-{}", i), "near-parallel", Primitive::kPlane, o, d, {n, p}));
  }
}

void shared_edges(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 60; ++i) {
    double scale = i % 4 == 3 ? 1e8 : 1;  // some far from the origin
    Vec3d shift = scale == 1 ? Vec3d{} : scale * rng.unit_vector();
    // A quad folded along its diagonal q0 q2, q1 and q3 on either side of it as seen from
    // above, where the rays come from.
    auto jitter = [&](double x, double y) {
      return shift +
             Vec3d{x + rng.uniform(-0.3, 0.3), y + rng.uniform(-0.3, 0.3), rng.uniform(-0.2, 0.2)};
    };
    Vec3d q[4] = {jitter(-1, -1), jitter(1, -1), jitter(1, 1), jitter(-1, 1)};
    Vec3d o = shift + Vec3d{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(2, 4)};
    if (i % 3 == 0) {
      // A fan of five triangles around a vertex, each ray exactly at the vertex.
      Vec3d center = jitter(0, 0), d = center - o;
      std::vector<Vec3d> rim;
      for (int k = 0; k < 5; ++k) {
        double a = 2 * M_PI * k / 5 + rng.uniform(-0.3, 0.3);
        rim.push_back(center + Vec3d{std::cos(a), std::sin(a), rng.uniform(-0.3, 0.3)});
      }
      for (int k = 0; k < 5; ++k) {
        out.push_back(make(fmt::format("shared-vertex-{}/{}", i, static_cast<char>('a' + k)),
                           "shared-edge", Primitive::kTriangle, o, d,
                           {center, rim[k], rim[(k + 1) % 5]}));
      }
      continue;
    }
    Vec3d target = q[0] + rng.uniform(0.05, 0.95) * (q[2] - q[0]);
    Vec3d d = target - o;
    std::string id = fmt::format("shared-edge-{}", i);
    out.push_back(make(id + "/a", "shared-edge", Primitive::kTriangle, o, d, {q[0], q[1], q[2]}));
    out.push_back(make(id + "/b", "shared-edge", Primitive::kTriangle, o, d, {q[0], q[2], q[3]}));
  }
  for (int i = 0; i < 20; ++i) {
    // Two planar polygons (a pentagon and a quad) sharing the edge v0 v2 of a plane.
    Vec3d base{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d e1{1, 0, 0}, e2{0, 1, 0};
    if (i % 2 == 1) e2 = Vec3d{0, 0.5, 0.5};  // a tilted plane with exact coordinates
    auto at = [&](double x, double y) { return base + x * e1 + y * e2; };
    std::vector<Vec3d> left = {at(0, 0), at(0, 2), at(-1, 2.5), at(-2, 1), at(-1, -0.5)};
    std::vector<Vec3d> right = {at(0, 2), at(0, 0), at(1.5, 0.5), at(1, 2)};
    Vec3d target = at(0, rng.uniform(0, 2));
    Vec3d o = target + Vec3d{rng.uniform(-1, 1), rng.uniform(-1, 1), 3};
    std::string id = fmt::format("shared-polygon-edge-{}", i);
    out.push_back(make(id + "/a", "shared-edge", Primitive::kPolygon, o, target - o, left));
    out.push_back(make(id + "/b", "shared-edge", Primitive::kPolygon, o, target - o, right));
  }
}

void needles(std::vector<AccuracyCase>& out, SplitMix& rng) {
  for (int i = 0; i < 40; ++i) {
    Vec3d a{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    Vec3d e1 = rng.unit_vector(), e2 = perpendicular(e1, rng);
    double h = std::pow(10.0, -rng.uniform(6, 12));
    Vec3d b = a + 2.0 * e1, c = a + 1.0 * e1 + h * e2;
    Vec3d target = a + rng.uniform(0.1, 1.9) * e1 + (h * rng.uniform(-0.5, 1.5) / 2) * e2;
    Vec3d o = target + 3.0 * rng.unit_vector();
    out.push_back(make(fmt::format("needle-{}", i), "needle", Primitive::kTriangle, o, target - o,
                       {a, b, c}));
  }
}

}  // namespace

std::vector<AccuracyCase> random_cases(Primitive primitive, int count, std::uint64_t seed) {
  SplitMix rng(seed);
  std::vector<AccuracyCase> out;
  auto point = [&](double s) {
    return Vec3d{rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s)};
  };
  for (int i = 0; i < count; ++i) {
    Vec3d o = 4.0 * rng.unit_vector();
    Vec3d target = point(1);
    std::vector<Vec3d> p;
    double r = 0;
    switch (primitive) {
      case Primitive::kSphere:
        p = {point(0.5)};
        r = rng.uniform(0.3, 1.2);
        break;
      case Primitive::kPlane: p = {rng.unit_vector(), point(0.5)}; break;
      case Primitive::kTriangle: p = {point(1), point(1), point(1)}; break;
      case Primitive::kPolygon: {
        Vec3d c = point(0.3), e1 = rng.unit_vector(), e2 = perpendicular(e1, rng);
        for (int k = 0; k < 5; ++k) {
          double a = 2 * M_PI * k / 5, s = rng.uniform(0.5, 1);
          p.push_back(c + (s * std::cos(a)) * e1 + (s * std::sin(a)) * e2);
        }
        break;
      }
      case Primitive::kCylinder:
        p = {point(0.5), rng.unit_vector()};
        r = rng.uniform(0.3, 1);
        break;
      case Primitive::kBox: {
        Vec3d lo = point(1),
              size{rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5), rng.uniform(0.2, 1.5)};
        p = {lo, lo + size};
        break;
      }
    }
    out.push_back(make(fmt::format("random-{}-{}", primitive_name(primitive), i), "random",
                       primitive, o, target - o, std::move(p), r));
  }
  return out;
}

std::vector<AccuracyCase> hard_cases() {
  SplitMix rng(20240611);
  std::vector<AccuracyCase> out;
  far_spheres(out, rng);
  huge_spheres(out, rng);
  grazing(out, rng);
  near_parallel_planes(out, rng);
  shared_edges(out, rng);
  needles(out, rng);
  scale_and_boundary_cases(out, rng);
  return out;
}

}  // namespace raygrade
