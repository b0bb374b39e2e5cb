// The access tokens the tool asks a platform for (client credentials with a signed assertion,
// Security Framework 4.1), kept until shortly before they run out: one per token URL, client
// and scope, shared by the outbox's thread and the requests' threads.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "serve/jwt.h"
#include "serve/store.h"

namespace raygrade::serve {

class AccessTokens {
 public:
  AccessTokens(EVP_PKEY* tool_key, std::string kid) : key_(tool_key), kid_(std::move(kid)) {}

  // A token of `scope` from the registration's token URL. Throws std::runtime_error saying why
  // there is none.
  std::string get(const Registration& r, const std::string& scope);
  // Forgets every token (a platform no longer took one).
  void forget();

 private:
  struct Token {
    std::string value;
    std::int64_t expires_ms = 0;
  };
  EVP_PKEY* key_;
  std::string kid_;
  std::mutex mutex_;
  std::map<std::string, Token> tokens_;  // by token URL, client and scope
};

}  // namespace raygrade::serve
