// Reading assignment files.
#include "assignments/assignment.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "json/cursor.h"

namespace raygrade {
namespace {

FeedbackPolicy read_policy(const Cursor& c) {
  std::string name = c.string();
  auto p = parse_feedback_policy(name);
  if (!p) c.fail(fmt::format("unknown feedback policy '{}' (known: score, mistakes, full)", name));
  return *p;
}

// "mistakes", or {"before_due": "mistakes", "after_due": "full"}.
FeedbackRule read_feedback(const Cursor& c, FeedbackRule rule) {
  if (c.json().is_string()) {
    rule.before_due = rule.after_due = read_policy(c);
    return rule;
  }
  if (!c.is_object())
    c.fail("feedback is a policy name, or {\"before_due\", \"after_due\"}", "type");
  c.allow_only({"before_due", "after_due"});
  if (auto b = c.find("before_due")) rule.before_due = read_policy(*b);
  if (auto a = c.find("after_due")) rule.after_due = read_policy(*a);
  return rule;
}

// Days from 1970-01-01 to a civil date (Howard Hinnant's days_from_civil).
std::int64_t days_from_civil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

// A civil date and time of day, UTC, from seconds since 1970-01-01 UTC (Howard Hinnant's
// civil_from_days, the inverse of days_from_civil).
struct UtcTime {
  std::int64_t year;
  unsigned month, day, weekday;  // weekday 0 is Sunday
  int hour, minute, second;
};

UtcTime utc_time(std::int64_t seconds) {
  std::int64_t days = seconds / 86400;
  std::int64_t rest = seconds % 86400;
  if (rest < 0) {
    rest += 86400;
    --days;
  }
  UtcTime t{};
  t.weekday = static_cast<unsigned>(((days + 4) % 7 + 7) % 7);  // 1970-01-01 was a Thursday
  t.hour = static_cast<int>(rest / 3600);
  t.minute = static_cast<int>(rest / 60 % 60);
  t.second = static_cast<int>(rest % 60);
  const std::int64_t z = days + 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  t.day = doy - (153 * mp + 2) / 5 + 1;
  t.month = mp < 10 ? mp + 3 : mp - 9;
  t.year = static_cast<std::int64_t>(yoe) + era * 400 + (t.month <= 2);
  return t;
}

bool digits(std::string_view s, std::size_t at, std::size_t n, int& out) {
  if (at + n > s.size()) return false;
  out = 0;
  for (std::size_t i = at; i < at + n; ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    out = out * 10 + (s[i] - '0');
  }
  return true;
}

}  // namespace

const char* to_string(FeedbackPolicy p) {
  switch (p) {
    case FeedbackPolicy::kScore: return "score";
    case FeedbackPolicy::kMistakes: return "mistakes";
    case FeedbackPolicy::kFull: return "full";
  }
  return "full";
}

std::optional<FeedbackPolicy> parse_feedback_policy(std::string_view name) {
  for (auto p : {FeedbackPolicy::kScore, FeedbackPolicy::kMistakes, FeedbackPolicy::kFull}) {
    if (name == to_string(p)) return p;
  }
  return std::nullopt;
}

std::optional<std::int64_t> parse_time(std::string_view s) {
  int y, mo, d, h = 23, mi = 59, sec = 59;
  if (!digits(s, 0, 4, y) || s.size() < 10 || s[4] != '-' || !digits(s, 5, 2, mo) || s[7] != '-' ||
      !digits(s, 8, 2, d))
    return std::nullopt;
  static const int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  if (mo < 1 || mo > 12 || d < 1 || d > kDays[mo - 1] || (mo == 2 && d == 29 && !leap))
    return std::nullopt;
  std::int64_t offset = 0;
  if (s.size() > 10) {
    if (s[10] != 'T' || !digits(s, 11, 2, h) || s.size() < 16 || s[13] != ':' ||
        !digits(s, 14, 2, mi))
      return std::nullopt;
    std::size_t at = 16;
    sec = 0;
    if (at < s.size() && s[at] == ':') {
      if (!digits(s, at + 1, 2, sec)) return std::nullopt;
      at += 3;
      // A fraction of a second (Gradescope writes microseconds) is dropped.
      if (at < s.size() && s[at] == '.') {
        std::size_t end = at + 1;
        while (end < s.size() && s[end] >= '0' && s[end] <= '9') ++end;
        if (end == at + 1) return std::nullopt;
        at = end;
      }
    }
    if (h > 23 || mi > 59 || sec > 59) return std::nullopt;
    if (at < s.size() && s[at] == 'Z') {
      ++at;
    } else if (at < s.size() && (s[at] == '+' || s[at] == '-')) {
      int oh, om;
      if (!digits(s, at + 1, 2, oh) || at + 3 >= s.size() || s[at + 3] != ':' ||
          !digits(s, at + 4, 2, om) || oh > 23 || om > 59)
        return std::nullopt;
      offset = (s[at] == '+' ? 1 : -1) * (std::int64_t{oh} * 3600 + std::int64_t{om} * 60);
      at += 6;
    } else {
      return std::nullopt;  // a time without a zone is ambiguous
    }
    if (at != s.size()) return std::nullopt;
  }
  return days_from_civil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d)) * 86400 +
         std::int64_t{h} * 3600 + std::int64_t{mi} * 60 + sec - offset;
}

