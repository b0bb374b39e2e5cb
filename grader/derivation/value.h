// Value: what a derivation step computes: a scalar, a vector or a yes/no verdict.
#pragma once

#include <string>

#include "math/vec3.h"

namespace raygrade {

struct Value {
  enum class Kind { kNone, kScalar, kVector, kBool };
  Kind kind = Kind::kNone;
  double scalar = 0;
  Vec3d vector{};
  bool truth = false;

  Value() = default;
  Value(double s) : kind(Kind::kScalar), scalar(s) {}        // NOLINT: implicit by design
  Value(int s) : kind(Kind::kScalar), scalar(s) {}           // NOLINT
  Value(const Vec3d& v) : kind(Kind::kVector), vector(v) {}  // NOLINT
  static Value verdict(bool b) {
    Value v;
    v.kind = Kind::kBool;
    v.truth = b;
    return v;
  }

  bool is_scalar() const { return kind == Kind::kScalar; }
  bool is_vector() const { return kind == Kind::kVector; }
  bool is_bool() const { return kind == Kind::kBool; }
};

}  // namespace raygrade
