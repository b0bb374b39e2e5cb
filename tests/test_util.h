// Helpers shared by the tests: building problems from JSON text.
#pragma once

#include <string>

#include "json/cursor.h"
#include "problems/problem.h"
#include "shapes/shape.h"

namespace raygrade::testing {

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

inline Ray ray(Vec3d o, Vec3d d, double t_min = 0, double t_max = kInfinity) {
  return Ray{o, d, t_min, t_max};
}

}  // namespace raygrade::testing
