// Every number an answer can hold is computed by the worked derivation from the problem's
// inputs: on every problem of the bundled bank, every kind of the table, no step's value is
// given unless the problem gives it, no computed step is a bare literal, and every number of
// the reference answer is the value of a computed step. A quantity the derivation takes as
// given is one no change of a formula can reach, so no mistake in it can be found.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "problems/kind.h"
#include "problems/problem.h"

namespace raygrade {
namespace derivation_reach_test {

using nlohmann::json;

constexpr double kSame = 1e-9;  // relative: far above rounding, far below any slip

bool same_scalar(double a, double b) {
  return std::abs(a - b) <= kSame * std::max(1.0, std::max(std::abs(a), std::abs(b)));
}

bool same_vector(const Vec3d& a, const Vec3d& b) {
  return same_scalar(a.x, b.x) && same_scalar(a.y, b.y) && same_scalar(a.z, b.z);
}

bool is_triple(const json& j) {
  return j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number();
}

// The keys of a problem that are not its inputs: how it is graded and shown.
bool not_an_input(const std::string& key) {
  static const std::set<std::string> kKeys = {"id",       "title",     "statement", "expected",
                                              "tests",    "points",    "tolerance", "precision",
                                              "mistakes", "parameters"};
  return kKeys.contains(key);
}

// The numbers (a flag counts as 0 or 1) and the triples the problem gives.
void collect_inputs(const json& j, std::vector<double>& numbers, std::vector<Vec3d>& triples) {
  if (j.is_number()) numbers.push_back(j.get<double>());
  if (j.is_boolean()) numbers.push_back(j.get<bool>() ? 1 : 0);
  if (is_triple(j))
    triples.emplace_back(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
  if (j.is_array()) {
    for (const auto& x : j) collect_inputs(x, numbers, triples);
  }
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) {
      if (!not_an_input(k)) collect_inputs(v, numbers, triples);
    }
  }
}

// The numbers of an answer with their paths: a triple is one value (a point, a direction, a
// colour), a flag and a name are not numbers.
void collect_answer(const json& j, const std::string& at,
                    std::vector<std::pair<std::string, Value>>& out) {
  if (j.is_number()) {
    out.emplace_back(at, Value(j.get<double>()));
  } else if (is_triple(j)) {
    out.emplace_back(at, Value(Vec3d{j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}));
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      collect_answer(j[i], fmt::format("{}/{}", at, i), out);
  } else if (j.is_object()) {
    for (const auto& [k, v] : j.items()) collect_answer(v, fmt::format("{}/{}", at, k), out);
  }
}

bool mentions_any_symbol(const E& e) {
  if (e.empty()) return false;
  if (e.node().op == Op::kSymbol) return true;
  for (const auto& a : e.node().args) {
    if (mentions_any_symbol(a)) return true;
  }
  return false;
}

bool matches(const Value& a, const Value& b) {
  if (a.is_scalar() && b.is_scalar()) return same_scalar(a.scalar, b.scalar);
  if (a.is_vector() && b.is_vector()) return same_vector(a.vector, b.vector);
  return false;
}

// What is wrong with one problem's derivations, one line each.
std::vector<std::string> faults(const Problem& p) {
  std::vector<std::string> out;
  std::vector<double> numbers;
  std::vector<Vec3d> triples;
  collect_inputs(p.source, numbers, triples);
  // 0 and 1: a flag's two values, and the default of a key left out (an intensity of 1, a
  // light not blocked).
  numbers.push_back(0);
  numbers.push_back(1);
  auto is_input = [&](const Value& v) {
    if (v.is_scalar()) {
      for (double x : numbers) {
        if (same_scalar(x, v.scalar)) return true;
      }
      return false;
    }
    if (v.is_vector()) {
      for (const auto& t : triples) {
        if (same_vector(t, v.vector)) return true;
      }
      // A number given for a colour: [1, 1, 1] for an intensity of 1.
      auto given = [&](double c) {
        for (double x : numbers) {
          if (same_scalar(x, c)) return true;
        }
        return false;
      };
      return given(v.vector.x) && given(v.vector.y) && given(v.vector.z);
    }
    return true;  // a verdict given (a flag of the problem)
  };
  std::vector<SolutionPart> parts = p.task->derive("", nullptr);
  // The values the derivation computes (in any part: a first hit's selection takes each
  // object's nearest t from that object's part).
  std::vector<Value> computed;
  for (const auto& part : parts) {
    for (const auto& s : part.derivation.steps) {
      if (!s.given) computed.push_back(s.value);
    }
  }
  auto is_computed = [&](const Value& v) {
    for (const auto& c : computed) {
      if (matches(c, v)) return true;
    }
    return false;
  };
  for (const auto& part : parts) {
    for (const auto& s : part.derivation.steps) {
      if (s.given) {
        if (!is_input(s.value) && !is_computed(s.value)) {
          out.push_back(fmt::format("step {} is given as {}, which the problem does not give",
                                    s.name, value_text(s.value)));
        }
      } else if (!mentions_any_symbol(s.formula)) {
        out.push_back(fmt::format("step {} = {} is a literal, not computed from the givens", s.name,
                                  to_text(s.formula)));
      }
    }
  }
  std::vector<std::pair<std::string, Value>> answer;
  collect_answer(p.task->answer(), "", answer);
  // An answer may restate an input (a camera's eye as its ray's origin): a given step has it.
  auto restates_input = [&](const Value& v) {
    for (const auto& part : parts) {
      for (const auto& s : part.derivation.steps) {
        if (s.given && is_input(s.value) && matches(s.value, v)) return true;
      }
    }
    return false;
  };
  for (const auto& [at, v] : answer) {
    if (!is_computed(v) && !restates_input(v)) {
      out.push_back(
          fmt::format("the answer's {} = {} has no step computing it", at, value_text(v)));
    }
  }
  return out;
}

// What the derivations do not compute yet, by kind and a piece of the fault: each entry must
// still be found (so that the list shrinks as derivations are completed), and nothing else.
struct Gap {
  std::string kind;
  std::string fault;  // a piece of the fault's line
  std::string why;
};
const std::vector<Gap>& known_gaps() {
  static const std::vector<Gap> gaps = {
      {"ray-tree", "", "a tree's hits, intensities and counts are taken from the traced tree"},
      {"intersect", "Minv", "a transformed object's inverse matrix is given, not computed"},
      {"normal", "Minv", "a transformed object's inverse matrix is given, not computed"},
      {"intersect", "/normal", "a hit's normal is worked only in the step answers' shape"},
      {"shade", "P_o", "a pattern's point in object space is given"},
      {"shade", "P_pat", "a pattern's point in pattern space is given"},
      {"shade", "step shininess", "a material's default exponent (10) is given"},
      {"intersect", "crossings", "a polygon's crossings are counted, not a formula"},
      {"intersect", "_obj is given", "a transformed object's normal in its space is given"},
      {"intersect", "step px is given", "the ray in a transformed object's space is given"},
      {"intersect", "step o_y is given", "the ray in a transformed object's space is given"},
      {"shade", "step r = ", "a ring's radius is worked from the pattern point's numbers"},
  };
  return gaps;
}

TEST(DerivationReach, EveryKindComputesEveryNumberOfItsAnswer) {
  Bank bank = load_bank({RAYGRADE_SOURCE_DIR "/problems"});
  ASSERT_TRUE(bank.errors.empty());
  std::map<std::string, int> walked;
  for (const auto& k : kind_table()) walked[std::string(k.name)] = 0;
  std::vector<int> seen(known_gaps().size(), 0);
  for (const auto& p : bank.problems) {
    ++walked[p.kind];
    for (const auto& f : faults(p)) {
      bool known = false;
      for (std::size_t i = 0; i < known_gaps().size(); ++i) {
        const Gap& g = known_gaps()[i];
        if (g.kind == p.kind && f.find(g.fault) != std::string::npos) {
          ++seen[i];
          known = true;
          break;
        }
      }
      if (!known) ADD_FAILURE() << p.kind << " " << p.id << ": " << f;
    }
  }
  for (const auto& [kind, n] : walked) {
    EXPECT_GT(n, 0) << "the bundled bank has no problem of the kind " << kind;
  }
  for (std::size_t i = 0; i < known_gaps().size(); ++i) {
    EXPECT_GT(seen[i], 0) << "no longer a gap (remove it from the list): " << known_gaps()[i].kind
                          << " " << known_gaps()[i].fault;
  }
}

}  // namespace derivation_reach_test
}  // namespace raygrade
