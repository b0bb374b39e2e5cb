// `raygrade serve`: the LTI 1.3 tool's endpoints (docs/lti.md).
#include "serve/server.h"

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <algorithm>
#include <chrono>
#include <mutex>

#include "assignments/answer_form.h"
#include "assignments/handout.h"
#include "assignments/variants.h"
#include "core/escape.h"
#include "grading/outputs.h"
#include "serve/catalog.h"
#include "serve/http_client.h"
#include "serve/instructor.h"
#include "serve/jwt.h"
#include "serve/lti.h"
#include "serve/outbox.h"
#include "serve/pages.h"
#include "serve/roster.h"
#include "serve/store.h"
#include "serve/tokens.h"

namespace raygrade::serve {

namespace {

// How long a login may take between /lti/login and /lti/launch.
constexpr std::int64_t kLoginSeconds = 600;
// How long a launch's session lasts.
constexpr std::int64_t kSessionSeconds = std::int64_t{8} * 3600;
// The least time between two fetches of one platform's JWKS for a kid it did not hold.
constexpr std::int64_t kJwksRefetchMs = 5000;
// Threads answering requests. cpp-httplib gives each connection a thread for as long as it is
// kept alive: its default of 8 would let 8 idle browsers hold up a class.
constexpr std::size_t kWorkers = 32;
// Seconds an idle kept-alive connection holds its thread (cpp-httplib's default is 5).
constexpr time_t kKeepAliveSeconds = 1;
// The largest request body: a submission's answers, or a bank for a regrade.
constexpr std::size_t kMaxBody = 8u << 20;

std::int64_t now_seconds() { return now_ms() / 1000; }

// cpp-httplib 0.11 (Debian's shared library, its backlog compiled in) listens with a queue of
// 5 connections: a class submitting at once sees the rest of its connections dropped and sent
// again a second later, or reset. Listening again on the socket bound to `port` widens it.
void widen_backlog(int port) {
  for (int fd = 0; fd < 1024; ++fd) {
    int accepting = 0;
    socklen_t size = sizeof accepting;
    if (getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &accepting, &size) != 0 || !accepting) continue;
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) continue;
    int bound = -1;
    if (address.ss_family == AF_INET)
      bound = ntohs(reinterpret_cast<const sockaddr_in*>(&address)->sin_port);
    if (address.ss_family == AF_INET6)
      bound = ntohs(reinterpret_cast<const sockaddr_in6*>(&address)->sin6_port);
    if (bound == port) ::listen(fd, SOMAXCONN);
  }
}

std::string cookie(const httplib::Request& req, const std::string& name) {
  std::string header = req.get_header_value("Cookie");
  std::size_t at = 0;
  while (at < header.size()) {
    std::size_t end = header.find(';', at);
    if (end == std::string::npos) end = header.size();
    std::string pair = header.substr(at, end - at);
    std::size_t start = pair.find_first_not_of(' ');
    if (start != std::string::npos) pair = pair.substr(start);
    if (pair.compare(0, name.size() + 1, name + "=") == 0) return pair.substr(name.size() + 1);
    at = end + 1;
  }
  return "";
}

// Equal strings, compared in a time that does not depend on where they differ.
bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size() || a.empty()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

// The header a refusal's reason travels in to the server's log (the page says it too).
constexpr const char* kReasonHeader = "X-Raygrade-Refusal";

void send_refusal(httplib::Response& res, const Refusal& r) {
  res.status = r.status();
  res.set_header(kReasonHeader, r.what());
  res.set_content(refusal_page(r.status(), r.what()), "text/html; charset=utf-8");
}

void send_json_refusal(httplib::Response& res, const Refusal& r) {
  res.status = r.status();
  res.set_header(kReasonHeader, r.what());
  res.set_content(nlohmann::json{{"error", r.what()}}.dump(), "application/json");
}

std::string param(const httplib::Request& req, const std::string& name) {
  return req.has_param(name.c_str()) ? req.get_param_value(name.c_str()) : std::string();
}

}  // namespace

