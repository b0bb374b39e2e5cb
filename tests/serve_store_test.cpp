// The LTI tool's database, on each backend: a state is used once, a submission and its score
// are stored together, a score is claimed by one sender at a time, a reopened database keeps
// everything, a database of a newer schema is refused. The PostgreSQL cases run when
// RAYGRADE_TEST_PG_HOST and RAYGRADE_TEST_PG_PORT name a server (tests/lti/pgcluster.py starts
// a throwaway one: ctest -R serve_store_pg); they are skipped otherwise.
#include <gtest/gtest.h>
#include <libpq-fe.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "core/error.h"
#include "serve/outbox.h"
#include "serve/store.h"

namespace serve_store_test {

using raygrade::serve::LaunchRecord;
using raygrade::serve::LoginState;
using raygrade::serve::Member;
using raygrade::serve::OutboxRow;
using raygrade::serve::Roster;
using raygrade::serve::Store;
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

// The database of one test on one backend: a fresh SQLite folder or a fresh PostgreSQL
// database, and a way to run SQL on it behind the store's back.
class Backend {
 public:
  Backend(const std::string& kind, const std::string& name) : kind_(kind), dir_(name) {
    if (kind_ != "postgresql") return;
    const char* host = std::getenv("RAYGRADE_TEST_PG_HOST");
    const char* port = std::getenv("RAYGRADE_TEST_PG_PORT");
    if (!host || !port) return;
    std::string db = "store_" + name + "_" + std::to_string(::getpid());
    admin_ = fmt::format("host={} port={} user=raygrade dbname=postgres", host, port);
    conninfo_ = fmt::format("host={} port={} user=raygrade dbname={}", host, port, db);
    url_ = fmt::format("postgresql://raygrade@/{}?host={}&port={}", db, host, port);
    exec_on(admin_, "DROP DATABASE IF EXISTS " + db);
    exec_on(admin_, "CREATE DATABASE " + db);
  }
  bool available() const { return kind_ == "sqlite" || !url_.empty(); }
  std::unique_ptr<Store> open() const { return raygrade::serve::open_store(url_, dir_.str()); }
  // The first column of the first row of `sql`, as text.
  std::string query(const std::string& sql) const {
    if (kind_ == "postgresql") return exec_on(conninfo_, sql);
    sqlite3* db = nullptr;
    sqlite3_open((dir_.str() + "/raygrade.sqlite").c_str(), &db);
    sqlite3_stmt* st = nullptr;
    std::string out;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &st, nullptr) == SQLITE_OK &&
        sqlite3_step(st) == SQLITE_ROW && sqlite3_column_text(st, 0))
      out = reinterpret_cast<const char*>(sqlite3_column_text(st, 0));
    sqlite3_finalize(st);
    sqlite3_close(db);
    return out;
  }

 private:
  static std::string exec_on(const std::string& conninfo, const std::string& sql) {
    PGconn* c = PQconnectdb(conninfo.c_str());
    PGresult* r = PQexec(c, sql.c_str());
    std::string out = PQntuples(r) > 0 ? PQgetvalue(r, 0, 0) : "";
    EXPECT_TRUE(PQresultStatus(r) == PGRES_TUPLES_OK || PQresultStatus(r) == PGRES_COMMAND_OK)
        << sql << ": " << PQerrorMessage(c);
    PQclear(r);
    PQfinish(c);
    return out;
  }

  std::string kind_;
  FreshDir dir_;
  std::string admin_, conninfo_, url_;
};

class ServeStore : public ::testing::TestWithParam<std::string> {
 protected:
  // The backend for this test, named after it; skips the test when it has no server.
  std::unique_ptr<Backend> backend(const std::string& name) {
    auto b = std::make_unique<Backend>(GetParam(), name);
    return b;
  }
};

#define RAYGRADE_NEED(b)                                                 \
  if (!(b)->available()) {                                               \
    GTEST_SKIP() << "no PostgreSQL server (RAYGRADE_TEST_PG_HOST/PORT)"; \
  }

