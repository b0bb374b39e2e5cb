// The class report as JSON: scores, shares, mistakes, groups of wrong answers, fairness and
// discrimination, per problem.
#include "reports/class_report.h"

#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "core/error.h"
#include "core/parallel.h"
#include "grading/discover.h"
#include "grading/mistakes.h"

namespace raygrade {
// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace class_report_internal {

using nlohmann::json;

// Report numbers carry three decimals: more than a class's mean needs, and the page shows
// them as they are.
double rounded(double x) { return std::round(x * 1000) / 1000; }

bool full_marks(const GradeResult& r) { return r.max_score > 0 && r.score >= r.max_score - 1e-9; }

json histogram(const std::vector<double>& fractions) {
  std::vector<int> counts(kHistogramBins, 0);
  for (double f : fractions) {
    int bin = static_cast<int>(std::floor(f * kHistogramBins));
    ++counts[std::clamp(bin, 0, kHistogramBins - 1)];
  }
  return counts;
}

json shares(int right, int partly, int wrong, int blank) {
  double n = std::max(1, right + partly + wrong + blank);
  return {{"right", rounded(right / n)},
          {"partly", rounded(partly / n)},
          {"wrong", rounded(wrong / n)},
          {"blank", rounded(blank / n)}};
}

// Scores, histogram and shares of one part over the class.
json part_json(const std::vector<const ClassAnswer*>& answers, const std::string& name) {
  double sum = 0, max_points = 0;
  int counts[4] = {0, 0, 0, 0};  // right, partly, wrong, blank
  std::vector<double> fractions;
  for (const ClassAnswer* a : answers) {
    const PartResult* part = nullptr;
    for (const auto& p : a->result.parts)
      if (p.name == name) part = &p;
    if (!part) {
      ++counts[3];
      fractions.push_back(0);
      continue;
    }
    max_points = std::max(max_points, part->max_points);
    sum += part->points;
    fractions.push_back(part->max_points > 0 ? part->points / part->max_points : 0);
    switch (part->status) {
      case PartStatus::kRight: ++counts[0]; break;
      case PartStatus::kPartial: ++counts[1]; break;
      case PartStatus::kWrong: ++counts[2]; break;
      case PartStatus::kMissing: ++counts[3]; break;
    }
  }
  double n = std::max<std::size_t>(1, answers.size());
  return {{"students", answers.size()},
          {"max_points", rounded(max_points)},
          {"mean", rounded(sum / n)},
          {"histogram", histogram(fractions)},
          {"shares", shares(counts[0], counts[1], counts[2], counts[3])}};
}

std::string mistake_title(const std::string& id) {
  for (const auto& m : mistake_catalogue())
    if (m.id == id) return std::string(m.title);
  return id;
}

// Every named mistake found, by count, with its students.
json mistakes_json(const ClassInput& in, std::size_t p) {
  std::map<std::string, std::vector<std::string>> by_id;
  for (const auto& s : in.students) {
    std::set<std::string> ids;
    for (const auto& m : s.answers[p].result.mistakes) ids.insert(m.id);
    for (const auto& id : ids) by_id[id].push_back(s.id);
  }
  json out = json::array();
  for (auto& [id, students] : by_id)
    out.push_back({{"id", id},
                   {"title", mistake_title(id)},
                   {"count", students.size()},
                   {"students", students}});
  std::stable_sort(out.begin(), out.end(),
                   [](const json& a, const json& b) { return a["count"] > b["count"]; });
  return out;
}

// The mean fraction per value of each parameter, and the values much harder than the rest.
json fairness_json(const ClassInput& in, std::size_t p) {
  std::map<std::string, std::map<std::string, std::pair<double, int>>> by;  // name → value → sum, n
  for (const auto& s : in.students) {
    const ClassAnswer& a = s.answers[p];
    if (!a.variant || a.result.max_score <= 0) continue;
    for (const auto& [name, value] : a.variant->values) {
      auto& cell = by[name][value.dump()];
      cell.first += a.result.score / a.result.max_score;
      ++cell.second;
    }
  }
  json out = json::array();
  for (const auto& [name, values] : by) {
    double total = 0;
    int n = 0;
    for (const auto& [v, c] : values) total += c.first, n += c.second;
    json rows = json::array();
    for (const auto& [v, c] : values) {
      double mean = c.first / c.second;
      double others = n > c.second ? (total - c.first) / (n - c.second) : mean;
      bool harder = c.second >= kMinFairnessStudents && others - mean >= kFairnessGap;
      rows.push_back({{"value", json::parse(v)},
                      {"students", c.second},
                      {"mean", rounded(mean)},
                      {"harder", harder}});
    }
    out.push_back({{"parameter", name}, {"values", rows}});
  }
  return out;
}

// The point-biserial correlation of full marks on problem p with the rest of the assignment's
// score; null when everyone or no one has full marks, or the rest does not vary.
json discrimination(const ClassInput& in, std::size_t p) {
  std::vector<double> rest;
  std::vector<bool> right;
  for (const auto& s : in.students) {
    double r = 0;
    for (std::size_t q = 0; q < s.answers.size(); ++q)
      if (q != p) r += s.answers[q].result.score;
    rest.push_back(r);
    right.push_back(full_marks(s.answers[p].result));
  }
  double n = rest.size(), mean = 0, m1 = 0, n1 = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    mean += rest[i] / n;
    if (right[i]) m1 += rest[i], ++n1;
  }
  double var = 0, m0 = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    var += (rest[i] - mean) * (rest[i] - mean) / n;
    if (!right[i]) m0 += rest[i];
  }
  if (n1 == 0 || n1 == n || var <= 0) return nullptr;
  m1 /= n1;
  m0 /= n - n1;
  double share = n1 / n;
  return rounded((m1 - m0) / std::sqrt(var) * std::sqrt(share * (1 - share)));
}

