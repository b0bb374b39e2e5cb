// Reading and writing intensities that are numbers or colours.
#include "scenes/colour.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "derivation/number_format.h"

namespace raygrade {

Intensity read_intensity(const Cursor& c, std::string_view what) {
  Intensity i;
  if (c.is_array()) {
    if (c.json().size() != 3) {
      c.fail(fmt::format("{} is a number or a colour [r, g, b]; found {} elements", what,
                         c.json().size()),
             "type");
    }
    auto e = c.items();
    Vec3d rgb{};
    for (int k = 0; k < 3; ++k) {
      rgb[k] = e[k].number();
      if (rgb[k] < 0) {
        e[k].fail(fmt::format("the {} channel of {} must not be negative", kChannelNames[k], what),
                  "range");
      }
    }
    i.colour = rgb;
    i.value = std::max({rgb.x, rgb.y, rgb.z});
    return i;
  }
  if (!c.json().is_number()) {
    c.fail(fmt::format("{} is a number or a colour [r, g, b]", what), "type");
  }
  i.value = c.number();
  if (i.value < 0) c.fail(fmt::format("{} must not be negative", what), "range");
  return i;
}

nlohmann::json channels_json(const Vec3d& rgb, bool colour) {
  if (!colour) return rgb.x;
  return nlohmann::json::array({rgb.x, rgb.y, rgb.z});
}

nlohmann::json intensity_json(const Intensity& i) {
  return i.colour ? channels_json(*i.colour, true) : nlohmann::json(i.value);
}

std::string colour_text(const Vec3d& c) {
  return fmt::format("[{}, {}, {}]", format_number(c.x), format_number(c.y), format_number(c.z));
}

std::string swatch_hex(const Vec3d& rgb) {
  auto byte = [](double v) {
    double clamped = std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0);
    return static_cast<int>(std::lround(clamped * 255));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(rgb.x), byte(rgb.y), byte(rgb.z));
}

}  // namespace raygrade
