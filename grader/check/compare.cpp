// Answer comparison for the bank check.
#include "check/compare.h"

#include <algorithm>
#include <cmath>

#include "derivation/number_format.h"
#include "json/cursor.h"
#include "kinds/part_names.h"

namespace raygrade {
namespace {

using json = nlohmann::json;

// Answer keys that the reference leaves out when they are false: a stated `false` matches
// their absence.
bool defaults_to_false(const std::string& key) { return key == "contained" || key == "tie"; }

std::string show(const json& v) {
  if (v.is_number()) return format_number(v.get<double>(), NumberFormat{6, -1});
  if (v.is_array() && v.size() == 3 && v[0].is_number()) {
    return format_vector({v[0].get<double>(), v[1].get<double>(), v[2].get<double>()},
                         NumberFormat{6, -1});
  }
  return v.dump();
}

const char* json_type(const json& v) {
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "true or false";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  return "null";
}

struct Comparer {
  const CompareTolerance& tolerance;
  const std::function<double(const std::string&)>& half_unit;
  std::vector<Mismatch> out;

  void add(const std::string& path, std::string message, std::string code = "wrong-expected") {
    out.push_back(Mismatch{path, std::move(message), std::move(code)});
  }

  void compare(const json& s, const json& r, const std::string& path) {
    if (s.is_number() && r.is_number()) {
      double sv = s.get<double>(), rv = r.get<double>();
      double allowed = std::max(tolerance.at(rv), half_unit(path)) +
                       kRoundingSlack * std::max(1.0, std::abs(rv));
      if (!(std::abs(sv - rv) <= allowed)) {
        add(path,
            fmt::format("states {}, the reference answer is {} (off by {}; the tolerance "
                        "and the digits stated allow {})",
                        show(s), show(r), show(json(std::abs(sv - rv))), show(json(allowed))));
      }
      return;
    }
    if (s.is_object() && r.is_object()) {
      std::vector<std::string> keys;
      for (const auto& [k, v] : r.items()) keys.push_back(k);
      for (const auto& [k, v] : s.items()) {
        std::string sub = path + "/" + pointer_token(k);
        if (r.contains(k)) {
          compare(v, r[k], sub);
        } else if (defaults_to_false(k)) {
          compare(v, json(false), sub);
        } else {
          std::string hint = closest_match(k, keys);
          add(sub,
              hint.empty() ? fmt::format("unknown answer key '{}'", k)
                           : fmt::format("unknown answer key '{}' (did you mean '{}'?)", k, hint),
              "unknown-key");
        }
      }
      return;
    }
    if (s.is_array() && r.is_array()) {
      if (s.size() != r.size()) {
        bool hits = path.size() >= 5 && path.compare(path.size() - 5, 5, "/hits") == 0;
        // not a part: the words of the message
        std::string what = hits ? (s.size() == 1 ? "hit" : "hits") : "entries";
        add(path, r.empty()
                      ? fmt::format("lists {} {}, the reference answer has none", s.size(), what)
                      : fmt::format("lists {} {}, the reference answer has {}: {}", s.size(), what,
                                    r.size(), describe_list(r)));
      }
      for (std::size_t i = 0; i < std::min(s.size(), r.size()); ++i) {
        compare(s[i], r[i], fmt::format("{}/{}", path, i));
      }
      return;
    }
    if (s.type() != r.type() && !(s.is_number() && r.is_number())) {
      if (r.is_null() || s.is_null() || s.is_boolean() == r.is_boolean()) {
        if (s != r)
          add(path, fmt::format("states {}, the reference answer is {}", show(s), show(r)));
        return;
      }
      add(path, fmt::format("expected {} here, found {}", json_type(r), json_type(s)), "type");
      return;
    }
    if (s != r) add(path, fmt::format("states {}, the reference answer is {}", show(s), show(r)));
  }

  static std::string describe_list(const json& list) {
    if (list.empty()) return "none";
    std::vector<std::string> parts;
    for (const auto& item : list) {
      if (item.is_object() && item.contains(part_names::kT)) {
        parts.push_back("t = " + show(item[part_names::kT]));
      } else {
        parts.push_back(show(item));
      }
    }
    return fmt::format("{}", fmt::join(parts, ", "));
  }
};

void outcome_into(const json& a, std::string& out) {
  if (a.is_number()) {
    out += '#';
  } else if (a.is_object()) {
    out += '{';
    for (const auto& [k, v] : a.items()) {
      out += k;
      out += ':';
      outcome_into(v, out);
      out += ',';
    }
    out += '}';
  } else if (a.is_array()) {
    out += '[';
    for (const auto& v : a) {
      outcome_into(v, out);
      out += ',';
    }
    out += ']';
  } else {
    out += a.dump();
  }
}

}  // namespace

double CompareTolerance::at(double reference) const {
  return std::max(absolute, relative * std::abs(reference));
}

std::vector<Mismatch> compare_stated(const json& stated, const json& reference,
                                     const CompareTolerance& tolerance,
                                     const std::function<double(const std::string&)>& half_unit) {
  Comparer c{tolerance, half_unit, {}};
  c.compare(stated, reference, "");
  return std::move(c.out);
}

std::string answer_outcome(const json& answer) {
  std::string out;
  outcome_into(answer, out);
  return out;
}

double answer_difference(const json& a, const json& b) {
  if (a.is_number() && b.is_number()) return std::abs(a.get<double>() - b.get<double>());
  double worst = 0;
  if (a.is_object() && b.is_object()) {
    for (const auto& [k, v] : a.items()) {
      if (b.contains(k)) worst = std::max(worst, answer_difference(v, b[k]));
    }
  } else if (a.is_array() && b.is_array()) {
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
      worst = std::max(worst, answer_difference(a[i], b[i]));
    }
  }
  return worst;
}

double answer_magnitude(const json& answer) {
  if (answer.is_number()) return std::abs(answer.get<double>());
  double m = 0;
  if (answer.is_structured()) {
    for (const auto& v : answer) m = std::max(m, answer_magnitude(v));
  }
  return m;
}

std::string describe_answer(const json& answer) {
  if (!answer.is_object()) return show(answer);
  std::string prefix;
  if (answer.contains(part_names::kObject)) {
    if (answer[part_names::kObject].is_null()) return "no object hit";
    prefix = answer[part_names::kObject].is_string()
                 ? answer[part_names::kObject].get<std::string>() + ", "
                 : "";
  }
  if (answer.contains("hits") && answer["hits"].is_array()) {
    const json& hits = answer["hits"];
    if (hits.empty()) return answer.value("contained", false) ? "contained in the plane" : "no hit";
    std::string ts = Comparer::describe_list(hits);
    return prefix + (hits.size() == 1 ? fmt::format("1 hit ({})", ts)
                                      : fmt::format("{} hits ({})", hits.size(), ts));
  }
  if (answer.contains(part_names::kRay) && answer[part_names::kRay].is_object() &&
      answer[part_names::kRay].contains(part_names::kDirection)) {
    return "direction " + show(answer[part_names::kRay][part_names::kDirection]);
  }
  std::string text = answer.dump();
  return text.size() <= 60 ? text : "(see raygrade solve)";
}

}  // namespace raygrade
