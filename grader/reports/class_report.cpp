// The class report as JSON: scores, shares, mistakes, groups of wrong answers, fairness and
// discrimination, per problem.
#include "reports/class_report.h"

#include <cmath>
#include <cstdint>
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

// One part of one answer, as the report counts it.
struct PartRow {
  std::uint32_t name = 0;  // in Tables::strings
  PartStatus status = PartStatus::kMissing;
  double points = 0;
  double max_points = 0;
};

// One answer, as the report counts it.
struct AnswerRow {
  double score = 0;
  double max_score = 0;
  bool answered = false;
  std::int32_t variant = -1;            // in the problem's variants; -1 for none
  std::vector<PartRow> parts;           // in the result's order
  std::vector<std::uint32_t> mistakes;  // ids in Tables::strings, in the result's order
  std::string answer;                   // as submitted (JSON text), when below full marks
};

struct StudentRow {
  std::string id, name, page;
  std::vector<AnswerRow> answers;  // one per problem
};

// A variant of one problem: its numbers, and the problem when it is kept as given.
struct VariantRow {
  std::string key;
  ParameterValues values;
  const Problem* problem = nullptr;  // borrowed (no bases), or the base itself
};

// Strings many rows share (part names, mistake ids), each kept once.
struct Tables {
  std::vector<std::string> strings;
  std::map<std::string, std::uint32_t, std::less<>> index;
  std::uint32_t intern(const std::string& s) {
    auto [it, fresh] = index.emplace(s, static_cast<std::uint32_t>(strings.size()));
    if (fresh) strings.push_back(s);
    return it->second;
  }
};

bool full_marks(const AnswerRow& r) { return r.max_score > 0 && r.score >= r.max_score - 1e-9; }

std::string variant_key(const Problem& v) { return v.id + "\n" + json(v.values).dump(); }

struct Report {
  std::string title;
  std::vector<std::string> problem_ids, problem_titles;
  std::vector<const Problem*> bases;
  Tables tables;
  std::vector<std::vector<VariantRow>> variants;                   // per problem
  std::vector<std::map<std::string, std::int32_t>> variant_index;  // per problem
  std::vector<StudentRow> students;
  std::map<std::string, std::size_t> student_index;
  std::vector<AbsentStudent> no_submission;
};