// Named rather than anonymous: a member of LtiServer::Impl.
namespace server_internal {

// The platform's keys, fetched from its JWKS URL and kept by kid.
class KeyCache {
 public:
  PKey find(const std::string& jwks_url, const std::string& kid) {
    std::lock_guard lock(mutex_);
    Keys& keys = by_url_[jwks_url];
    auto it = keys.by_kid.find(kid);
    if (it != keys.by_kid.end()) return rsa_public_key_from_jwk(it->second);
    std::int64_t now = now_ms();
    if (keys.fetched_ms != 0 && now - keys.fetched_ms < kJwksRefetchMs) return nullptr;
    keys.fetched_ms = now;
    HttpAnswer a = http_get(jwks_url);
    if (a.status != 200) return nullptr;
    nlohmann::json j = nlohmann::json::parse(a.body, nullptr, false);
    if (!j.is_object() || !j.contains("keys") || !j["keys"].is_array()) return nullptr;
    keys.by_kid.clear();
    for (const auto& k : j["keys"])
      if (k.is_object() && k.contains("kid") && k["kid"].is_string()) keys.by_kid[k["kid"]] = k;
    it = keys.by_kid.find(kid);
    return it == keys.by_kid.end() ? nullptr : rsa_public_key_from_jwk(it->second);
  }

 private:
  struct Keys {
    std::map<std::string, nlohmann::json> by_kid;
    std::int64_t fetched_ms = 0;
  };
  std::mutex mutex_;
  std::map<std::string, Keys> by_url_;
};

}  // namespace server_internal

struct LtiServer::Impl {
  ServeOptions options;
  std::unique_ptr<Store> store;
  Catalog catalog;
  std::string kid;
  PKey key;
  server_internal::KeyCache keys;
  std::unique_ptr<AccessTokens> tokens;
  std::unique_ptr<Outbox> outbox;
  httplib::Server http;
  bool secure_cookies = false;

  explicit Impl(ServeOptions o)
      : options(std::move(o)),
        store(open_store(options.database, options.data_dir)),
        catalog(options.assignments_dir) {
    if (!store->tool_key()) store->set_tool_key(random_token(12), generate_rsa_pem());
    auto [k, pem] = *store->tool_key();
    kid = k;
    key = private_key_from_pem(pem);
    if (!key) {
      throw Error(Diagnostic{options.data_dir, "", 0, 0, Severity::kError,
                             "the tool's key in the database is not a PEM private key",
                             "database"});
    }
    if (!options.public_url.empty()) set_public_url(options.public_url);
    tokens = std::make_unique<AccessTokens>(key.get(), kid);
    outbox = std::make_unique<Outbox>(*store, *tokens, options.outbox_base_ms, options.log,
                                      options.outbox_lease_ms);
    routes();
  }

  void set_public_url(const std::string& public_url) {
    options.public_url = public_url;
    while (!options.public_url.empty() && options.public_url.back() == '/')
      options.public_url.pop_back();
    // Browsers send SameSite=None cookies only with Secure, which they allow over plain
    // http on loopback alone.
    auto [origin, path] = split_url(options.public_url);
    secure_cookies = origin.starts_with("https://") || origin.starts_with("http://127.0.0.1") ||
                     origin.starts_with("http://localhost") || origin.starts_with("http://[::1]");
  }

  std::string url(const std::string& path) const { return options.public_url + path; }

  void set_cookie(httplib::Response& res, const std::string& name, const std::string& value,
                  std::int64_t max_age) const {
    res.set_header("Set-Cookie",
                   fmt::format("{}={}; Path=/lti; Max-Age={}; HttpOnly{}", name, value, max_age,
                               secure_cookies ? "; SameSite=None; Secure" : ""));
  }

