// Grading a colour channel by channel.
#include "grading/grade_colour.h"

#include <fmt/format.h>

#include "scenes/colour.h"

namespace raygrade {

ColourVerdict grade_colour(const std::string& name, const AnswerReader& s, const Vec3d& want,
                           const Tolerance& tol, const NumberFormat& numbers) {
  // A channel at the precision it is graded to.
  auto number = [&](double v) { return format_number(v, shown_at(tol, v, numbers)); };
  std::string right = fmt::format("[{}, {}, {}]", number(want.x), number(want.y), number(want.z));
  if (s.json().is_null()) return {0, {fmt::format("{} is {}, not none.", name, right)}, {}};
  if (s.json().is_number()) {
    const char* id = "scalar-for-colour";
    std::string msg = fmt::format("{} is the colour {} (r, g, b), not the single number {}.", name,
                                  right, number(s.json().get<double>()));
    return {mistake_info(id).credit, {msg}, {make_mistake(id, name, msg)}};
  }
  if (!s.json().is_array() || s.json().size() != 3) {
    return {0, {fmt::format("{}: expected a colour [r, g, b]", name)}, {}};
  }
  std::vector<std::string> wrong, imprecise;
  auto given = s.items();
  for (int c = 0; c < 3; ++c) {
    auto n = given[c].number();
    if (!n.value) {
      return {0, {fmt::format("{} channel {}: {}", name, kChannelNames[c], n.fault)}, {}};
    }
    NumberVerdict v = compare_number(*n.value, want[c], want[c], tol);
    if (v.match == Match::kWrong) {
      wrong.push_back(
          fmt::format("{} is {}, not {}", kChannelNames[c], number(want[c]), n.value->text));
    } else if (v.match == Match::kInsufficientPrecision) {
      imprecise.push_back(fmt::format("{}: {}", kChannelNames[c], v.message));
    }
  }
  if (!wrong.empty()) {
    return {0,
            {fmt::format("{} is {}; wrong channel{}: {}.", name, right,
                         wrong.size() == 1 ? "" : "s", fmt::join(wrong, "; "))},
            {}};
  }
  if (!imprecise.empty()) {
    return {tol.precision_credit, {fmt::format("{}: {}", name, fmt::join(imprecise, "; "))}, {}};
  }
  return {1, {}, {}};
}

}  // namespace raygrade
