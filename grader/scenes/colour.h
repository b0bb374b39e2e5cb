// Colour: every intensity of a scene (a light's, the ambient light, the Phong coefficients, the
// background) is one number or a colour [r, g, b]. A number stays a number, so a problem
// without colours computes, answers and grades exactly as before; a colour is worked channel
// by channel, a number meeting a colour acting on every channel alike.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "json/cursor.h"
#include "math/vec3.h"

namespace raygrade {

// The channels of a colour, as answers and feedback name them.
constexpr const char* kChannelNames[3] = {"r", "g", "b"};

// A number (`colour` empty) or a colour; `value` is the number, or the largest channel of the
// colour (what decides whether a term applies: a coefficient applies when any channel is > 0).
struct Intensity {
  double value = 0;
  std::optional<Vec3d> colour;

  double channel(int c) const { return colour ? (*colour)[c] : value; }
  Vec3d rgb() const { return colour ? *colour : Vec3d{value, value, value}; }
};

// Reads a number ≥ 0 or [r, g, b] of numbers ≥ 0; `what` names the quantity in errors.
Intensity read_intensity(const Cursor& c, std::string_view what);

// The number, or [r, g, b].
nlohmann::json intensity_json(const Intensity& i);
// A colour's channels as [r, g, b] JSON, or a number when `colour` is false.
nlohmann::json channels_json(const Vec3d& rgb, bool colour);

// A colour as the worked solutions write it: "[0.9, 0.5, 0.2]".
std::string colour_text(const Vec3d& rgb);

// A colour clamped to [0, 1] per channel and written as #rrggbb, for a swatch.
std::string swatch_hex(const Vec3d& rgb);

}  // namespace raygrade