// Scores, histogram and shares of one part over the class.
json part_json(const Report& in, std::size_t p, std::uint32_t name) {
  double sum = 0, max_points = 0;
  int counts[4] = {0, 0, 0, 0};  // right, partly, wrong, blank
  std::vector<double> fractions;
  for (const auto& s : in.students) {
    const PartRow* part = nullptr;
    for (const auto& q : s.answers[p].parts)
      if (q.name == name) part = &q;
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
  double n = static_cast<double>(std::max<std::size_t>(1, in.students.size()));
  return {{"students", in.students.size()},
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
json mistakes_json(const Report& in, std::size_t p) {
  std::map<std::string, std::vector<std::string>> by_id;
  for (const auto& s : in.students) {
    std::set<std::string> ids;
    for (std::uint32_t m : s.answers[p].mistakes) ids.insert(in.tables.strings[m]);
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
json fairness_json(const Report& in, std::size_t p) {
  std::map<std::string, std::map<std::string, std::pair<double, int>>> by;  // name → value → sum, n
  for (const auto& s : in.students) {
    const AnswerRow& a = s.answers[p];
    if (a.variant < 0 || a.max_score <= 0) continue;
    for (const auto& [name, value] : in.variants[p][a.variant].values) {
      auto& cell = by[name][value.dump()];
      cell.first += a.score / a.max_score;
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
json discrimination(const Report& in, std::size_t p) {
  std::vector<double> rest;
  std::vector<bool> right;
  for (const auto& s : in.students) {
    double r = 0;
    for (std::size_t q = 0; q < s.answers.size(); ++q)
      if (q != p) r += s.answers[q].score;
    rest.push_back(r);
    right.push_back(full_marks(s.answers[p]));
  }
  double n = static_cast<double>(rest.size()), mean = 0, m1 = 0, n1 = 0;
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

// One wrong answer and how it is grouped.
struct Wrong {
  std::size_t student;
  std::string key;  // the group
  Discovery discovery;
};

// The variants whose searches are held at once: the memory of the search does not grow with
// the number of variants.
constexpr std::size_t kVariantsAtOnce = 64;

// The changes that explain each answer, the search run once per variant.
void discover(const Report& in, std::size_t p, std::vector<Wrong>& wrong, unsigned jobs) {
  std::vector<std::int32_t> variants;
  std::map<std::int32_t, std::vector<Wrong*>> answers_of;
  for (auto& w : wrong) {
    const AnswerRow& a = in.students[w.student].answers[p];
    if (!w.key.empty() || a.variant < 0) continue;
    auto& list = answers_of[a.variant];
    if (list.empty()) variants.push_back(a.variant);
    list.push_back(&w);
  }
  for (std::size_t from = 0; from < variants.size(); from += kVariantsAtOnce) {
    std::size_t n = std::min(kVariantsAtOnce, variants.size() - from);
    parallel_map<int>(n, jobs, [&](std::size_t i) -> int {
      const VariantRow& v = in.variants[p][variants[from + i]];
      std::unique_ptr<const ChangeSearch> search;
      try {
        if (v.problem) {
          search = std::make_unique<const ChangeSearch>(*v.problem);
        } else {
          Problem problem = read_problem_variant(*in.bases[p], v.values);
          search = std::make_unique<const ChangeSearch>(problem);
        }
      } catch (const Error&) {
        return 0;  // a derivation that cannot be worked: nothing to search
      }
      for (Wrong* w : answers_of.at(variants[from + i]))
        w->discovery = search->explain(json::parse(in.students[w->student].answers[p].answer));
      return 0;
    });
  }
  std::map<std::string, int> popularity;
  for (auto& w : wrong)
    for (const auto& c : w.discovery.changes) ++popularity[c.key()];
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

bool is_wrong(const AnswerRow& r) { return r.answered && !full_marks(r) && r.max_score > 0; }

json groups_json(const Report& in, std::size_t p, unsigned jobs) {
  std::vector<Wrong> wrong;
  for (std::size_t s = 0; s < in.students.size(); ++s) {
    const AnswerRow& r = in.students[s].answers[p];
    if (!is_wrong(r)) continue;
    wrong.push_back(
        {s, r.mistakes.empty() ? "" : "mistake:" + in.tables.strings[r.mistakes.front()], {}});
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
              {"example", in.students[first.student].answers[p].answer}};
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

json problem_json(const Report& in, std::size_t p, unsigned jobs) {
  std::vector<std::uint32_t> part_names;
  double sum = 0, max_points = 0;
  int counts[4] = {0, 0, 0, 0};
  std::vector<double> fractions;
  for (const auto& s : in.students) {
    const AnswerRow& a = s.answers[p];
    for (const auto& part : a.parts)
      if (std::find(part_names.begin(), part_names.end(), part.name) == part_names.end())
        part_names.push_back(part.name);
    sum += a.score;
    max_points = std::max(max_points, a.max_score);
    fractions.push_back(a.max_score > 0 ? a.score / a.max_score : 0);
    int k = !a.answered ? 3 : full_marks(a) ? 0 : a.score > 0 ? 1 : 2;
    ++counts[k];
  }
  json parts = json::object();
  for (std::uint32_t name : part_names) parts[in.tables.strings[name]] = part_json(in, p, name);
  double n = static_cast<double>(std::max<std::size_t>(1, in.students.size()));
  return {{"id", in.problem_ids[p]},
          {"title", p < in.problem_titles.size() ? in.problem_titles[p] : in.problem_ids[p]},
          {"students", in.students.size()},
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

std::size_t bytes(const std::string& s) { return s.capacity() > 15 ? s.capacity() + 1 : 0; }

}  // namespace class_report_internal

struct ClassReportBuilder::Impl : class_report_internal::Report {};

ClassReportBuilder::ClassReportBuilder(std::string title, std::vector<std::string> problem_ids,
                                       std::vector<std::string> problem_titles,
                                       std::vector<const Problem*> bases)
    : impl_(std::make_unique<Impl>()) {
  impl_->title = std::move(title);
  impl_->variants.resize(problem_ids.size());
  impl_->variant_index.resize(problem_ids.size());
  impl_->problem_ids = std::move(problem_ids);
  impl_->problem_titles = std::move(problem_titles);
  impl_->bases = std::move(bases);
}

ClassReportBuilder::~ClassReportBuilder() = default;

void ClassReportBuilder::add(const ClassStudent& student) {
  using namespace class_report_internal;  // NOLINT: this file's own functions
  Report& r = *impl_;
  StudentRow row{student.id, student.name, student.page, {}};
  row.answers.resize(r.problem_ids.size());
  for (std::size_t p = 0; p < r.problem_ids.size() && p < student.answers.size(); ++p) {
    const ClassAnswer& a = student.answers[p];
    AnswerRow& out = row.answers[p];
    out.score = a.result.score;
    out.max_score = a.result.max_score;
    out.answered = a.result.answered;
    for (const auto& part : a.result.parts)
      out.parts.push_back({r.tables.intern(part.name), part.status, part.points, part.max_points});
    for (const auto& m : a.result.mistakes) out.mistakes.push_back(r.tables.intern(m.id));
    if (a.variant) {
      std::string key = variant_key(*a.variant);
      auto [it, fresh] =
          r.variant_index[p].emplace(key, static_cast<std::int32_t>(r.variants[p].size()));
      if (fresh) {
        bool keep = r.bases.empty() || a.variant->values.empty() || a.variant == r.bases[p];
        const Problem* kept = !keep ? nullptr : r.bases.empty() ? a.variant : r.bases[p];
        r.variants[p].push_back({key, a.variant->values, kept});
      }
      out.variant = it->second;
    }
    if (is_wrong(out)) out.answer = a.answer.dump();
    out.parts.shrink_to_fit();
    out.mistakes.shrink_to_fit();
  }
  auto [it, fresh] = r.student_index.emplace(student.id, r.students.size());
  if (fresh)
    r.students.push_back(std::move(row));
  else
    r.students[it->second] = std::move(row);
}

void ClassReportBuilder::set_no_submission(std::vector<AbsentStudent> absent) {
  impl_->no_submission = std::move(absent);
}

std::size_t ClassReportBuilder::students() const { return impl_->students.size(); }

std::size_t ClassReportBuilder::retained_bytes() const {
  using namespace class_report_internal;  // NOLINT: this file's own functions
  const Report& r = *impl_;
  std::size_t n = r.students.capacity() * sizeof(StudentRow);
  for (const auto& s : r.students) {
    n += bytes(s.id) + bytes(s.name) + bytes(s.page) + s.answers.capacity() * sizeof(AnswerRow);
    for (const auto& a : s.answers)
      n += a.parts.capacity() * sizeof(PartRow) + a.mistakes.capacity() * sizeof(std::uint32_t) +
           bytes(a.answer);
  }
  // A map entry: its key and value, and about four words of the tree's node.
  constexpr std::size_t kNode = 4 * sizeof(void*);
  for (const auto& [id, k] : r.student_index) n += kNode + sizeof(std::string) + bytes(id) + 8;
  for (const auto& s : r.tables.strings) n += 2 * (sizeof(std::string) + bytes(s)) + kNode;
  for (const auto& problem_variants : r.variants) {
    for (const auto& v : problem_variants) {
      n += sizeof(VariantRow) + 2 * bytes(v.key) + kNode + sizeof(std::string);
      for (const auto& [name, value] : v.values) n += kNode + bytes(name) + value.dump().size();
    }
  }
  return n;
}

nlohmann::json ClassReportBuilder::json(unsigned jobs) const {
  using namespace class_report_internal;  // NOLINT: this file's own functions
  const Report& in = *impl_;
  nlohmann::json problems = nlohmann::json::array();
  for (std::size_t p = 0; p < in.problem_ids.size(); ++p)
    problems.push_back(problem_json(in, p, jobs));
  nlohmann::json students = nlohmann::json::array();
  for (const auto& s : in.students)
    students.push_back({{"id", s.id}, {"name", s.name}, {"page", s.page}});
  nlohmann::json absent = nlohmann::json::array();
  for (const auto& s : in.no_submission) absent.push_back({{"id", s.id}, {"name", s.name}});
  return {{"title", in.title},
          {"problems", problems},
          {"students", students},
          {"no_submission", absent}};
}

nlohmann::json class_report_json(const ClassInput& input, unsigned jobs) {
  ClassReportBuilder b(input.title, input.problem_ids, input.problem_titles);
  for (const auto& s : input.students) b.add(s);
  b.set_no_submission(input.no_submission);
  return b.json(jobs);
}

}  // namespace raygrade