std::string variant_key(const ClassAnswer& a) {
  return a.variant->id + "\n" + json(a.variant->values).dump();
}

// One wrong answer and how it is grouped.
struct Wrong {
  std::size_t student;
  std::string key;  // the group
  Discovery discovery;
};

// The changes that explain each answer, the search run once per variant.
void discover(const ClassInput& in, std::size_t p, std::vector<Wrong>& wrong, unsigned jobs) {
  std::vector<std::string> keys;
  std::map<std::string, std::shared_ptr<const ChangeSearch>> searches;
  for (const auto& w : wrong) {
    const ClassAnswer& a = in.students[w.student].answers[p];
    if (w.key.empty() && a.variant && searches.emplace(variant_key(a), nullptr).second)
      keys.push_back(variant_key(a));
  }
  std::map<std::string, const Problem*> variant_of;
  for (const auto& w : wrong) {
    const ClassAnswer& a = in.students[w.student].answers[p];
    if (a.variant) variant_of.emplace(variant_key(a), a.variant);
  }
  auto built = parallel_map<std::shared_ptr<const ChangeSearch>>(
      keys.size(), jobs, [&](std::size_t i) -> std::shared_ptr<const ChangeSearch> {
        try {
          return std::make_shared<const ChangeSearch>(*variant_of.at(keys[i]));
        } catch (const Error&) {
          return nullptr;  // a derivation that cannot be worked: nothing to search
        }
      });
  for (std::size_t i = 0; i < keys.size(); ++i) searches[keys[i]] = built[i];
  std::map<std::string, int> popularity;
  for (auto& w : wrong) {
    const ClassAnswer& a = in.students[w.student].answers[p];
    if (!w.key.empty() || !a.variant || !searches[variant_key(a)]) continue;
    w.discovery = searches[variant_key(a)]->explain(a.answer);
    for (const auto& c : w.discovery.changes) ++popularity[c.key()];
  }
  // Of the changes that agree on an answer, the one that explains the most answers names it.
  for (auto& w : wrong) {
    if (!w.key.empty()) continue;
    if (w.discovery.verdict != Discovery::Verdict::kExplained) {
      w.key = std::string("unexplained:") + to_string(w.discovery.verdict);
      continue;
    }
    const StepChange* best = &w.discovery.changes.front();
    for (const auto& c : w.discovery.changes)
      if (popularity[c.key()] > popularity[best->key()]) best = &c;
    w.key = "change:" + best->key();
    std::swap(w.discovery.changes.front(), w.discovery.changes[best - &w.discovery.changes[0]]);
  }
}

std::string unexplained_note(const std::string& key) {
  if (key == "unexplained:ambiguous")
    return "several single changes fit each of these answers, giving different numbers: none "
           "is claimed";
  if (key == "unexplained:noisy")
    return "the changes of these variants fit too many random answers to claim any";
  return "no single change of the derivation reproduces these answers";
}