  void routes() {
    http.set_payload_max_length(kMaxBody);
    http.new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
    http.set_keep_alive_timeout(kKeepAliveSeconds);
    if (options.log) {
      http.set_logger([this](const httplib::Request& req, const httplib::Response& res) {
        std::string line = fmt::format("{} {} {}", req.method, req.path, res.status);
        if (res.has_header(kReasonHeader)) line += ": " + res.get_header_value(kReasonHeader);
        options.log(line);
      });
    }
    http.Get("/lti/jwks", [this](const httplib::Request&, httplib::Response& res) {
      nlohmann::json jwks = {{"keys", {public_jwk(key.get(), kid)}}};
      res.set_content(jwks.dump(), "application/json");
    });
    auto guarded = [this](void (Impl::*handler)(const httplib::Request&, httplib::Response&)) {
      return [this, handler](const httplib::Request& req, httplib::Response& res) {
        try {
          (this->*handler)(req, res);
        } catch (const Refusal& r) {
          send_refusal(res, r);
        } catch (const Error& e) {
          send_refusal(res, Refusal(400, e.diagnostic().message));
        }
      };
    };
    http.Get("/lti/register", guarded(&Impl::on_register));
    http.Get("/lti/login", guarded(&Impl::on_login));
    http.Post("/lti/login", guarded(&Impl::on_login));
    http.Post("/lti/launch", guarded(&Impl::on_launch));
    http.Post("/lti/deep-link", guarded(&Impl::on_deep_link));
    http.Get("/lti/report", guarded(&Impl::on_report));
    http.Get("/lti/gradebook.csv", guarded(&Impl::on_gradebook));
    http.Post("/lti/regrade", guarded(&Impl::on_regrade));
    http.Post("/lti/submit", [this](const httplib::Request& req, httplib::Response& res) {
      try {
        on_submit(req, res);
      } catch (const Refusal& r) {
        send_json_refusal(res, r);
      } catch (const Error& e) {
        send_json_refusal(res, Refusal(400, e.diagnostic().message));
      }
    });
    http.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, std::exception_ptr e) {
          std::string why = "the tool failed on this request";
          try {
            std::rethrow_exception(std::move(e));
          } catch (const std::exception& x) {
            why += std::string(": ") + x.what();
          } catch (...) {
          }
          res.status = 500;
          res.set_content(refusal_page(500, why), "text/html; charset=utf-8");
        });
  }

  // --- Dynamic Registration 1.0
  void on_register(const httplib::Request& req, httplib::Response& res);
  // --- Third-party initiated login (Security Framework 5.1.1)
  void on_login(const httplib::Request& req, httplib::Response& res);
  void on_launch(const httplib::Request& req, httplib::Response& res);
  LaunchRecord launch_record(const LaunchClaims& c, const LoginState& s);
  void launch_page(const LaunchRecord& l, httplib::Response& res);
  void on_deep_link(const httplib::Request& req, httplib::Response& res);
  void on_submit(const httplib::Request& req, httplib::Response& res);
  void on_report(const httplib::Request& req, httplib::Response& res);
  void on_gradebook(const httplib::Request& req, httplib::Response& res);
  void on_regrade(const httplib::Request& req, httplib::Response& res);
  ClassList class_list(const LaunchRecord& l);

  // The launch a request belongs to: its id, this browser's session cookie and, for a
  // request that changes something, its CSRF token must go together.
  LaunchRecord session_launch(const httplib::Request& req, const std::string& launch_id,
                              const std::string* csrf) {
    auto l = store->find_launch(launch_id);
    if (!l) throw Refusal(403, "no launch has that id");
    if (!same_secret(cookie(req, "raygrade_session"), l->session))
      throw Refusal(403, "this browser's session is not the one of that launch");
    if (csrf && !same_secret(*csrf, l->csrf))
      throw Refusal(403, "the request's token (csrf) is not the launch's");
    if (l->expires <= now_seconds()) throw Refusal(403, "the launch has expired: launch again");
    return *l;
  }

  LaunchRecord instructor_launch(const httplib::Request& req, const std::string& launch_id,
                                 const std::string* csrf) {
    LaunchRecord l = session_launch(req, launch_id, csrf);
    if (!l.instructor) throw Refusal(403, "only an instructor's launch may see this");
    return l;
  }

  const CatalogEntry& entry_of(const LaunchRecord& l) const {
    const CatalogEntry* e = catalog.find(l.assignment);
    if (!e) throw Refusal(400, "the assignment '" + l.assignment + "' is not in the folder");
    return *e;
  }
};