TEST_P(ServeStore, AStateCompletesOneLaunchOnly) {
  auto b = backend("state");
  RAYGRADE_NEED(b);
  auto store = b->open();
  store->add_login_state(LoginState{"st", "br", "no", "https://lms.example", "tool-1", 1000});
  ASSERT_TRUE(store->find_login_state("st", 999));
  EXPECT_FALSE(store->find_login_state("st", 1000));  // its time has run out
  EXPECT_TRUE(store->complete_launch("st", launch("a")));
  EXPECT_FALSE(store->complete_launch("st", launch("b")));
  EXPECT_FALSE(store->find_login_state("st", 999));
  EXPECT_TRUE(store->find_launch("a"));
  EXPECT_FALSE(store->find_launch("b"));  // refused: nothing stored
}

TEST_P(ServeStore, ReopenedDatabaseKeepsEverythingAtItsSchemaVersion) {
  auto b = backend("reopen");
  RAYGRADE_NEED(b);
  {
    auto store = b->open();
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
    s.score = 2.0 / 3.0;
    s.max_score = 4;
    OutboxRow o;
    o.lineitem = "https://lms.example/li/1";
    o.score = 3;
    o.max_score = 4;
    store->add_submission(s, o);
  }
  auto store = b->open();
  EXPECT_EQ(store->tool_key()->first, "k1");
  auto r = store->find_registration("https://lms.example", "tool-1");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->deployments, (std::vector<std::string>{"d1", "d2"}));
  auto subs = store->submissions("https://lms.example", "tool-1", "rl-1", "hw.json");
  ASSERT_EQ(subs.size(), 1u);
  EXPECT_EQ(subs[0].score, 2.0 / 3.0);  // every bit of the double, not 15 digits
  auto out = store->outbox();
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].submission_id, subs[0].id);
  // Migrated once to each version, not again at reopening: versions 1, 2 (the outbox's
  // claims) and 3 (the rosters).
  EXPECT_EQ(b->query("SELECT COUNT(*) FROM schema_version"), "3");
  EXPECT_EQ(b->query("SELECT MAX(version) FROM schema_version"), "3");
  EXPECT_EQ(raygrade::serve::kSchemaVersion, 3);
  if (GetParam() == "sqlite") {
    EXPECT_EQ(b->query("PRAGMA journal_mode"), "wal");
  }
}

TEST_P(ServeStore, ScoreWaitsForItsNextTryAndIsDeliveredOnce) {
  auto b = backend("outbox");
  RAYGRADE_NEED(b);
  auto store = b->open();
  OutboxRow o;
  o.lineitem = "https://lms.example/li/1";
  store->add_score(o);
  auto due = store->claim_scores(0, 100, 10);
  ASSERT_EQ(due.size(), 1u);
  store->retry_later(due[0].id, 1, 5000, "HTTP 503");
  EXPECT_TRUE(store->claim_scores(4999, 100, 10).empty());
  ASSERT_EQ(store->claim_scores(5000, 100, 10).size(), 1u);
  store->mark_delivered(due[0].id);
  EXPECT_TRUE(store->claim_scores(1'000'000, 100, 10).empty());
}

TEST_P(ServeStore, AClaimedScoreIsOneSendersUntilItsLeaseRunsOut) {
  auto b = backend("claim");
  RAYGRADE_NEED(b);
  auto first = b->open();
  auto second = b->open();  // another process on the same database
  for (int i = 0; i < 3; ++i) first->add_score(OutboxRow{});
  auto mine = first->claim_scores(1000, 500, 2);  // held until 1500
  ASSERT_EQ(mine.size(), 2u);
  EXPECT_LT(mine[0].id, mine[1].id);
  EXPECT_EQ(mine[0].claimed_until_ms, 1500);
  auto theirs = second->claim_scores(1200, 500, 10);  // held until 1700
  ASSERT_EQ(theirs.size(), 1u);                       // the third only
  EXPECT_GT(theirs[0].id, mine[1].id);
  EXPECT_TRUE(second->claim_scores(1499, 500, 10).empty());
  // The first sender was killed: at 1500 its claims are anyone's.
  EXPECT_EQ(second->claim_scores(1500, 500, 10).size(), 2u);
  // Given back by a sender that stops: free at once.
  second->release_claim(mine[0].id);
  EXPECT_EQ(first->claim_scores(1500, 500, 10).size(), 1u);
}