json groups_json(const ClassInput& in, std::size_t p, unsigned jobs) {
  std::vector<Wrong> wrong;
  for (std::size_t s = 0; s < in.students.size(); ++s) {
    const GradeResult& r = in.students[s].answers[p].result;
    if (!r.answered || full_marks(r) || r.max_score <= 0) continue;
    wrong.push_back({s, r.mistakes.empty() ? "" : "mistake:" + r.mistakes.front().id, {}});
  }
  discover(in, p, wrong, jobs);
  std::map<std::string, std::vector<const Wrong*>> by_key;
  for (const auto& w : wrong) by_key[w.key].push_back(&w);
  json out = json::array();
  for (const auto& [key, members] : by_key) {
    json students = json::array();
    for (const Wrong* w : members) students.push_back(in.students[w->student].id);
    const Wrong& first = *members.front();
    json g = {{"count", members.size()},
              {"students", students},
              {"mistake", nullptr},
              {"discovered", nullptr},
              {"example", in.students[first.student].answers[p].answer.dump()}};
    if (key.starts_with("mistake:")) {
      g["mistake"] = key.substr(8);
    } else if (key.starts_with("change:")) {
      const StepChange& c = first.discovery.changes.front();
      json equivalent = json::array();
      for (std::size_t k = 1; k < first.discovery.changes.size(); ++k)
        equivalent.push_back(first.discovery.changes[k].text());
      g["discovered"] = {{"method", c.method},
                         {"step", c.step},
                         {"change", c.text()},
                         {"kind", c.kind},
                         {"equivalent", equivalent}};
    } else {
      g["note"] = unexplained_note(key);
    }
    out.push_back(std::move(g));
  }
  std::stable_sort(out.begin(), out.end(), [](const json& a, const json& b) {
    return a["count"].get<int>() > b["count"].get<int>();
  });
  return out;
}

json problem_json(const ClassInput& in, std::size_t p, unsigned jobs) {
  std::vector<const ClassAnswer*> answers;
  std::vector<std::string> part_names;
  double sum = 0, max_points = 0;
  int counts[4] = {0, 0, 0, 0};
  std::vector<double> fractions;
  for (const auto& s : in.students) {
    const ClassAnswer& a = s.answers[p];
    answers.push_back(&a);
    for (const auto& part : a.result.parts)
      if (std::find(part_names.begin(), part_names.end(), part.name) == part_names.end())
        part_names.push_back(part.name);
    sum += a.result.score;
    max_points = std::max(max_points, a.result.max_score);
    fractions.push_back(a.result.max_score > 0 ? a.result.score / a.result.max_score : 0);
    int k = !a.result.answered ? 3 : full_marks(a.result) ? 0 : a.result.score > 0 ? 1 : 2;
    ++counts[k];
  }
  json parts = json::object();
  for (const auto& name : part_names) parts[name] = part_json(answers, name);
  double n = std::max<std::size_t>(1, answers.size());
  return {{"id", in.problem_ids[p]},
          {"title", p < in.problem_titles.size() ? in.problem_titles[p] : in.problem_ids[p]},
          {"students", answers.size()},
          {"no_submission", in.no_submission.size()},
          {"max_points", rounded(max_points)},
          {"mean", rounded(sum / n)},
          {"histogram", histogram(fractions)},
          {"shares", shares(counts[0], counts[1], counts[2], counts[3])},
          {"parts", parts},
          {"mistakes", mistakes_json(in, p)},
          {"groups", groups_json(in, p, jobs)},
          {"fairness", fairness_json(in, p)},
          {"discrimination", discrimination(in, p)}};
}

}  // namespace class_report_internal

nlohmann::json class_report_json(const ClassInput& input, unsigned jobs) {
  using namespace class_report_internal;  // NOLINT: this file's own functions
  json problems = json::array();
  for (std::size_t p = 0; p < input.problem_ids.size(); ++p)
    problems.push_back(problem_json(input, p, jobs));
  json students = json::array();
  for (const auto& s : input.students)
    students.push_back({{"id", s.id}, {"name", s.name}, {"page", s.page}});
  json absent = json::array();
  for (const auto& s : input.no_submission) absent.push_back({{"id", s.id}, {"name", s.name}});
  return {{"title", input.title},
          {"problems", problems},
          {"students", students},
          {"no_submission", absent}};
}

}  // namespace raygrade