void LtiServer::Impl::on_register(const httplib::Request& req, httplib::Response& res) {
  std::string config_url = param(req, "openid_configuration");
  std::string token = param(req, "registration_token");
  if (config_url.empty()) throw Refusal(400, "no openid_configuration was given");
  HttpAnswer a = http_get(config_url);
  nlohmann::json config = nlohmann::json::parse(a.body, nullptr, false);
  if (a.status != 200 || !config.is_object())
    throw Refusal(400, "the platform's OpenID configuration could not be read");
  auto text = [&](const char* name) {
    if (!config.contains(name) || !config[name].is_string())
      throw Refusal(400, std::string("the platform's OpenID configuration has no ") + name);
    return config[name].get<std::string>();
  };
  std::string issuer = text("issuer");
  // The configuration must come from its issuer's own origin.
  if (split_url(config_url).first != split_url(issuer).first)
    throw Refusal(400, "the OpenID configuration is not served from its issuer's origin");
  nlohmann::json request = {
      {"application_type", "web"},
      {"response_types", {"id_token"}},
      {"grant_types", {"implicit", "client_credentials"}},
      {"initiate_login_uri", url("/lti/login")},
      {"redirect_uris", {url("/lti/launch")}},
      {"client_name", "raygrade"},
      {"jwks_uri", url("/lti/jwks")},
      {"token_endpoint_auth_method", "private_key_jwt"},
      {"scope",
       "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem "
       "https://purl.imsglobal.org/spec/lti-ags/scope/score "
       "https://purl.imsglobal.org/spec/lti-ags/scope/result.readonly "
       "https://purl.imsglobal.org/spec/lti-nrps/scope/contextmembership.readonly"},
      {"https://purl.imsglobal.org/spec/lti-tool-configuration",
       {{"domain", split_url(options.public_url)
                       .first.substr(split_url(options.public_url).first.find("://") + 3)},
        {"target_link_uri", url("/lti/launch")},
        {"claims", {"iss", "sub", "name", "email"}},
        {"messages",
         {{{"type", "LtiResourceLinkRequest"}, {"target_link_uri", url("/lti/launch")}},
          {{"type", "LtiDeepLinkingRequest"}, {"target_link_uri", url("/lti/launch")}}}}}}};
  HttpHeaders headers;
  if (!token.empty()) headers.emplace("Authorization", "Bearer " + token);
  HttpAnswer made =
      http_post(text("registration_endpoint"), request.dump(), "application/json", headers);
  nlohmann::json client = nlohmann::json::parse(made.body, nullptr, false);
  if (made.status < 200 || made.status >= 300 || !client.is_object() ||
      !client.contains("client_id") || !client["client_id"].is_string())
    throw Refusal(400, fmt::format("the platform refused the registration (HTTP {})", made.status));
  Registration r;
  r.issuer = issuer;
  r.client_id = client["client_id"];
  r.auth_url = text("authorization_endpoint");
  r.token_url = text("token_endpoint");
  r.jwks_url = text("jwks_uri");
  auto tool = client.find("https://purl.imsglobal.org/spec/lti-tool-configuration");
  if (tool != client.end() && tool->is_object() && tool->contains("deployment_id") &&
      (*tool)["deployment_id"].is_string())
    r.deployments.push_back((*tool)["deployment_id"]);
  store->add_registration(r);
  res.set_content(registration_done_page(r.issuer, r.client_id), "text/html; charset=utf-8");
}

