// Lattice points and integer vectors for the problem generator.
#include "sampling/lattice.h"

#include <cmath>
#include <map>
#include <mutex>
#include <numeric>

#include "derivation/number_format.h"

namespace raygrade {

namespace {
// The caches below are filled once per radius and only read after that; the lock makes the
// first fill safe when problems are drawn on several threads.
std::mutex lattice_mutex;
}  // namespace

const std::vector<Vec3d>& lattice_sphere(int r) {
  static std::map<int, std::vector<Vec3d>> cache;
  std::lock_guard lock(lattice_mutex);
  auto [it, fresh] = cache.try_emplace(r);
  if (fresh) {
    for (int x = -r; x <= r; ++x) {
      for (int y = -r; y <= r; ++y) {
        for (int z = -r; z <= r; ++z) {
          if (x * x + y * y + z * z == r * r)
            it->second.emplace_back(double(x), double(y), double(z));
        }
      }
    }
  }
  return it->second;
}

const std::vector<Vec3d>& lattice_circle(int r) {
  static std::map<int, std::vector<Vec3d>> cache;
  std::lock_guard lock(lattice_mutex);
  auto [it, fresh] = cache.try_emplace(r);
  if (fresh) {
    for (int x = -r; x <= r; ++x) {
      for (int y = -r; y <= r; ++y) {
        if (x * x + y * y == r * r) it->second.emplace_back(double(x), double(y), 0);
      }
    }
  }
  return it->second;
}

long long component_gcd(const Vec3d& v) {
  long long g = std::gcd(std::gcd(std::llabs(std::llround(v.x)), std::llabs(std::llround(v.y))),
                         std::llabs(std::llround(v.z)));
  return g == 0 ? 1 : g;
}

Vec3d reduced(const Vec3d& v) { return v / static_cast<double>(component_gcd(v)); }

Vec3d random_point(Prng& rng, int limit) {
  return {double(rng.range(-limit, limit)), double(rng.range(-limit, limit)),
          double(rng.range(-limit, limit))};
}

Vec3d random_direction(Prng& rng, const Vec3d& avoid) {
  while (true) {
    Vec3d d{double(rng.range(-2, 2)), double(rng.range(-2, 2)), double(rng.range(-2, 2))};
    if (length_squared(d) == 0) continue;
    if (length_squared(avoid) > 0 && length_squared(cross(d, avoid)) == 0) continue;
    return d;
  }
}

Vec3d AxisMap::operator()(const Vec3d& v) const {
  Vec3d out;
  for (int i = 0; i < 3; ++i) out[axis[i]] = sign[i] * v[i];
  return out;
}

AxisMap random_axis_map(Prng& rng) {
  static const int kPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                          {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  AxisMap m;
  const int* p = kPermutations[rng.below(6)];
  for (int i = 0; i < 3; ++i) {
    m.axis[i] = p[i];
    m.sign[i] = rng.sign();
  }
  return m;
}

nlohmann::ordered_json number_json(double v) {
  if (v == std::round(v) && std::abs(v) < 1e15) return static_cast<long long>(v);
  return v;
}

nlohmann::ordered_json vector_json(const Vec3d& v) {
  return nlohmann::ordered_json::array({number_json(v.x), number_json(v.y), number_json(v.z)});
}

std::string point_text(const Vec3d& v) {
  return fmt::format("({}, {}, {})", format_number(v.x), format_number(v.y), format_number(v.z));
}

std::string direction_text(const Vec3d& v) {
  return fmt::format("<{}, {}, {}>", format_number(v.x), format_number(v.y), format_number(v.z));
}

}  // namespace raygrade
