// The scores' outbox: a thread that sends each stored score to its platform's line item by
// Assignment and Grade Services 2.0, retrying with a doubling delay until it is delivered.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "serve/jwt.h"
#include "serve/store.h"
#include "serve/tokens.h"

namespace raygrade::serve {

// The longest wait between two tries of one score.
inline constexpr std::int64_t kOutboxMaxDelayMs = 30000;
// How long a sender holds the scores it claimed (store.h, claim_scores) by default. A delivery
// is at most five HTTP calls of 10 s each (http_client.cpp), and a score is only begun while
// more than half the lease is left, so no other process takes a score being sent; a process
// killed while holding scores delays them by this much.
inline constexpr std::int64_t kOutboxLeaseMs = 300000;

// The delay before try `attempts` + 1 of a score after `attempts` failed ones: `base_ms`,
// doubled each time, at most kOutboxMaxDelayMs.
std::int64_t outbox_delay_ms(int attempts, std::int64_t base_ms);

// "2026-12-07T19:20:01.250Z".
std::string iso_time_ms(std::int64_t ms);
std::int64_t now_ms();

class Outbox {
 public:
  // `log`, when set, is told of each score that could not be delivered, and why. Scores are
  // claimed for `lease_ms` at a time, so that several processes share one outbox.
  Outbox(Store& store, AccessTokens& tokens, std::int64_t base_ms,
         std::function<void(const std::string&)> log = nullptr,
         std::int64_t lease_ms = kOutboxLeaseMs);
  ~Outbox();
  Outbox(const Outbox&) = delete;
  Outbox& operator=(const Outbox&) = delete;

  void start();
  void stop();
  // A score was stored: look now rather than at the next tick.
  void wake();

 private:
  void loop();
  // Sends one claimed score and notes the outcome.
  void send(const OutboxRow& row);
  bool stopping();
  // Sends one score; throws std::runtime_error saying why it could not.
  void deliver(const OutboxRow& row);
  std::string find_line_item(const OutboxRow& row, const Registration& r);

  Store& store_;
  AccessTokens& tokens_;
  std::int64_t base_ms_;
  std::function<void(const std::string&)> log_;
  std::int64_t lease_ms_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool stopping_ = false;
  bool woken_ = false;
  std::thread thread_;
};

}  // namespace raygrade::serve