void LtiServer::Impl::on_login(const httplib::Request& req, httplib::Response& res) {
  std::string issuer = param(req, "iss");
  std::string client_id = param(req, "client_id");
  if (issuer.empty() || param(req, "login_hint").empty())
    throw Refusal(400, "a login needs iss and login_hint");
  std::vector<Registration> regs = store->registrations(issuer);
  const Registration* reg = nullptr;
  for (const auto& r : regs)
    if (r.client_id == client_id || (client_id.empty() && regs.size() == 1)) reg = &r;
  if (!reg) throw Refusal(400, "the platform '" + issuer + "' is not registered with this tool");
  std::string deployment = param(req, "lti_deployment_id");
  if (!deployment.empty() && std::find(reg->deployments.begin(), reg->deployments.end(),
                                       deployment) == reg->deployments.end())
    throw Refusal(400, "the deployment '" + deployment + "' is not registered with this tool");
  LoginState s{random_token(), random_token(), random_token(),
               reg->issuer,    reg->client_id, now_seconds() + kLoginSeconds};
  store->add_login_state(s);
  std::map<std::string, std::string> query = {{"scope", "openid"},
                                              {"response_type", "id_token"},
                                              {"response_mode", "form_post"},
                                              {"prompt", "none"},
                                              {"client_id", reg->client_id},
                                              {"redirect_uri", url("/lti/launch")},
                                              {"login_hint", param(req, "login_hint")},
                                              {"state", s.state},
                                              {"nonce", s.nonce}};
  if (req.has_param("lti_message_hint")) query["lti_message_hint"] = param(req, "lti_message_hint");
  set_cookie(res, "raygrade_state", s.browser, kLoginSeconds);
  std::string sep = reg->auth_url.find('?') == std::string::npos ? "?" : "&";
  res.set_redirect(reg->auth_url + sep + form_encode(query), 302);
}

LaunchRecord LtiServer::Impl::launch_record(const LaunchClaims& c, const LoginState& s) {
  LaunchRecord l;
  l.launch_id = random_token(18);
  l.session = random_token();
  l.csrf = random_token();
  l.issuer = s.issuer;
  l.client_id = s.client_id;
  l.deployment_id = c.deployment_id;
  l.sub = c.sub;
  l.name = c.name;
  l.roles = nlohmann::json(c.roles).dump();
  l.instructor = c.instructor();
  l.message_type = c.message_type;
  l.context_id = c.context_id;
  l.resource_link_id = c.resource_link_id;
  l.lineitem = c.lineitem;
  l.lineitems = c.lineitems;
  l.deep_link_return_url = c.deep_link_return_url;
  l.deep_link_data = c.deep_link_data;
  l.expires = now_seconds() + kSessionSeconds;
  if (c.message_type == kResourceLinkRequest) {
    std::string name = c.custom.is_object() ? c.custom.value("assignment", "") : "";
    if (name.empty() && catalog.entries().size() == 1) name = catalog.entries().front()->name;
    if (name.empty()) throw Refusal(400, "the link names no assignment (custom assignment)");
    if (!catalog.find(name))
      throw Refusal(400, "the assignment '" + name + "' is not in this tool's folder");
    l.assignment = name;
  }
  return l;
}

void LtiServer::Impl::on_launch(const httplib::Request& req, httplib::Response& res) {
  std::string token = param(req, "id_token");
  std::string state = param(req, "state");
  if (token.empty() || state.empty()) throw Refusal(400, "a launch needs id_token and state");
  std::int64_t now = now_seconds();
  auto s = store->find_login_state(state, now);
  if (!s) throw Refusal(400, "the state is unknown, used already or expired: log in again");
  if (!same_secret(cookie(req, "raygrade_state"), s->browser))
    throw Refusal(403, "this login was started in another browser (the state cookie differs)");
  auto reg = store->find_registration(s->issuer, s->client_id);
  if (!reg) throw Refusal(400, "the platform is no longer registered");
  DecodedJwt jwt = verify_platform_jwt(
      token, [&](const std::string& named) { return keys.find(reg->jwks_url, named); });
  LaunchClaims c = check_launch_claims(
      jwt.payload, LaunchExpectation{reg->issuer, reg->client_id, reg->deployments, s->nonce, now});
  LaunchRecord l = launch_record(c, *s);
  if (!store->complete_launch(state, l)) throw Refusal(400, "the state was used already");
  // Where the course's roster is served: read when an instructor opens the report.
  if (!c.memberships_url.empty() && !c.context_id.empty())
    store->set_memberships_url(l.issuer, l.client_id, c.context_id, c.memberships_url);
  set_cookie(res, "raygrade_session", l.session, kSessionSeconds);
  launch_page(l, res);
}

