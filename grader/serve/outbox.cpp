// The scores' outbox and its delivery by AGS 2.0.
#include "serve/outbox.h"

#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <stdexcept>

#include "serve/http_client.h"

namespace raygrade::serve {

namespace {

constexpr std::string_view kScoreScope = "https://purl.imsglobal.org/spec/lti-ags/scope/score";
constexpr std::string_view kLineItemScope =
    "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem";
// Scores looked at per pass, and the wait between passes when nothing wakes the thread.
constexpr int kBatch = 32;
constexpr std::chrono::milliseconds kTick{250};

// A URL with `suffix` added to its path, before any query.
std::string with_path(const std::string& url, const std::string& suffix) {
  std::size_t q = url.find('?');
  if (q == std::string::npos) return url + suffix;
  return url.substr(0, q) + suffix + url.substr(q);
}

}  // namespace

std::int64_t outbox_delay_ms(int attempts, std::int64_t base_ms) {
  std::int64_t d = base_ms;
  for (int i = 1; i < attempts && d < kOutboxMaxDelayMs; ++i) d *= 2;
  return std::min(d, kOutboxMaxDelayMs);
}

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string iso_time_ms(std::int64_t ms) {
  std::time_t seconds = static_cast<std::time_t>(ms / 1000);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z", tm.tm_year + 1900, tm.tm_mon + 1,
                     tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, ms % 1000);
}

Outbox::Outbox(Store& store, AccessTokens& tokens, std::int64_t base_ms,
               std::function<void(const std::string&)> log, std::int64_t lease_ms)
    : store_(store),
      tokens_(tokens),
      base_ms_(base_ms),
      log_(std::move(log)),
      lease_ms_(lease_ms) {}

Outbox::~Outbox() { stop(); }

void Outbox::start() {
  thread_ = std::thread([this] { loop(); });
}

void Outbox::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void Outbox::wake() {
  {
    std::lock_guard lock(mutex_);
    woken_ = true;
  }
  cv_.notify_all();
}

bool Outbox::stopping() {
  std::lock_guard lock(mutex_);
  return stopping_;
}

void Outbox::loop() {
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      cv_.wait_for(lock, kTick, [this] { return stopping_ || woken_; });
      if (stopping_) return;
      woken_ = false;
    }
    std::vector<OutboxRow> claimed;
    std::int64_t claimed_at = now_ms();
    try {
      claimed = store_.claim_scores(claimed_at, lease_ms_, kBatch);
    } catch (const std::exception&) {
      continue;  // the database is busy or failing: the next pass tries again
    }
    for (std::size_t i = 0; i < claimed.size(); ++i) {
      // A score is begun only with more than half its lease left; the rest go back.
      if (stopping() || now_ms() - claimed_at > lease_ms_ / 2) {
        for (; i < claimed.size(); ++i) {
          try {
            store_.release_claim(claimed[i].id);
          } catch (const std::exception&) {
            // Left claimed: another sender takes it when the lease runs out.
          }
        }
        break;
      }
      send(claimed[i]);
    }
  }
}

void Outbox::send(const OutboxRow& row) {
  try {
    deliver(row);
    store_.mark_delivered(row.id);
  } catch (const std::exception& e) {
    int attempts = row.attempts + 1;
    if (log_) {
      log_(fmt::format("score {} for {} (attempt {}) not delivered: {}", row.id, row.user_id,
                       attempts, e.what()));
    }
    try {
      store_.retry_later(row.id, attempts, now_ms() + outbox_delay_ms(attempts, base_ms_),
                         e.what());
    } catch (const std::exception&) {
      // Left claimed: tried again when the lease runs out.
    }
  }
}

std::string Outbox::find_line_item(const OutboxRow& row, const Registration& r) {
  if (auto known = store_.line_item(row.issuer, row.client_id, row.resource_link_id)) return *known;
  std::string token = tokens_.get(r, std::string(kLineItemScope));
  HttpHeaders auth = {{"Authorization", "Bearer " + token},
                      {"Accept", "application/vnd.ims.lis.v2.lineitemcontainer+json"}};
  std::string query = std::string(row.lineitems.find('?') == std::string::npos ? "?" : "&") +
                      "resource_link_id=" + form_encode({{"", row.resource_link_id}}).substr(1);
  HttpAnswer list = http_get(row.lineitems + query, auth);
  if (!http_ok(list)) throw std::runtime_error(http_failure("line items", list));
  nlohmann::json items = nlohmann::json::parse(list.body, nullptr, false);
  if (items.is_array()) {
    for (const auto& item : items) {
      if (item.is_object() && item.value("resourceLinkId", "") == row.resource_link_id &&
          item.contains("id") && item["id"].is_string()) {
        store_.set_line_item(row.issuer, row.client_id, row.resource_link_id, item["id"]);
        return item["id"];
      }
    }
  }
  nlohmann::json item = {{"scoreMaximum", row.max_score},
                         {"label", row.label},
                         {"resourceLinkId", row.resource_link_id},
                         {"tag", "raygrade"}};
  HttpAnswer made =
      http_post(row.lineitems, item.dump(), "application/vnd.ims.lis.v2.lineitem+json",
                {{"Authorization", "Bearer " + token}});
  nlohmann::json j = nlohmann::json::parse(made.body, nullptr, false);
  if (!http_ok(made) || !j.is_object() || !j.contains("id") || !j["id"].is_string())
    throw std::runtime_error(http_failure("new line item", made));
  store_.set_line_item(row.issuer, row.client_id, row.resource_link_id, j["id"]);
  return j["id"];
}

void Outbox::deliver(const OutboxRow& row) {
  auto r = store_.find_registration(row.issuer, row.client_id);
  if (!r) throw std::runtime_error("the platform is no longer registered");
  std::string lineitem = row.lineitem.empty() ? find_line_item(row, *r) : row.lineitem;
  std::string token = tokens_.get(*r, std::string(kScoreScope));
  nlohmann::json score = {{"userId", row.user_id},
                          {"scoreGiven", row.score},
                          {"scoreMaximum", row.max_score},
                          {"activityProgress", "Completed"},
                          {"gradingProgress", "FullyGraded"},
                          {"timestamp", row.timestamp}};
  HttpAnswer a =
      http_post(with_path(lineitem, "/scores"), score.dump(),
                "application/vnd.ims.lis.v1.score+json", {{"Authorization", "Bearer " + token}});
  if (a.status == 401) tokens_.forget();  // a token the platform no longer takes
  if (!http_ok(a)) throw std::runtime_error(http_failure("scores", a));
}

}  // namespace raygrade::serve
