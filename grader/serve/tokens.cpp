// The platform's access tokens, asked for with a signed client assertion and kept.
#include "serve/tokens.h"

#include <stdexcept>

#include "serve/http_client.h"
#include "serve/outbox.h"

namespace raygrade::serve {

std::string AccessTokens::get(const Registration& r, const std::string& scope) {
  std::string cache_key = r.token_url + "\n" + r.client_id + "\n" + scope;
  std::int64_t now = now_ms();
  {
    std::lock_guard lock(mutex_);
    auto it = tokens_.find(cache_key);
    if (it != tokens_.end() && it->second.expires_ms > now) return it->second.value;
  }
  nlohmann::json assertion = {{"iss", r.client_id},      {"sub", r.client_id},
                              {"aud", r.token_url},      {"iat", now / 1000},
                              {"exp", now / 1000 + 300}, {"jti", random_token(16)}};
  std::string body = form_encode(
      {{"grant_type", "client_credentials"},
       {"client_assertion_type", "urn:ietf:params:oauth:client-assertion-type:jwt-bearer"},
       {"client_assertion", sign_jwt(assertion, key_, kid_)},
       {"scope", scope}});
  HttpAnswer a = http_post(r.token_url, body, "application/x-www-form-urlencoded");
  if (!http_ok(a)) throw std::runtime_error(http_failure("token endpoint", a));
  nlohmann::json j = nlohmann::json::parse(a.body, nullptr, false);
  if (!j.is_object() || !j.contains("access_token") || !j["access_token"].is_string())
    throw std::runtime_error("token endpoint: no access_token in its answer");
  double lifetime = j.contains("expires_in") && j["expires_in"].is_number()
                        ? j["expires_in"].get<double>()
                        : 3600;
  // Renewed a minute early, so that a token does not run out between asking and using it.
  Token t{j["access_token"].get<std::string>(),
          now + static_cast<std::int64_t>(lifetime * 1000) - 60000};
  std::lock_guard lock(mutex_);
  tokens_[cache_key] = t;
  return t.value;
}

void AccessTokens::forget() {
  std::lock_guard lock(mutex_);
  tokens_.clear();
}

}  // namespace raygrade::serve