void LtiServer::Impl::launch_page(const LaunchRecord& l, httplib::Response& res) {
  nlohmann::json launch = {{"launch", l.launch_id}, {"csrf", l.csrf}};
  if (l.message_type == kDeepLinkingRequest) {
    std::vector<PickerItem> items;
    for (const auto& e : catalog.entries()) items.push_back({e->name, e->title(), e->points()});
    res.set_content(picker_page(items, url("/lti/deep-link"), l.launch_id, l.csrf),
                    "text/html; charset=utf-8");
    return;
  }
  const CatalogEntry& e = entry_of(l);
  launch["submit"] = url("/lti/submit");
  launch["assignment"] = l.assignment;
  if (l.instructor) {
    launch["role"] = "instructor";
    int count = static_cast<int>(
        store->submissions(l.issuer, l.client_id, l.resource_link_id, l.assignment).size());
    res.set_content(instructor_page(e.title(), options.public_url, launch, count),
                    "text/html; charset=utf-8");
    return;
  }
  std::string student = student_key_of(l.issuer, l.sub);
  StudentIdentity who{l.name, student, ""};
  std::vector<Problem> problems = student_problems(e.spec, e.bank.problems, student);
  nlohmann::json forms = nlohmann::json::object();
  for (const auto& p : problems) forms[p.id] = answer_form(p);
  launch["form"] = forms;
  launch["student"] = student;
  launch["role"] = "learner";
  // What the student's last submission to this link scored: points are shown under every
  // feedback policy.
  for (const auto& s : store->submissions(l.issuer, l.client_id, l.resource_link_id, l.assignment))
    if (s.sub == l.sub)
      launch["last"] = {{"submission", s.id},
                        {"score", s.score},
                        {"max", s.max_score},
                        {"at", iso_utc_time(s.created)}};
  Handout h = make_handout(e.spec, problems, &who);
  res.set_content(student_page(h.html, launch), "text/html; charset=utf-8");
}

void LtiServer::Impl::on_deep_link(const httplib::Request& req, httplib::Response& res) {
  std::string csrf = param(req, "csrf");
  LaunchRecord l = session_launch(req, param(req, "launch"), &csrf);
  if (l.message_type != kDeepLinkingRequest)
    throw Refusal(403, "that launch is not a deep linking request");
  const CatalogEntry* e = catalog.find(param(req, "assignment"));
  if (!e) throw Refusal(400, "no such assignment in this tool's folder");
  std::int64_t now = now_seconds();
  nlohmann::json item = {{"type", "ltiResourceLink"},
                         {"title", e->title()},
                         {"url", url("/lti/launch")},
                         {"custom", {{"assignment", e->name}}},
                         {"lineItem",
                          {{"scoreMaximum", e->points()},
                           {"label", e->title()},
                           {"resourceId", e->name},
                           {"tag", "raygrade"}}}};
  nlohmann::json payload = {{"iss", l.client_id},
                            {"aud", l.issuer},
                            {"iat", now},
                            {"exp", now + kLoginSeconds},
                            {"nonce", random_token()},
                            {std::string(kClaimPrefix) + "message_type", "LtiDeepLinkingResponse"},
                            {std::string(kClaimPrefix) + "version", "1.3.0"},
                            {std::string(kClaimPrefix) + "deployment_id", l.deployment_id},
                            {std::string(kDlClaimPrefix) + "content_items", {item}}};
  if (!l.deep_link_data.empty()) payload[std::string(kDlClaimPrefix) + "data"] = l.deep_link_data;
  res.set_content(deep_link_return_page(l.deep_link_return_url, sign_jwt(payload, key.get(), kid)),
                  "text/html; charset=utf-8");
}