std::string utc_time_text(std::int64_t seconds) {
  static const char* const kWeekdays[] = {"Sunday",   "Monday", "Tuesday", "Wednesday",
                                          "Thursday", "Friday", "Saturday"};
  static const char* const kMonths[] = {"January",   "February", "March",    "April",
                                        "May",       "June",     "July",     "August",
                                        "September", "October",  "November", "December"};
  UtcTime t = utc_time(seconds);
  return fmt::format("{} {} {} {}, {:02}:{:02} UTC", kWeekdays[t.weekday], t.day,
                     kMonths[t.month - 1], t.year, t.hour, t.minute);
}

std::string iso_utc_time(std::int64_t seconds) {
  UtcTime t = utc_time(seconds);
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}Z", t.year, t.month, t.day, t.hour,
                     t.minute, t.second);
}

FeedbackPolicy AssignmentSpec::policy(const AssignmentProblem& p, std::int64_t now) const {
  const FeedbackRule& rule = p.feedback ? *p.feedback : feedback;
  return due && now > *due ? rule.after_due : rule.before_due;
}

bool is_assignment_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  try {
    auto file = load_json_file(path);
    return file->root.is_object() && file->root.contains("assignment");
  } catch (const Error&) {
    return false;
  }
}

namespace {

// Runs `read`, keeping the fault it throws in `errors` instead of stopping there.
template <typename Read>
void collecting(std::vector<Diagnostic>& errors, Read&& read) {
  try {
    read();
  } catch (const Error& e) {
    errors.push_back(e.diagnostic());
  }
}

// Each key of `c` that is not allowed, as a fault of its own.
void unknown_keys(const Cursor& c, const std::vector<std::string>& allowed,
                  std::vector<Diagnostic>& errors) {
  if (!c.is_object()) return;
  for (const auto& [key, value] : c.json().items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string hint = closest_match(key, allowed);
    errors.push_back(c.at(key).diagnostic(
        hint.empty() ? fmt::format("unknown key '{}'", key)
                     : fmt::format("unknown key '{}' (did you mean '{}'?)", key, hint),
        "unknown-key"));
  }
}

AssignmentProblem read_assignment_problem(const Cursor& item, const AssignmentSpec& a,
                                          std::vector<Diagnostic>& errors) {
  AssignmentProblem p;
  p.path = item.path();
  if (item.json().is_string()) {
    p.id = item.string();
    return p;
  }
  if (!item.is_object()) item.fail("a problem is an id, or {\"id\", \"points\", ...}", "type");
  unknown_keys(item, {"id", "points", "variants", "feedback"}, errors);
  p.id = item.at("id").string();
  collecting(errors, [&] {
    if (auto pts = item.find("points")) {
      p.points = pts->number();
      if (*p.points < 0) pts->fail("points must not be negative", "range");
    }
  });
  collecting(errors, [&] { p.variants = item.boolean_or("variants", true); });
  collecting(errors, [&] {
    if (auto f = item.find("feedback")) p.feedback = read_feedback(*f, a.feedback);
  });
  return p;
}

}  // namespace

