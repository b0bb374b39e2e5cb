// The class report on classes the test makes up: 200 students, each problem of the bank's
// variant set (every kind students answer with numbers), some answers right, some with a named
// mistake planted, some with a mistake nobody named, some random. The planted answers are
// worked out here by hand from each variant's parameters, not by raygrade.
#include "reports/class_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <set>

#include "grading/discover.h"
#include "grading/grade.h"
#include "problems/problem.h"

namespace raygrade {
// Named rather than anonymous: a unity batch of tests shares one anonymous namespace.
namespace class_report_test {

using nlohmann::json;

// What a planted answer is.
struct Planted {
  std::string label;  // "right", "noise", a catalogue id, or "change:<step>"
  json answer;
};

double p(const ParameterValues& v, const char* name) { return v.at(name).get<double>(); }

// Students round to four decimals.
double r4(double x) { return std::round(x * 1e4) / 1e4; }
json vec3(double x, double y, double z) { return json::array({r4(x), r4(y), r4(z)}); }

json hit(double t, json point) { return {{"t", r4(t)}, {"point", std::move(point)}}; }

// Each problem's answers by hand. `kind` 0: right, 1: a named mistake, 2: a mistake nobody
// named. Returns the label and the answer; an empty label when the problem has no such mistake
// for these numbers.
Planted sphere(const ParameterValues& v, int kind) {
  double ox = p(v, "ox"), cz = p(v, "cz"), dz = p(v, "dz"), s = std::sqrt(25 - ox * ox);
  if (kind == 0)
    return {"right",
            {{"hits",
              {hit((cz - s) / dz, vec3(ox, 0, cz - s)), hit((cz + s) / dz, vec3(ox, 0, cz + s))}}}};
  if (kind == 1) {
    // t measured along D/|D|: t·|D| for t, the points unchanged (only when |D| ≠ 1).
    if (dz == 1) return {"", {}};
    return {"unit-direction-t",
            {{"hits", {hit(cz - s, vec3(ox, 0, cz - s)), hit(cz + s, vec3(ox, 0, cz + s))}}}};
  }
  // t_hc = r² − d² (the square root forgotten); d² = ox², so t_hc = 25 − ox².
  double h = 25 - ox * ox;
  return {"change:t_hc",
          {{"hits",
            {hit((cz - h) / dz, vec3(ox, 0, cz - h)), hit((cz + h) / dz, vec3(ox, 0, cz + h))}}}};
}

Planted plane(const ParameterValues& v, int kind) {
  double ox = p(v, "ox"), dx = p(v, "dx"), dy = p(v, "dy"), h = p(v, "h");
  if (kind == 1) return {"", {}};
  // t = numerator/denominator = h/dy; written the other way round, t = dy/h.
  double t = kind == 0 ? h / dy : dy / h;
  return {kind == 0 ? "right" : "change:t", {{"hits", {hit(t, vec3(ox + dx * t, dy * t, 1))}}}};
}

Planted triangle(const ParameterValues& v, int kind) {
  double px = p(v, "px"), py = p(v, "py"), z = p(v, "z");
  if (kind == 1) return {"", {}};
  // n·(O − a) for n·(a − O): t = −z, behind the origin.
  double t = kind == 0 ? z : -z;
  return {kind == 0 ? "right" : "change:numerator", {{"hits", {hit(t, vec3(px, py, t))}}}};
}

Planted camera(const ParameterValues& v, int kind) {
  double x = p(v, "x"), y = p(v, "y"), f = p(v, "f");
  json origin = vec3(0, 0, 0);
  // An 8 × 6 image, looking along −z with up +y: d × u = +x.
  if (kind == 0)
    return {"right",
            {{"ray", {{"origin", origin}, {"direction", vec3(x + 0.5 - 4, y + 0.5 - 3, -f)}}}}};
  if (kind == 1)
    return {"pixel-corner", {{"ray", {{"origin", origin}, {"direction", vec3(x - 4, y - 3, -f)}}}}};
  // f·d left out of d_r: the direction lies in the image plane.
  return {"change:d_r",
          {{"ray", {{"origin", origin}, {"direction", vec3(x + 0.5 - 4, y + 0.5 - 3, 0)}}}}};
}

Planted reflect(const ParameterValues& v, int kind) {
  double dx = p(v, "dx"), dy = p(v, "dy");
  if (kind == 1) return {"", {}};
  // d = (dx, −dy, 0), n = (0, 1, 0): r = d − 2(d·n)n = (dx, dy, 0); with + instead,
  // r = (dx, −3dy, 0).
  return {kind == 0 ? "right" : "change:r",
          {{"direction", kind == 0 ? vec3(dx, dy, 0) : vec3(dx, -3 * dy, 0)}}};
}

Planted refract(const ParameterValues& v, int kind) {
  double dx = p(v, "dx"), n2 = p(v, "n2"), eta = 1 / n2;
  if (kind == 1) return {"", {}};
  double len = std::sqrt(dx * dx + 1), cos_i = 1 / len, k = 1 - eta * eta * (1 - cos_i * cos_i);
  // t = η·d̂ + (η·cos θi − √k)·n̂ with d̂ = d/‖d‖; with d itself for d̂: cos θi = 1, k = 1,
  // t = η·d + (η − 1)·n = (η·dx, −1, 0).
  json dir = kind == 0 ? vec3(eta * dx / len, -eta / len + (eta * cos_i - std::sqrt(k)), 0)
                       : vec3(eta * dx, -1, 0);
  return {kind == 0 ? "right" : "change:d_hat",
          {{"total_internal_reflection", false}, {"direction", dir}}};
}

Planted shade(const ParameterValues& v, int kind) {
  double lx = p(v, "lx"), kd = p(v, "kd"), len = std::sqrt(lx * lx + 16);
  // N = (0, 1, 0), L = (lx, 4, 0)/len, R = 2(N·L)N − L = (−lx, 4, 0)/len, V = (−0.6, 0.8, 0).
  double nl = 4 / len, rv = (0.6 * lx + 3.2) / len;
  double ambient = 0.1 * 2, diffuse = kd * nl, specular = 0.3 * std::pow(rv, 12);
  if (kind == 0) return {"right", {{"intensity", r4(ambient + diffuse + specular)}}};
  if (kind == 1) return {"", {}};  // the shade kind names no mistake of the catalogue
  // The ambient term left out of the sum.
  return {"change:I", {{"intensity", r4(diffuse + specular)}}};
}

Planted first_hit(const ParameterValues& v, int kind) {
  double a = p(v, "a"), b = p(v, "b");
  // Sphere A: radius 1 at (a, 0, 0); sphere B: radius 2 at (b, 0, 0); the ray runs along +x.
  if (a - 1 == b - 2 || kind == 2) return {"", {}};
  bool first_a = a - 1 < b - 2;
  double t = kind == 0 ? (first_a ? a - 1 : b - 2) : (first_a ? a + 1 : b + 2);
  return {kind == 0 ? "right" : "far-root",
          {{"object", first_a ? "sphere A" : "sphere B"}, {"hits", {hit(t, vec3(t, 0, 0))}}}};
}

using Maker = Planted (*)(const ParameterValues&, int);
const std::map<std::string, Maker>& makers() {
  static const std::map<std::string, Maker> m = {
      {"variant-sphere", &sphere},     {"variant-plane", &plane},
      {"variant-triangle", &triangle}, {"variant-camera-ray", &camera},
      {"variant-reflect", &reflect},   {"variant-refract", &refract},
      {"variant-shade", &shade},       {"variant-first-hit", &first_hit}};
  return m;
}

// Every number of `j` drawn anew within 3 of itself, rounded to two decimals.
json noise(const json& j, std::mt19937_64& rng) {
  if (j.is_object() || j.is_array()) {
    json out = j;
    for (auto& [k, v] : out.items()) v = noise(v, rng);
    return out;
  }
  if (!j.is_number()) return j;
  std::uniform_real_distribution<double> u(-3, 3);
  return std::round((j.get<double>() + u(rng)) * 100) / 100;
}

struct Class {
  Bank bank;
  std::vector<std::unique_ptr<Problem>> variants;
  std::map<std::string, std::unique_ptr<Grader>> graders;
  ClassInput input;
  std::map<std::string, std::string> label;  // "problem/student" → what was planted
};

const Grader& grader_for(Class& c, const Problem& variant) {
  std::string key = variant.id + json(variant.values).dump();
  auto& g = c.graders[key];
  if (!g) g = std::make_unique<Grader>(variant);
  return *g;
}

// A class of `students`, drawn from `seed`.
void make_class(Class& c, int students, std::uint64_t seed) {
  c.bank = load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems/variants.json"});
  std::vector<const Problem*> problems;
  for (const auto& pr : c.bank.problems)
    if (makers().count(pr.id)) problems.push_back(&pr);
  ASSERT_EQ(problems.size(), makers().size());
  for (const Problem* pr : problems) {
    c.input.problem_ids.push_back(pr->id);
    c.input.problem_titles.push_back(pr->title);
  }
  std::mt19937_64 rng(seed);
  for (int s = 0; s < students; ++s) {
    ClassStudent st{fmt::format("s{:03}", s), "", "", {}};
    for (const Problem* pr : problems) {
      ParameterValues values;
      for (const auto& par : pr->parameters->parameters)
        values[par.name] =
            par.value(std::uniform_int_distribution<std::uint64_t>(0, par.size() - 1)(rng));
      c.variants.push_back(std::make_unique<Problem>(read_problem_variant(*pr, values)));
      const Problem& variant = *c.variants.back();
      int roll = std::uniform_int_distribution<int>(0, 99)(rng);
      int kind = roll < 35 ? 0 : roll < 55 ? 1 : roll < 80 ? 2 : 3;
      Maker make = makers().at(pr->id);
      Planted planted = make(values, kind == 3 ? 0 : kind);
      if (planted.label.empty()) planted = make(values, 0);
      if (kind == 3 && !planted.label.empty()) planted = {"noise", noise(planted.answer, rng)};
      // Two spheres entered at the same t: either is first, and the student leaves it blank.
      bool blank = planted.label.empty();
      ClassAnswer a{blank ? grader_for(c, variant).unanswered()
                          : grader_for(c, variant).grade(planted.answer),
                    planted.answer, &variant};
      if (blank) planted.label = "right";
      c.label[pr->id + "/" + st.id] = planted.label;
      st.answers.push_back(std::move(a));
    }
    c.input.students.push_back(std::move(st));
  }
}

TEST(ClassReport, PlantedMistakesAreFoundAndNoiseIsNotClaimed) {
  Class c;
  make_class(c, 200, 20261126);
  json report = class_report_json(c.input, 2);
  // Where each student's answer landed: "mistake:<id>", "change:<step>" or "unexplained".
  std::map<std::string, std::string> landed;
  std::map<std::string, json> group_of;
  for (const auto& pr : report["problems"]) {
    for (const auto& g : pr["groups"]) {
      std::string where = !g["mistake"].is_null() ? "mistake:" + g["mistake"].get<std::string>()
                          : !g["discovered"].is_null() ? "change"
                                                       : "unexplained";
      for (const auto& s : g["students"]) {
        landed[pr["id"].get<std::string>() + "/" + s.get<std::string>()] = where;
        group_of[pr["id"].get<std::string>() + "/" + s.get<std::string>()] = g;
      }
    }
  }
  std::map<std::string, std::pair<int, int>> recall;  // label → found, planted
  std::map<std::string, std::string> misses;          // label → where a few of the rest went
  int noise = 0, noise_claimed = 0;
  for (const auto& [key, label] : c.label) {
    std::string problem = key.substr(0, key.find('/'));
    if (label == "right") {
      EXPECT_EQ(landed.count(key), 0u) << key << " is right but was grouped";
      continue;
    }
    if (label == "noise") {
      ++noise;
      noise_claimed += landed.count(key) && landed[key] == "change";
      continue;
    }
    auto& [found, planted] = recall[problem + " " + label];
    ++planted;
    int before = found;
    auto miss = [&] {
      if (found == before && misses[problem + " " + label].size() < 600)
        misses[problem + " " + label] +=
            " | " + (landed.count(key) ? group_of[key].dump() : "not grouped");
    };
    if (!landed.count(key)) {
      miss();
      continue;
    }
    if (label.starts_with("change:")) {
      // The group's change, or one that gives the same numbers, is in the planted step.
      const json& d = group_of[key]["discovered"];
      if (d.is_null()) {
        miss();
        continue;
      }
      std::string step = label.substr(7);
      bool in_step = d["step"] == step;
      for (const auto& e : d["equivalent"])
        in_step = in_step || e.get<std::string>().starts_with(step + " = ");
      found += in_step;
    } else {
      found += landed[key] == "mistake:" + label;
    }
    miss();
  }
  int found_all = 0, planted_all = 0;
  for (const auto& [label, fp] : recall) {
    found_all += fp.first;
    planted_all += fp.second;
    // Per mistake a little less than in all: the grader's own readings are tried first, and a
    // few planted answers fall on one of them (t_hc without the root can give the numbers the
    // b-sign reading names; a far root of first-hit that lies past the other sphere reads as
    // another object's hit).
    EXPECT_GE(fp.first, 0.75 * fp.second)
        << label << ": " << fp.first << " of " << fp.second << misses[label];
  }
  for (const auto& [label, fp] : recall)
    std::cout << label << ": " << fp.first << " of " << fp.second << " grouped by it\n";
  std::cout << "planted: " << found_all << " of " << planted_all
            << "; noise claimed by a change: " << noise_claimed << " of " << noise << "\n";
  EXPECT_GE(found_all, 0.9 * planted_all) << found_all << " of " << planted_all;
  EXPECT_LE(noise_claimed, 0.05 * noise) << noise_claimed << " of " << noise;
  EXPECT_GT(noise, 100);
  EXPECT_GT(planted_all, 400);
}

// The plane of the bank's defaults: O = (1, 0, 1), R = (1, 2, 0), the plane y = 5, so t = 5/2
// and P = (3.5, 5, 1). Written dy/h, t = 2/5 = 0.4 and P = (1.4, 0.8, 1).
TEST(ChangeSearch, ExplainsAnAnswerByOneChangeAndNotTheRightOne) {
  Bank bank = load_bank({std::string(RAYGRADE_SOURCE_DIR) + "/problems/variants.json"});
  auto it = std::find_if(bank.problems.begin(), bank.problems.end(),
                         [](const Problem& p) { return p.id == "variant-plane"; });
  ASSERT_NE(it, bank.problems.end());
  ChangeSearch search(*it);
  Discovery d = search.explain(json{{"hits", {{{"t", 0.4}, {"point", {1.4, 0.8, 1}}}}}});
  EXPECT_EQ(d.verdict, Discovery::Verdict::kExplained) << to_string(d.verdict);
  ASSERT_FALSE(d.changes.empty());
  EXPECT_EQ(d.changes.front().step, "t");
  EXPECT_EQ(search.explain(json{{"hits", {{{"t", 2.5}, {"point", {3.5, 5, 1}}}}}}).verdict,
            Discovery::Verdict::kNone);
  EXPECT_EQ(search.explain(json{{"hits", {{{"t", 7.123}, {"point", {8.123, 14.246, 1}}}}}}).verdict,
            Discovery::Verdict::kNone);
  // t alone is one number: with relative 0.1% each change is fitted by a random t within 2.5
  // of 2.5 with a chance of 0.0025/2.5 = 0.1% (more for a larger changed t), and there are
  // dozens of changes. t = 0.4 alone is fitted by t = dy/h and by others giving 0.4.
  Discovery alone = search.explain(json{{"hits", {{{"t", 0.4}}}}});
  EXPECT_GT(alone.random_fit, 0.001);
}

}  // namespace class_report_test
}  // namespace raygrade
