// The class list by NRPS 2.0: pages read and their members kept.
#include "serve/roster.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
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

// The members of one page read as the parser meets them (its SAX events), never as a tree of
// the whole page: a page of many small members costs what the members kept cost. A member is
// an object of the top object's "members" array; of it are read its string fields and the
// strings of its "roles" array. `take` gets each member; it returns false to stop the parse.
class PageReader : public nlohmann::json::json_sax_t {
 public:
  explicit PageReader(std::function<bool(Member)> take) : take_(std::move(take)) {}
  // The page was a membership container (an object with a "members" array).
  bool container() const { return top_object_ && saw_members_; }

  bool start_object(std::size_t) override {
    if (depth_ == 0) top_object_ = true;
    if (depth_ == 2 && in_members_) {
      in_member_ = true;
      fields_.clear();
      roles_ = nlohmann::json::array();
    }
    ++depth_;
    return true;
  }
  bool end_object() override {
    --depth_;
    if (depth_ == 2 && in_member_) {
      in_member_ = false;
      return take_(member());
    }
    return true;
  }
  bool start_array(std::size_t) override {
    if (depth_ == 1 && top_key_ == "members") in_members_ = saw_members_ = true;
    if (depth_ == 3 && in_member_ && member_key_ == "roles") in_roles_ = true;
    ++depth_;
    return true;
  }
  bool end_array() override {
    --depth_;
    if (depth_ == 1) in_members_ = false;
    if (depth_ == 3) in_roles_ = false;
    return true;
  }
  bool key(string_t& k) override {
    if (depth_ == 1) top_key_ = k;
    if (depth_ == 3) member_key_ = k;
    return true;
  }
  bool string(string_t& v) override {
    if (depth_ == 3 && in_member_) fields_[member_key_] = v;
    if (depth_ == 4 && in_roles_) roles_.push_back(v);
    return true;
  }
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }

 private:
  Member member() const {
    auto field = [&](const char* name) {
      auto it = fields_.find(name);
      return it == fields_.end() ? std::string() : it->second;
    };
    Member out;
    out.user_id = field("user_id");
    out.name = field("name");
    if (out.name.empty()) out.name = trimmed(field("given_name") + " " + field("family_name"));
    out.email = field("email");
    out.roles = roles_.dump();
    out.status = field("status");
    if (out.status != "Inactive" && out.status != "Deleted") out.status = "Active";
    return out;
  }

  std::function<bool(Member)> take_;
  int depth_ = 0;  // containers open
  bool top_object_ = false, saw_members_ = false;
  bool in_members_ = false, in_member_ = false, in_roles_ = false;
  std::string top_key_, member_key_;
  std::map<std::string, std::string> fields_;  // the member's string fields
  nlohmann::json roles_;
};

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
    bool too_many = false;
    PageReader reader([&](Member got) {
      if (!usable_user_id(got.user_id) || !seen_members.insert(got.user_id).second) return true;
      if (members.size() == kMaxRosterMembers) {
        too_many = true;
        return false;  // the parse stops here
      }
      members.push_back(std::move(got));
      return true;
    });
    bool parsed = nlohmann::json::sax_parse(a.body, &reader);
    if (too_many)
      throw std::runtime_error(
          fmt::format("the roster has more than {} members", kMaxRosterMembers));
    if (!parsed || !reader.container())
      throw std::runtime_error("memberships: the answer is not a membership container");
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
