// The class list by NRPS 2.0: pages read and their members kept.
#include "serve/roster.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "core/escape.h"
#include "serve/http_client.h"

namespace raygrade::serve {

namespace {

std::string trimmed(std::string_view s) {
  std::size_t from = s.find_first_not_of(" \t");
  if (from == std::string_view::npos) return "";
  std::size_t to = s.find_last_not_of(" \t");
  return std::string(s.substr(from, to - from + 1));
}

std::string text_of(const nlohmann::json& o, const char* name) {
  auto it = o.find(name);
  return it != o.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// The rel parameter of one link's parameters ("; rel=\"next\"; title=x"), quotes removed.
std::string rel_of(std::string_view params) {
  std::size_t at = 0;
  while (at < params.size()) {
    std::size_t end = params.find(';', at);
    if (end == std::string_view::npos) end = params.size();
    std::string p = trimmed(params.substr(at, end - at));
    std::size_t eq = p.find('=');
    if (eq != std::string::npos) {
      std::string name = trimmed(std::string_view(p).substr(0, eq));
      for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      std::string value = trimmed(std::string_view(p).substr(eq + 1));
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
      if (name == "rel") return value;
    }
    at = end + 1;
  }
  return "";
}

// A rel value is a space-separated list of relation types, compared case-insensitively.
bool has_next(const std::string& rel) {
  std::size_t at = 0;
  while (at <= rel.size()) {
    std::size_t end = rel.find(' ', at);
    if (end == std::string::npos) end = rel.size();
    std::string type = rel.substr(at, end - at);
    for (char& c : type) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (type == "next") return true;
    at = end + 1;
  }
  return false;
}

std::string resolved(const std::string& target, const std::string& base) {
  if (target.starts_with("http://") || target.starts_with("https://")) return target;
  auto [origin, path] = split_url(base);
  if (target.starts_with("/")) return origin + target;
  std::size_t query = path.find('?');
  std::string folder = path.substr(0, query);
  if (target.starts_with("?")) return origin + folder + target;
  return origin + folder.substr(0, folder.rfind('/') + 1) + target;
}

// A user_id a launch's sub can be and a database keeps whole: not empty, no C0 control
// character (NUL among them) and no DEL.
bool usable_user_id(std::string_view id) {
  return !id.empty() && std::none_of(id.begin(), id.end(), [](char c) {
    return static_cast<unsigned char>(c) < 0x20 || c == '\x7f';
  });
}

Member member_of(const nlohmann::json& m) {
  Member out;
  out.user_id = text_of(m, "user_id");
  out.name = text_of(m, "name");
  if (out.name.empty())
    out.name = trimmed(text_of(m, "given_name") + " " + text_of(m, "family_name"));
  out.email = text_of(m, "email");
  nlohmann::json roles = nlohmann::json::array();
  if (m.contains("roles") && m["roles"].is_array()) {
    for (const auto& r : m["roles"])
      if (r.is_string()) roles.push_back(r);
  }
  out.roles = roles.dump();
  out.status = text_of(m, "status");
  if (out.status != "Inactive" && out.status != "Deleted") out.status = "Active";
  return out;
}

}  // namespace

std::string next_link(const std::string& header, const std::string& base) {
  std::size_t at = 0;
  while ((at = header.find('<', at)) != std::string::npos) {
    std::size_t close = header.find('>', at);
    if (close == std::string::npos) return "";
    std::string target = header.substr(at + 1, close - at - 1);
    // The link's parameters run to the next link (a comma outside quotes) or the end.
    std::size_t end = close + 1;
    bool quoted = false;
    while (end < header.size() && (quoted || header[end] != ',')) {
      if (header[end] == '"') quoted = !quoted;
      ++end;
    }
    if (has_next(rel_of(std::string_view(header).substr(close + 1, end - close - 1))))
      return resolved(target, base);
    at = end;
  }
  return "";
}

std::vector<Member> read_memberships(const std::string& url, const std::string& token) {
  std::vector<Member> members;
  std::set<std::string> seen_members, seen_pages;
  HttpHeaders headers = {{"Authorization", "Bearer " + token},
                         {"Accept", std::string(kMembershipType)}};
  const std::string origin = origin_of(url);
  HttpBounds bounds{kMaxRosterPageBytes,
                    std::chrono::steady_clock::now() + std::chrono::seconds(kRosterSeconds)};
  std::string page = url;
  for (int n = 0; !page.empty(); ++n) {
    if (n == kMaxRosterPages || !seen_pages.insert(page).second)
      throw std::runtime_error(fmt::format("the roster's pages do not end (page {})", n + 1));
    // The bearer token is for the membership service alone.
    if (origin_of(page) != origin)
      throw std::runtime_error(
          fmt::format("page {} of the roster is at another origin than the membership service "
                      "({}), not asked for",
                      n + 1, printable(page, 200)));
    if (std::chrono::steady_clock::now() >= bounds.deadline)
      throw std::runtime_error(fmt::format("the roster was not read in {} s", kRosterSeconds));
    HttpAnswer a = http_get(page, headers, bounds);
    if (!http_ok(a)) throw std::runtime_error(http_failure("memberships", a));
    nlohmann::json j = nlohmann::json::parse(a.body, nullptr, false);
    if (!j.is_object() || !j.contains("members") || !j["members"].is_array())
      throw std::runtime_error("memberships: the answer is not a membership container");
    for (const auto& m : j["members"]) {
      if (!m.is_object()) continue;
      Member got = member_of(m);
      if (usable_user_id(got.user_id) && seen_members.insert(got.user_id).second)
        members.push_back(std::move(got));
    }
    page = next_link(a.link, page);
  }
  return members;
}

bool is_learner(const Member& m) {
  nlohmann::json roles = nlohmann::json::parse(m.roles, nullptr, false);
  if (!roles.is_array()) return false;
  for (const auto& r : roles) {
    if (r == "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner" || r == "Learner")
      return true;
  }
  return false;
}

}  // namespace raygrade::serve
