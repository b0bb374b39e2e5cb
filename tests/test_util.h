// Helpers shared by the tests: building problems from JSON text.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "grading/result.h"
#include "json/cursor.h"
#include "problems/problem.h"
#include "shapes/shape.h"

namespace raygrade::testing {

// The source tree (the test data, the bank and the docs are read from it).
inline const std::string kSource = RAYGRADE_SOURCE_DIR;

// A file's bytes; empty when it cannot be read.
inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::shared_ptr<const SourceFile> json_file(const std::string& text) {
  return parse_json_text("test.json", text);
}

inline std::unique_ptr<Shape> shape(const std::string& text) {
  auto f = json_file(text);
  return read_shape(Cursor(f));
}

inline Problem problem(const std::string& text) {
  auto f = json_file(text);
  return read_problem(Cursor(f));
}

// A shade problem worked by hand in the tests that use it: P at the origin, N = y, the eye at
// (−3, 4, 0), light A at (3, 4, 0) and light B at (0, 9, 0), blocked.
inline constexpr const char* kTwoLightShade = R"({"id": "s", "kind": "shade",
    "point": [0, 0, 0], "normal": [0, 1, 0], "eye": [-3, 4, 0], "ambient_light": 2,
    "material": {"ambient": 0.1, "diffuse": 0.5, "specular": 0.3, "shininess": 12},
    "lights": [{"name": "A", "position": [3, 4, 0]},
               {"name": "B", "position": [0, 9, 0], "blocked": true}]})";

// The part of a graded problem with this name, or null.
inline const PartResult* part(const GradeResult& r, const std::string& name) {
  for (const auto& p : r.parts) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

inline Ray ray(Vec3d o, Vec3d d, double t_min = 0, double t_max = kInfinity) {
  return Ray{o, d, t_min, t_max};
}

}  // namespace raygrade::testing