void LtiServer::Impl::on_submit(const httplib::Request& req, httplib::Response& res) {
  nlohmann::json body = nlohmann::json::parse(req.body, nullptr, false);
  if (!body.is_object() || !body.contains("launch") || !body["launch"].is_string() ||
      !body.contains("csrf") || !body["csrf"].is_string())
    throw Refusal(400, "a submission is {\"launch\", \"csrf\", \"answers\"}");
  std::string csrf = body["csrf"];
  LaunchRecord l = session_launch(req, body["launch"], &csrf);
  if (l.message_type != kResourceLinkRequest)
    throw Refusal(403, "that launch is not an assignment's");
  if (!body.contains("answers") || !body["answers"].is_object())
    throw Refusal(400, "the submission's answers are not an object");
  const CatalogEntry& e = entry_of(l);
  std::int64_t now = now_seconds();
  StudentIdentity who{l.name, student_key_of(l.issuer, l.sub), ""};
  SubmissionGrade g = grade_answers(e, who, body["answers"], now);
  if (!g.gradable) throw Refusal(400, g.fault ? g.fault->message : "the answers were not graded");
  SubmissionRecord r;
  r.launch_id = l.launch_id;
  r.issuer = l.issuer;
  r.client_id = l.client_id;
  r.sub = l.sub;
  r.context_id = l.context_id;
  r.resource_link_id = l.resource_link_id;
  r.assignment = l.assignment;
  r.answers = body["answers"].dump();
  r.result = submission_json(g).dump();
  r.score = g.score;
  r.max_score = g.max_score;
  r.created = now;
  std::optional<OutboxRow> score;
  if (!l.lineitem.empty() || !l.lineitems.empty()) {
    OutboxRow o;
    o.issuer = l.issuer;
    o.client_id = l.client_id;
    o.lineitem = l.lineitem;
    o.lineitems = l.lineitems;
    o.resource_link_id = l.resource_link_id;
    o.label = e.title();
    o.user_id = l.sub;
    o.score = g.score;
    o.max_score = g.max_score;
    o.timestamp = iso_time_ms(now_ms());
    score = o;
  }
  std::int64_t id = store->add_submission(r, score);
  if (score) outbox->wake();
  nlohmann::json answer = {{"submission", id},
                           {"score", g.score},
                           {"max", g.max_score},
                           {"feedback", feedback_at(e, std::move(g), now)}};
  res.set_content(answer.dump(), "application/json");
}

// The course's roster read again from the platform (NRPS) and kept; when it cannot be read, the
// one read last, and a note saying so.
ClassList LtiServer::Impl::class_list(const LaunchRecord& l) {
  ClassList list;
  list.issuer = l.issuer;
  if (l.context_id.empty()) return list;
  Roster roster = store->roster(l.issuer, l.client_id, l.context_id);
  list.members = roster.members;
  if (roster.memberships_url.empty()) {
    list.note =
        "The platform gave no class list (Names and Role Provisioning Services) for this "
        "course: only the students who submitted are listed.";
    return list;
  }
  try {
    auto reg = store->find_registration(l.issuer, l.client_id);
    if (!reg) throw std::runtime_error("the platform is no longer registered");
    std::string token = tokens->get(*reg, std::string(kNrpsScope));
    std::vector<Member> members = read_memberships(roster.memberships_url, token);
    store->set_members(l.issuer, l.client_id, l.context_id, members, now_seconds());
    list.members = std::move(members);
  } catch (const std::exception& e) {
    // A token the platform no longer takes is asked for again next time.
    tokens->forget();
    list.note = fmt::format(
        "The class list could not be read from the platform ({}); {}.", e.what(),
        roster.read_at == 0 ? "only the students who submitted are listed"
                            : "the list read at " + iso_utc_time(roster.read_at) + " is shown");
    if (options.log) options.log("roster of " + l.context_id + " not read: " + e.what());
  }
  return list;
}