AssignmentSpec read_assignment(const std::string& path, std::vector<Diagnostic>& errors) {
  auto file = load_json_file(path);
  Cursor root(file);
  if (!root.is_object()) root.fail("an assignment is a JSON object", "type");
  unknown_keys(
      root, {"$schema", "assignment", "title", "bank", "due", "variants", "feedback", "problems"},
      errors);
  AssignmentSpec a;
  a.file = path;
  collecting(errors, [&] {
    a.id = root.at("assignment").string();
    if (a.id.empty()) root.at("assignment").fail("the assignment's id must not be empty");
  });
  collecting(errors, [&] { a.title = root.string_or("title", a.id); });
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  collecting(errors, [&] {
    Cursor bank = root.at("bank");
    std::vector<Cursor> banks = bank.json().is_string() ? std::vector<Cursor>{bank} : bank.items();
    if (banks.empty()) bank.fail("no bank named");
    for (const auto& b : banks) a.bank.push_back((folder / b.string()).lexically_normal().string());
  });
  collecting(errors, [&] {
    if (auto due = root.find("due")) {
      a.due_text = due->string();
      a.due = parse_time(a.due_text);
      if (!a.due) {
        due->fail(
            fmt::format("'{}' is not a date and time such as 2026-12-04T23:59:00Z (or "
                        "2026-12-04T23:59:00+01:00, or a date alone)",
                        a.due_text));
      }
    }
  });
  collecting(errors, [&] {
    if (auto v = root.find("variants")) {
      unknown_keys(*v, {"per_student", "seed", "allow_degenerate"}, errors);
      a.per_student = v->boolean_or("per_student", true);
      a.allow_degenerate = v->boolean_or("allow_degenerate", false);
      if (auto seed = v->find("seed")) {
        if (!seed->json().is_number_unsigned()) seed->fail("the seed is a whole number ≥ 0");
        a.seed = seed->json().get<std::uint64_t>();
      }
    }
  });
  collecting(errors, [&] {
    if (auto f = root.find("feedback")) a.feedback = read_feedback(*f, a.feedback);
  });
  collecting(errors, [&] {
    Cursor list = root.at("problems");
    std::map<std::string, std::string> seen;
    for (const auto& item : list.items()) {
      collecting(errors, [&] {
        AssignmentProblem p = read_assignment_problem(item, a, errors);
        auto [it, fresh] = seen.emplace(p.id, p.path);
        if (!fresh)
          item.fail(fmt::format("problem '{}' is listed twice (first at {})", p.id, it->second),
                    "duplicate-id");
        a.problems.push_back(std::move(p));
      });
    }
    if (list.items().empty()) list.fail("an assignment needs at least one problem");
  });
  return a;
}

AssignmentSpec load_assignment(const std::string& path) {
  std::vector<Diagnostic> errors;
  AssignmentSpec a = read_assignment(path, errors);
  if (!errors.empty()) throw Error(errors.front());
  return a;
}

AssignmentBank load_assignment_bank(const AssignmentSpec& spec) {
  AssignmentBank out;
  out.bank = load_bank(spec.bank);
  out.errors = out.bank.errors;
  std::map<std::string, const Problem*, std::less<>> by_id;
  std::vector<std::string> ids;
  for (const auto& p : out.bank.problems) {
    by_id[p.id] = &p;
    ids.push_back(p.id);
  }
  auto file = load_json_file(spec.file);
  for (const auto& ap : spec.problems) {
    auto it = by_id.find(ap.id);
    if (it != by_id.end()) {
      out.problems.push_back(it->second);
      continue;
    }
    std::string hint = closest_match(ap.id, ids);
    std::string at =
        ap.path + (file->root.at(nlohmann::json::json_pointer(ap.path)).is_object() ? "/id" : "");
    auto [line, column] = locate(file->text, at);
    out.errors.push_back(Diagnostic{
        spec.file, at, line, column, Severity::kError,
        hint.empty() ? fmt::format("no problem '{}' in the bank", ap.id)
                     : fmt::format("no problem '{}' in the bank (did you mean '{}'?)", ap.id, hint),
        "unknown-problem"});
  }
  return out;
}

}  // namespace raygrade