TEST_P(ServeStore, ADatabaseOfANewerSchemaIsRefused) {
  auto b = backend("newer");
  RAYGRADE_NEED(b);
  b->open();  // made at the current version
  b->query("INSERT INTO schema_version VALUES (4)");
  try {
    b->open();
    ADD_FAILURE() << "a database of schema version 4 was opened";
  } catch (const raygrade::Error& e) {
    EXPECT_NE(e.diagnostic().message.find("schema is version 4, newer than this raygrade knows "
                                          "(version 3)"),
              std::string::npos)
        << e.diagnostic().message;
  }
}

TEST_P(ServeStore, ARosterIsReplacedWholeAndKeepsItsOrder) {
  auto b = backend("roster");
  RAYGRADE_NEED(b);
  auto store = b->open();
  const std::string lms = "https://lms.example";
  EXPECT_TRUE(store->roster(lms, "tool-1", "c1").memberships_url.empty());
  store->set_memberships_url(lms, "tool-1", "c1", "https://lms.example/nrps/c1");
  std::vector<Member> read = {{"zoe", "Zoë", "z@x", "[]", "Active"},
                              {"ada", "Ada", "a@x", "[]", "Inactive"},
                              {"zoe", "Zoë again", "", "[]", "Active"}};  // twice: the first kept
  store->set_members(lms, "tool-1", "c1", read, 1000);
  store->set_memberships_url(lms, "tool-1", "c1", "https://lms.example/nrps/c1?v=2");
  Roster r = store->roster(lms, "tool-1", "c1");
  EXPECT_EQ(r.memberships_url, "https://lms.example/nrps/c1?v=2");
  EXPECT_EQ(r.read_at, 1000);
  ASSERT_EQ(r.members.size(), 2u);
  EXPECT_EQ(r.members[0].user_id, "zoe");
  EXPECT_EQ(r.members[0].name, "Zoë");
  EXPECT_EQ(r.members[1].status, "Inactive");
  // Read again: the members of the new read only; another course untouched.
  store->set_members(lms, "tool-1", "c2", {{"bob", "Bob", "", "[]", "Active"}}, 5);
  store->set_members(lms, "tool-1", "c1", {{"ada", "Ada", "a@x", "[]", "Active"}}, 2000);
  r = store->roster(lms, "tool-1", "c1");
  ASSERT_EQ(r.members.size(), 1u);
  EXPECT_EQ(r.members[0].status, "Active");
  EXPECT_EQ(r.memberships_url, "https://lms.example/nrps/c1?v=2");
  EXPECT_EQ(store->roster(lms, "tool-1", "c2").members.size(), 1u);
}

std::string backend_name(const ::testing::TestParamInfo<std::string>& p) { return p.param; }

INSTANTIATE_TEST_SUITE_P(Backends, ServeStore, ::testing::Values("sqlite", "postgresql"),
                         backend_name);

TEST(ServeDatabase, UrlShownWithoutItsPassword) {
  using raygrade::serve::redacted_url;
  EXPECT_EQ(redacted_url("postgresql://ray:s3cret@db.example.edu:5433/raygrade"),
            "postgresql://ray:***@db.example.edu:5433/raygrade");
  EXPECT_EQ(redacted_url("postgresql://ray@db.example.edu/raygrade"),
            "postgresql://ray@db.example.edu/raygrade");
  EXPECT_EQ(redacted_url("postgresql:///raygrade?host=/run/postgresql"),
            "postgresql:///raygrade?host=/run/postgresql");
}

TEST(ServeDatabase, OnlyPostgresUrlsOrSqlite) {
  EXPECT_TRUE(raygrade::serve::is_postgres_url("postgres://db/x"));
  EXPECT_TRUE(raygrade::serve::is_postgres_url("postgresql://db/x"));
  EXPECT_THROW(raygrade::serve::open_store("mysql://db/x", "/nonexistent"), raygrade::Error);
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