void LtiServer::Impl::on_report(const httplib::Request& req, httplib::Response& res) {
  LaunchRecord l = instructor_launch(req, param(req, "launch"), nullptr);
  const CatalogEntry& e = entry_of(l);
  ClassList list = class_list(l);
  auto subs = store->submissions(l.issuer, l.client_id, l.resource_link_id, l.assignment);
  res.set_content(class_report_page(e, subs, list), "text/html; charset=utf-8");
}

void LtiServer::Impl::on_gradebook(const httplib::Request& req, httplib::Response& res) {
  LaunchRecord l = instructor_launch(req, param(req, "launch"), nullptr);
  const CatalogEntry& e = entry_of(l);
  ClassList list = class_list(l);
  auto subs = store->submissions(l.issuer, l.client_id, l.resource_link_id, l.assignment);
  res.set_header("Content-Disposition", "attachment; filename=\"gradebook.csv\"");
  res.set_content(gradebook_of(e, subs, list), "text/csv; charset=utf-8");
}

void LtiServer::Impl::on_regrade(const httplib::Request& req, httplib::Response& res) {
  auto field = [&](const char* name) {
    if (req.has_file(name)) return req.get_file_value(name).content;
    return param(req, name);
  };
  std::string csrf = field("csrf");
  LaunchRecord l = instructor_launch(req, field("launch"), &csrf);
  const CatalogEntry& e = entry_of(l);
  std::vector<BankFile> bank;
  auto [from, to] = req.files.equal_range("bank");
  for (auto it = from; it != to; ++it)
    if (!it->second.content.empty()) bank.push_back({it->second.filename, it->second.content});
  if (bank.empty()) throw Refusal(400, "no bank file was sent");
  auto subs = store->submissions(l.issuer, l.client_id, l.resource_link_id, l.assignment);
  std::vector<Regraded> changed = regrade_with(e, subs, bank, options.data_dir);
  std::string body = fmt::format("<h1>Regraded {}</h1>\n<p>{} students' scores changed.</p>\n<ul>",
                                 html_escape(e.title()), changed.size());
  for (const auto& c : changed) {
    body += fmt::format("<li>{}: {} → {}</li>", html_escape(c.sub), c.before, c.after);
    if (l.lineitem.empty() && l.lineitems.empty()) continue;
    OutboxRow o;
    o.issuer = l.issuer;
    o.client_id = l.client_id;
    o.lineitem = l.lineitem;
    o.lineitems = l.lineitems;
    o.resource_link_id = l.resource_link_id;
    o.label = e.title();
    o.user_id = c.sub;
    o.score = c.after;
    o.max_score = c.max_score;
    o.timestamp = iso_time_ms(now_ms());
    store->add_score(o);
  }
  outbox->wake();
  res.set_content(page("Regraded", body + "</ul>"), "text/html; charset=utf-8");
}

LtiServer::LtiServer(ServeOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

LtiServer::~LtiServer() {
  stop();
  impl_->outbox->stop();
}

int LtiServer::bind(const std::string& host, int port) {
  bool bound = port == 0 ? (port = impl_->http.bind_to_any_port(host)) > 0
                         : impl_->http.bind_to_port(host, port);
  if (!bound) {
    throw Error(Diagnostic{host, "", 0, 0, Severity::kError,
                           fmt::format("cannot listen on {}:{}", host, port), "listen"});
  }
  widen_backlog(port);
  if (impl_->options.public_url.empty())
    impl_->set_public_url(fmt::format("http://{}:{}", host, port));
  return port;
}

void LtiServer::run() {
  impl_->outbox->start();
  impl_->http.listen_after_bind();
  impl_->outbox->stop();
}

void LtiServer::stop() { impl_->http.stop(); }

const std::vector<Diagnostic>& LtiServer::warnings() const { return impl_->catalog.errors(); }

const std::string& LtiServer::public_url() const { return impl_->options.public_url; }

void register_platform(const std::string& data_dir, const std::string& database,
                       const ManualRegistration& m) {
  auto store = open_store(database, data_dir);
  store->add_registration(Registration{
      0, m.issuer, m.client_id, m.auth_url, m.token_url, m.jwks_url, {m.deployment_id}});
}

}  // namespace raygrade::serve
