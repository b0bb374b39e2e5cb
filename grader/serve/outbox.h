// The scores' outbox: a thread that sends each stored score to its platform's line item by
// Assignment and Grade Services 2.0, retrying with a doubling delay until it is delivered.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "serve/jwt.h"
#include "serve/store.h"

namespace raygrade::serve {

// The longest wait between two tries of one score.
inline constexpr std::int64_t kOutboxMaxDelayMs = 30000;

// The delay before try `attempts` + 1 of a score after `attempts` failed ones: `base_ms`,
// doubled each time, at most kOutboxMaxDelayMs.
std::int64_t outbox_delay_ms(int attempts, std::int64_t base_ms);

// "2026-12-07T19:20:01.250Z".
std::string iso_time_ms(std::int64_t ms);
std::int64_t now_ms();

class Outbox {
 public:
  // `log`, when set, is told of each score that could not be delivered, and why.
  Outbox(Store& store, EVP_PKEY* tool_key, std::string kid, std::int64_t base_ms,
         std::function<void(const std::string&)> log = nullptr);
  ~Outbox();
  Outbox(const Outbox&) = delete;
  Outbox& operator=(const Outbox&) = delete;

  void start();
  void stop();
  // A score was stored: look now rather than at the next tick.
  void wake();

 private:
  void loop();
  // Sends one score; throws std::runtime_error saying why it could not.
  void deliver(const OutboxRow& row);
  std::string access_token(const Registration& r, const std::string& scope);
  std::string find_line_item(const OutboxRow& row, const Registration& r);

  Store& store_;
  EVP_PKEY* key_;
  std::string kid_;
  std::int64_t base_ms_;
  std::function<void(const std::string&)> log_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool stopping_ = false;
  bool woken_ = false;
  std::thread thread_;
  struct Token {
    std::string value;
    std::int64_t expires_ms = 0;
  };
  std::map<std::string, Token> tokens_;  // by token URL, client and scope
};

}  // namespace raygrade::serve
