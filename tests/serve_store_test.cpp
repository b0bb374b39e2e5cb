// The LTI tool's database: a state is used once, a submission and its score are stored
// together, the outbox's delays, and a reopened database keeps everything.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>

#include "serve/outbox.h"
#include "serve/store.h"

namespace serve_store_test {

using raygrade::serve::LaunchRecord;
using raygrade::serve::LoginState;
using raygrade::serve::OutboxRow;
using raygrade::serve::SubmissionRecord;

// A folder of its own for one test's database, removed at the end of the test.
class FreshDir {
 public:
  explicit FreshDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("raygrade-serve-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
  }
  ~FreshDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  FreshDir(const FreshDir&) = delete;
  FreshDir& operator=(const FreshDir&) = delete;
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

LaunchRecord launch(const std::string& id) {
  LaunchRecord l;
  l.launch_id = id;
  l.session = "session-" + id;
  l.csrf = "csrf-" + id;
  l.issuer = "https://lms.example";
  l.client_id = "tool-1";
  l.sub = "s1";
  l.roles = "[]";
  l.message_type = "LtiResourceLinkRequest";
  l.resource_link_id = "rl-1";
  l.assignment = "hw.json";
  l.expires = 2'000'000'000;
  return l;
}

TEST(ServeStore, AStateCompletesOneLaunchOnly) {
  FreshDir dir("state");
  auto store = raygrade::serve::open_sqlite_store(dir.str());
  store->add_login_state(LoginState{"st", "br", "no", "https://lms.example", "tool-1", 1000});
  ASSERT_TRUE(store->find_login_state("st", 999));
  EXPECT_FALSE(store->find_login_state("st", 1000));  // its time has run out
  EXPECT_TRUE(store->complete_launch("st", launch("a")));
  EXPECT_FALSE(store->complete_launch("st", launch("b")));
  EXPECT_FALSE(store->find_login_state("st", 999));
  EXPECT_TRUE(store->find_launch("a"));
  EXPECT_FALSE(store->find_launch("b"));  // refused: nothing stored
}

TEST(ServeStore, ReopenedDatabaseKeepsEverythingAtItsSchemaVersion) {
  FreshDir fresh("reopen");
  std::string dir = fresh.str();
  {
    auto store = raygrade::serve::open_sqlite_store(dir);
    store->set_tool_key("k1", "pem-1");
    store->set_tool_key("k2", "pem-2");  // the first key stays
    store->add_registration({0, "https://lms.example", "tool-1", "a", "t", "j", {"d1"}});
    store->add_registration({0, "https://lms.example", "tool-1", "a", "t", "j", {"d2"}});
    SubmissionRecord s;
    s.issuer = "https://lms.example";
    s.client_id = "tool-1";
    s.sub = "s1";
    s.resource_link_id = "rl-1";
    s.assignment = "hw.json";
    s.score = 3;
    s.max_score = 4;
    OutboxRow o;
    o.lineitem = "https://lms.example/li/1";
    o.score = 3;
    o.max_score = 4;
    store->add_submission(s, o);
  }
  auto store = raygrade::serve::open_sqlite_store(dir);
  EXPECT_EQ(store->tool_key()->first, "k1");
  auto r = store->find_registration("https://lms.example", "tool-1");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->deployments, (std::vector<std::string>{"d1", "d2"}));
  auto subs = store->submissions("https://lms.example", "tool-1", "rl-1", "hw.json");
  ASSERT_EQ(subs.size(), 1u);
  auto out = store->outbox();
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].submission_id, subs[0].id);
  sqlite3* db = nullptr;
  sqlite3_open((dir + "/raygrade.sqlite").c_str(), &db);
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db, "SELECT COUNT(*), MAX(version) FROM schema_version", -1, &st, nullptr);
  ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(st, 0), 1);  // migrated once, not again at reopening
  EXPECT_EQ(sqlite3_column_int(st, 1), 1);
  sqlite3_finalize(st);
  sqlite3_prepare_v2(db, "PRAGMA journal_mode", -1, &st, nullptr);
  ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(st, 0)), "wal");
  sqlite3_finalize(st);
  sqlite3_close(db);
}

TEST(ServeStore, ScoreWaitsForItsNextTryAndIsDeliveredOnce) {
  FreshDir dir("outbox");
  auto store = raygrade::serve::open_sqlite_store(dir.str());
  OutboxRow o;
  o.lineitem = "https://lms.example/li/1";
  store->add_score(o);
  auto due = store->due_scores(0, 10);
  ASSERT_EQ(due.size(), 1u);
  store->retry_later(due[0].id, 1, 5000, "HTTP 503");
  EXPECT_TRUE(store->due_scores(4999, 10).empty());
  ASSERT_EQ(store->due_scores(5000, 10).size(), 1u);
  store->mark_delivered(due[0].id);
  EXPECT_TRUE(store->due_scores(1'000'000, 10).empty());
}

TEST(ServeOutbox, DelayDoublesFromTheBaseUpToThirtySeconds) {
  using raygrade::serve::outbox_delay_ms;
  EXPECT_EQ(outbox_delay_ms(1, 1000), 1000);
  EXPECT_EQ(outbox_delay_ms(2, 1000), 2000);
  EXPECT_EQ(outbox_delay_ms(5, 1000), 16000);
  EXPECT_EQ(outbox_delay_ms(6, 1000), 30000);  // 32 s, capped
  EXPECT_EQ(outbox_delay_ms(50, 1000), 30000);
  EXPECT_EQ(outbox_delay_ms(3, 10), 40);
}

TEST(ServeOutbox, TimestampIsIso8601WithMilliseconds) {
  using raygrade::serve::iso_time_ms;
  EXPECT_EQ(iso_time_ms(0), "1970-01-01T00:00:00.000Z");
  // 1,700,000,000 s is 2023-11-14 22:13:20 UTC.
  EXPECT_EQ(iso_time_ms(1'700'000'000'123), "2023-11-14T22:13:20.123Z");
}

}  // namespace serve_store_test
