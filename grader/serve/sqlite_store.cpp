// The Store on SQLite: one connection behind a mutex, WAL and synchronous=FULL, so that a
// method's commit is on disk when it returns.
#include <fmt/format.h>
#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "core/error.h"
#include "serve/store.h"

namespace raygrade::serve {

namespace {

// The schema, one entry per version: a database at version v runs the entries after v. The
// same versions as PostgreSQL's (postgres_store.cpp), in SQLite's words.
const char* const kMigrations[] = {
    R"(CREATE TABLE registrations (
         id INTEGER PRIMARY KEY, issuer TEXT NOT NULL, client_id TEXT NOT NULL,
         auth_url TEXT NOT NULL, token_url TEXT NOT NULL, jwks_url TEXT NOT NULL,
         UNIQUE (issuer, client_id));
       CREATE TABLE deployments (
         registration_id INTEGER NOT NULL REFERENCES registrations(id),
         deployment_id TEXT NOT NULL, PRIMARY KEY (registration_id, deployment_id));
       CREATE TABLE tool_keys (kid TEXT PRIMARY KEY, pem TEXT NOT NULL, created INTEGER NOT NULL);
       CREATE TABLE login_states (
         state TEXT PRIMARY KEY, browser TEXT NOT NULL, nonce TEXT NOT NULL,
         issuer TEXT NOT NULL, client_id TEXT NOT NULL, expires INTEGER NOT NULL,
         used INTEGER NOT NULL DEFAULT 0);
       CREATE TABLE launches (
         launch_id TEXT PRIMARY KEY, session TEXT NOT NULL, csrf TEXT NOT NULL,
         issuer TEXT NOT NULL, client_id TEXT NOT NULL, deployment_id TEXT NOT NULL,
         sub TEXT NOT NULL, name TEXT NOT NULL, roles TEXT NOT NULL, instructor INTEGER NOT NULL,
         message_type TEXT NOT NULL, context_id TEXT NOT NULL, resource_link_id TEXT NOT NULL,
         assignment TEXT NOT NULL, lineitem TEXT NOT NULL, lineitems TEXT NOT NULL,
         deep_link_return_url TEXT NOT NULL, deep_link_data TEXT NOT NULL,
         expires INTEGER NOT NULL);
       CREATE TABLE submissions (
         id INTEGER PRIMARY KEY, launch_id TEXT NOT NULL, issuer TEXT NOT NULL,
         client_id TEXT NOT NULL, sub TEXT NOT NULL, context_id TEXT NOT NULL,
         resource_link_id TEXT NOT NULL, assignment TEXT NOT NULL, answers TEXT NOT NULL,
         result TEXT NOT NULL, score REAL NOT NULL, max_score REAL NOT NULL,
         created INTEGER NOT NULL);
       CREATE INDEX submissions_by_link ON submissions (issuer, client_id, resource_link_id);
       CREATE TABLE outbox (
         id INTEGER PRIMARY KEY, submission_id INTEGER NOT NULL, issuer TEXT NOT NULL,
         client_id TEXT NOT NULL, lineitem TEXT NOT NULL, lineitems TEXT NOT NULL,
         resource_link_id TEXT NOT NULL, label TEXT NOT NULL, user_id TEXT NOT NULL,
         score REAL NOT NULL, max_score REAL NOT NULL, timestamp TEXT NOT NULL,
         attempts INTEGER NOT NULL DEFAULT 0, next_try_ms INTEGER NOT NULL DEFAULT 0,
         delivered INTEGER NOT NULL DEFAULT 0, last_error TEXT NOT NULL DEFAULT '');
       CREATE INDEX outbox_due ON outbox (delivered, next_try_ms);
       CREATE TABLE line_items (
         issuer TEXT NOT NULL, client_id TEXT NOT NULL, resource_link_id TEXT NOT NULL,
         url TEXT NOT NULL, PRIMARY KEY (issuer, client_id, resource_link_id));)",
    // 2: several senders share the outbox; a score is held by one until claimed_until.
    R"(ALTER TABLE outbox ADD COLUMN claimed_until INTEGER NOT NULL DEFAULT 0;)",
    // 3: the courses' class lists read from the platform (NRPS).
    R"(CREATE TABLE rosters (
         issuer TEXT NOT NULL, client_id TEXT NOT NULL, context_id TEXT NOT NULL,
         memberships_url TEXT NOT NULL DEFAULT '', read_at INTEGER NOT NULL DEFAULT 0,
         PRIMARY KEY (issuer, client_id, context_id));
       CREATE TABLE members (
         issuer TEXT NOT NULL, client_id TEXT NOT NULL, context_id TEXT NOT NULL,
         user_id TEXT NOT NULL, position INTEGER NOT NULL, name TEXT NOT NULL,
         email TEXT NOT NULL, roles TEXT NOT NULL, status TEXT NOT NULL,
         PRIMARY KEY (issuer, client_id, context_id, user_id));)",
};
static_assert(std::size(kMigrations) == kSchemaVersion, "one migration per schema version");

class Statement {
 public:
  Statement(sqlite3* db, const char* sql, const std::string& file) : db_(db), file_(file) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) fail("prepare");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(const std::string& s) {
    sqlite3_bind_text(stmt_, ++index_, s.data(), static_cast<int>(s.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Statement& bind(std::int64_t v) {
    sqlite3_bind_int64(stmt_, ++index_, v);
    return *this;
  }
  Statement& bind(double v) {
    sqlite3_bind_double(stmt_, ++index_, v);
    return *this;
  }
  // Steps once: true when a row came.
  bool step() {
    int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) fail("step");
    return false;
  }
  void run() {
    while (step()) {
    }
  }
  std::string text(int i) const {
    const unsigned char* t = sqlite3_column_text(stmt_, i);
    return t ? std::string(reinterpret_cast<const char*>(t),
                           static_cast<std::size_t>(sqlite3_column_bytes(stmt_, i)))
             : std::string();
  }
  std::int64_t integer(int i) const { return sqlite3_column_int64(stmt_, i); }
  double real(int i) const { return sqlite3_column_double(stmt_, i); }

 private:
  [[noreturn]] void fail(const char* what) const {
    throw Error(Diagnostic{file_, "", 0, 0, Severity::kError,
                           std::string("database ") + what + ": " + sqlite3_errmsg(db_),
                           "database"});
  }
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
  int index_ = 0;
  const std::string& file_;
};

const char* const kLaunchColumns =
    "launch_id, session, csrf, issuer, client_id, deployment_id, sub, name, roles, instructor, "
    "message_type, context_id, resource_link_id, assignment, lineitem, lineitems, "
    "deep_link_return_url, deep_link_data, expires";
const char* const kOutboxColumns =
    "id, submission_id, issuer, client_id, lineitem, lineitems, resource_link_id, label, "
    "user_id, score, max_score, timestamp, attempts, next_try_ms, delivered, last_error, "
    "claimed_until";

OutboxRow read_outbox(const Statement& s) {
  OutboxRow r;
  r.id = s.integer(0);
  r.submission_id = s.integer(1);
  r.issuer = s.text(2);
  r.client_id = s.text(3);
  r.lineitem = s.text(4);
  r.lineitems = s.text(5);
  r.resource_link_id = s.text(6);
  r.label = s.text(7);
  r.user_id = s.text(8);
  r.score = s.real(9);
  r.max_score = s.real(10);
  r.timestamp = s.text(11);
  r.attempts = static_cast<int>(s.integer(12));
  r.next_try_ms = s.integer(13);
  r.delivered = s.integer(14) != 0;
  r.last_error = s.text(15);
  r.claimed_until_ms = s.integer(16);
  return r;
}

class SqliteStore : public Store {
 public:
  explicit SqliteStore(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    file_ = (std::filesystem::path(dir) / "raygrade.sqlite").string();
    if (sqlite3_open_v2(file_.c_str(), &db_,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
      std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      throw Error(Diagnostic{file_, "", 0, 0, Severity::kError, "cannot open the database: " + why,
                             "database"});
    }
    // A constructor that throws runs no destructor: the connection is closed here (a database
    // of a newer schema, refused by migrate, leaked it).
    try {
      sqlite3_busy_timeout(db_, 5000);
      exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL; PRAGMA foreign_keys=ON;");
      migrate();
      // One server per SQLite database: claims still held were the previous process's, killed
      // before it could give them back; its scores are sent at once rather than after the lease.
      exec("UPDATE outbox SET claimed_until = 0 WHERE claimed_until != 0");
    } catch (...) {
      sqlite3_close_v2(db_);
      db_ = nullptr;
      throw;
    }
  }
  ~SqliteStore() override { sqlite3_close(db_); }

  std::int64_t add_registration(const Registration& r) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    Statement(db_,
              "INSERT INTO registrations (issuer, client_id, auth_url, token_url, jwks_url) "
              "VALUES (?, ?, ?, ?, ?) ON CONFLICT (issuer, client_id) DO UPDATE SET "
              "auth_url = excluded.auth_url, token_url = excluded.token_url, "
              "jwks_url = excluded.jwks_url",
              file_)
        .bind(r.issuer)
        .bind(r.client_id)
        .bind(r.auth_url)
        .bind(r.token_url)
        .bind(r.jwks_url)
        .run();
    Statement id(db_, "SELECT id FROM registrations WHERE issuer = ? AND client_id = ?", file_);
    id.bind(r.issuer).bind(r.client_id).step();
    std::int64_t rid = id.integer(0);
    for (const auto& d : r.deployments) {
      Statement(db_, "INSERT OR IGNORE INTO deployments VALUES (?, ?)", file_)
          .bind(rid)
          .bind(d)
          .run();
    }
    t.commit();
    return rid;
  }

  std::optional<Registration> find_registration(const std::string& issuer,
                                                const std::string& client_id) override {
    for (auto& r : registrations(issuer))
      if (r.client_id == client_id) return r;
    return std::nullopt;
  }

  std::vector<Registration> registrations(const std::string& issuer) override {
    std::lock_guard lock(mutex_);
    std::vector<Registration> out;
    Statement s(db_,
                "SELECT id, issuer, client_id, auth_url, token_url, jwks_url FROM registrations "
                "WHERE issuer = ? ORDER BY id",
                file_);
    s.bind(issuer);
    while (s.step()) {
      Registration r{s.integer(0), s.text(1), s.text(2), s.text(3), s.text(4), s.text(5), {}};
      Statement d(db_, "SELECT deployment_id FROM deployments WHERE registration_id = ?", file_);
      d.bind(r.id);
      while (d.step()) r.deployments.push_back(d.text(0));
      out.push_back(std::move(r));
    }
    return out;
  }

  std::optional<std::pair<std::string, std::string>> tool_key() override {
    std::lock_guard lock(mutex_);
    Statement s(db_, "SELECT kid, pem FROM tool_keys ORDER BY created, kid LIMIT 1", file_);
    if (!s.step()) return std::nullopt;
    return std::make_pair(s.text(0), s.text(1));
  }

  void set_tool_key(const std::string& kid, const std::string& pem) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    Statement count(db_, "SELECT COUNT(*) FROM tool_keys", file_);
    count.step();
    if (count.integer(0) == 0) {
      Statement(db_, "INSERT INTO tool_keys VALUES (?, ?, strftime('%s','now'))", file_)
          .bind(kid)
          .bind(pem)
          .run();
    }
    t.commit();
  }

  void add_login_state(const LoginState& s) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    // States whose time ran out an hour ago are of no use to anyone.
    Statement(db_, "DELETE FROM login_states WHERE expires < ?", file_)
        .bind(s.expires - 4200)
        .run();
    Statement(db_, "INSERT INTO login_states VALUES (?, ?, ?, ?, ?, ?, 0)", file_)
        .bind(s.state)
        .bind(s.browser)
        .bind(s.nonce)
        .bind(s.issuer)
        .bind(s.client_id)
        .bind(s.expires)
        .run();
    t.commit();
  }

  std::optional<LoginState> find_login_state(const std::string& state, std::int64_t now) override {
    std::lock_guard lock(mutex_);
    Statement s(db_,
                "SELECT state, browser, nonce, issuer, client_id, expires FROM login_states "
                "WHERE state = ? AND used = 0 AND expires > ?",
                file_);
    s.bind(state).bind(now);
    if (!s.step()) return std::nullopt;
    return LoginState{s.text(0), s.text(1), s.text(2), s.text(3), s.text(4), s.integer(5)};
  }

  bool complete_launch(const std::string& state, const LaunchRecord& l) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    Statement(db_, "UPDATE login_states SET used = 1 WHERE state = ? AND used = 0", file_)
        .bind(state)
        .run();
    if (sqlite3_changes(db_) != 1) return false;
    std::string sql = fmt::format(
        "INSERT INTO launches ({}) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
        "?)",
        kLaunchColumns);
    Statement(db_, sql.c_str(), file_)
        .bind(l.launch_id)
        .bind(l.session)
        .bind(l.csrf)
        .bind(l.issuer)
        .bind(l.client_id)
        .bind(l.deployment_id)
        .bind(l.sub)
        .bind(l.name)
        .bind(l.roles)
        .bind(std::int64_t{l.instructor})
        .bind(l.message_type)
        .bind(l.context_id)
        .bind(l.resource_link_id)
        .bind(l.assignment)
        .bind(l.lineitem)
        .bind(l.lineitems)
        .bind(l.deep_link_return_url)
        .bind(l.deep_link_data)
        .bind(l.expires)
        .run();
    t.commit();
    return true;
  }

  std::optional<LaunchRecord> find_launch(const std::string& launch_id) override {
    std::lock_guard lock(mutex_);
    std::string sql = fmt::format("SELECT {} FROM launches WHERE launch_id = ?", kLaunchColumns);
    Statement s(db_, sql.c_str(), file_);
    s.bind(launch_id);
    if (!s.step()) return std::nullopt;
    LaunchRecord l;
    l.launch_id = s.text(0);
    l.session = s.text(1);
    l.csrf = s.text(2);
    l.issuer = s.text(3);
    l.client_id = s.text(4);
    l.deployment_id = s.text(5);
    l.sub = s.text(6);
    l.name = s.text(7);
    l.roles = s.text(8);
    l.instructor = s.integer(9) != 0;
    l.message_type = s.text(10);
    l.context_id = s.text(11);
    l.resource_link_id = s.text(12);
    l.assignment = s.text(13);
    l.lineitem = s.text(14);
    l.lineitems = s.text(15);
    l.deep_link_return_url = s.text(16);
    l.deep_link_data = s.text(17);
    l.expires = s.integer(18);
    return l;
  }

  std::int64_t add_submission(const SubmissionRecord& r,
                              const std::optional<OutboxRow>& score) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    Statement(db_,
              "INSERT INTO submissions (launch_id, issuer, client_id, sub, context_id, "
              "resource_link_id, assignment, answers, result, score, max_score, created) "
              "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
              file_)
        .bind(r.launch_id)
        .bind(r.issuer)
        .bind(r.client_id)
        .bind(r.sub)
        .bind(r.context_id)
        .bind(r.resource_link_id)
        .bind(r.assignment)
        .bind(r.answers)
        .bind(r.result)
        .bind(r.score)
        .bind(r.max_score)
        .bind(r.created)
        .run();
    std::int64_t id = sqlite3_last_insert_rowid(db_);
    if (score) {
      OutboxRow o = *score;
      o.submission_id = id;
      insert_score(o);
    }
    t.commit();
    return id;
  }

  std::vector<SubmissionRecord> submissions(const std::string& issuer, const std::string& client_id,
                                            const std::string& resource_link_id,
                                            const std::string& assignment) override {
    std::lock_guard lock(mutex_);
    Statement s(db_,
                "SELECT id, launch_id, issuer, client_id, sub, context_id, resource_link_id, "
                "assignment, answers, result, score, max_score, created FROM submissions "
                "WHERE issuer = ? AND client_id = ? AND resource_link_id = ? AND assignment = ? "
                "ORDER BY id",
                file_);
    s.bind(issuer).bind(client_id).bind(resource_link_id).bind(assignment);
    std::vector<SubmissionRecord> out;
    while (s.step()) {
      out.push_back({s.integer(0), s.text(1), s.text(2), s.text(3), s.text(4), s.text(5), s.text(6),
                     s.text(7), s.text(8), s.text(9), s.real(10), s.real(11), s.integer(12)});
    }
    return out;
  }

  std::vector<OutboxRow> claim_scores(std::int64_t now_ms, std::int64_t lease_ms,
                                      int limit) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    std::string sql = fmt::format(
        "UPDATE outbox SET claimed_until = ? WHERE id IN (SELECT id FROM outbox WHERE "
        "delivered = 0 AND next_try_ms <= ? AND claimed_until <= ? ORDER BY id LIMIT ?) "
        "RETURNING {}",
        kOutboxColumns);
    std::vector<OutboxRow> out;
    {
      Statement s(db_, sql.c_str(), file_);
      s.bind(now_ms + lease_ms).bind(now_ms).bind(now_ms).bind(std::int64_t{limit});
      while (s.step()) out.push_back(read_outbox(s));
    }
    t.commit();
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    return out;
  }

  void release_claim(std::int64_t id) override {
    std::lock_guard lock(mutex_);
    Statement(db_, "UPDATE outbox SET claimed_until = 0 WHERE id = ?", file_).bind(id).run();
  }

  std::vector<OutboxRow> outbox() override {
    std::lock_guard lock(mutex_);
    std::string sql = fmt::format("SELECT {} FROM outbox ORDER BY id", kOutboxColumns);
    Statement s(db_, sql.c_str(), file_);
    std::vector<OutboxRow> out;
    while (s.step()) out.push_back(read_outbox(s));
    return out;
  }

  void add_score(const OutboxRow& score) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    insert_score(score);
    t.commit();
  }

  void mark_delivered(std::int64_t id) override {
    std::lock_guard lock(mutex_);
    Statement(db_,
              "UPDATE outbox SET delivered = 1, last_error = '', claimed_until = 0 WHERE id = ?",
              file_)
        .bind(id)
        .run();
  }

  void retry_later(std::int64_t id, int attempts, std::int64_t next_try_ms,
                   const std::string& error) override {
    std::lock_guard lock(mutex_);
    Statement(db_,
              "UPDATE outbox SET attempts = ?, next_try_ms = ?, last_error = ?, claimed_until = 0 "
              "WHERE id = ?",
              file_)
        .bind(std::int64_t{attempts})
        .bind(next_try_ms)
        .bind(error)
        .bind(id)
        .run();
  }

  std::optional<std::string> line_item(const std::string& issuer, const std::string& client_id,
                                       const std::string& resource_link_id) override {
    std::lock_guard lock(mutex_);
    Statement s(db_,
                "SELECT url FROM line_items WHERE issuer = ? AND client_id = ? AND "
                "resource_link_id = ?",
                file_);
    s.bind(issuer).bind(client_id).bind(resource_link_id);
    if (!s.step()) return std::nullopt;
    return s.text(0);
  }

  void set_line_item(const std::string& issuer, const std::string& client_id,
                     const std::string& resource_link_id, const std::string& url) override {
    std::lock_guard lock(mutex_);
    Statement(db_, "INSERT OR REPLACE INTO line_items VALUES (?, ?, ?, ?)", file_)
        .bind(issuer)
        .bind(client_id)
        .bind(resource_link_id)
        .bind(url)
        .run();
  }

  void set_memberships_url(const std::string& issuer, const std::string& client_id,
                           const std::string& context_id, const std::string& url) override {
    std::lock_guard lock(mutex_);
    Statement(db_,
              "INSERT INTO rosters (issuer, client_id, context_id, memberships_url) "
              "VALUES (?, ?, ?, ?) ON CONFLICT (issuer, client_id, context_id) DO UPDATE SET "
              "memberships_url = excluded.memberships_url",
              file_)
        .bind(issuer)
        .bind(client_id)
        .bind(context_id)
        .bind(url)
        .run();
  }

  Roster roster(const std::string& issuer, const std::string& client_id,
                const std::string& context_id) override {
    std::lock_guard lock(mutex_);
    Roster r;
    Statement s(db_,
                "SELECT memberships_url, read_at FROM rosters WHERE issuer = ? AND "
                "client_id = ? AND context_id = ?",
                file_);
    s.bind(issuer).bind(client_id).bind(context_id);
    if (!s.step()) return r;
    r.memberships_url = s.text(0);
    r.read_at = s.integer(1);
    Statement m(db_,
                "SELECT user_id, name, email, roles, status FROM members WHERE issuer = ? AND "
                "client_id = ? AND context_id = ? ORDER BY position",
                file_);
    m.bind(issuer).bind(client_id).bind(context_id);
    while (m.step()) r.members.push_back({m.text(0), m.text(1), m.text(2), m.text(3), m.text(4)});
    return r;
  }

  void set_members(const std::string& issuer, const std::string& client_id,
                   const std::string& context_id, const std::vector<Member>& members,
                   std::int64_t read_at) override {
    std::lock_guard lock(mutex_);
    Transaction t(*this);
    Statement(db_,
              "INSERT INTO rosters (issuer, client_id, context_id, read_at) VALUES (?, ?, ?, ?) "
              "ON CONFLICT (issuer, client_id, context_id) DO UPDATE SET read_at = "
              "excluded.read_at",
              file_)
        .bind(issuer)
        .bind(client_id)
        .bind(context_id)
        .bind(read_at)
        .run();
    Statement(db_, "DELETE FROM members WHERE issuer = ? AND client_id = ? AND context_id = ?",
              file_)
        .bind(issuer)
        .bind(client_id)
        .bind(context_id)
        .run();
    std::int64_t position = 0;
    for (const auto& m : members) {
      Statement(db_, "INSERT OR IGNORE INTO members VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)", file_)
          .bind(issuer)
          .bind(client_id)
          .bind(context_id)
          .bind(m.user_id)
          .bind(position++)
          .bind(m.name)
          .bind(m.email)
          .bind(m.roles)
          .bind(m.status)
          .run();
    }
    t.commit();
  }

 private:
  // BEGIN IMMEDIATE at construction; ROLLBACK at destruction unless committed.
  class Transaction {
   public:
    explicit Transaction(SqliteStore& s) : s_(s) { s_.exec("BEGIN IMMEDIATE"); }
    ~Transaction() {
      if (!done_) sqlite3_exec(s_.db_, "ROLLBACK", nullptr, nullptr, nullptr);
    }
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    void commit() {
      s_.exec("COMMIT");
      done_ = true;
    }

   private:
    SqliteStore& s_;
    bool done_ = false;
  };

  void exec(const char* sql) {
    char* message = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
      std::string why = message ? message : sqlite3_errmsg(db_);
      sqlite3_free(message);
      throw Error(Diagnostic{file_, "", 0, 0, Severity::kError, "database: " + why, "database"});
    }
  }

  void insert_score(const OutboxRow& o) {
    Statement(db_,
              "INSERT INTO outbox (submission_id, issuer, client_id, lineitem, lineitems, "
              "resource_link_id, label, user_id, score, max_score, timestamp) "
              "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
              file_)
        .bind(o.submission_id)
        .bind(o.issuer)
        .bind(o.client_id)
        .bind(o.lineitem)
        .bind(o.lineitems)
        .bind(o.resource_link_id)
        .bind(o.label)
        .bind(o.user_id)
        .bind(o.score)
        .bind(o.max_score)
        .bind(o.timestamp)
        .run();
  }

  // Brings the schema to the last version, one transaction per version.
  void migrate() {
    exec("CREATE TABLE IF NOT EXISTS schema_version (version INTEGER NOT NULL)");
    std::lock_guard lock(mutex_);
    std::int64_t version = 0;
    {
      Statement s(db_, "SELECT MAX(version) FROM schema_version", file_);
      if (s.step()) version = s.integer(0);
    }
    if (version > kSchemaVersion) {
      throw Error(
          Diagnostic{file_, "", 0, 0, Severity::kError, newer_schema_message(version), "database"});
    }
    for (; version < kSchemaVersion; ++version) {
      Transaction t(*this);
      exec(kMigrations[version]);
      Statement(db_, "INSERT INTO schema_version VALUES (?)", file_).bind(version + 1).run();
      t.commit();
    }
  }

  std::string file_;
  sqlite3* db_ = nullptr;
  std::mutex mutex_;
};

}  // namespace

std::unique_ptr<Store> open_sqlite_store(const std::string& dir) {
  return std::make_unique<SqliteStore>(dir);
}

}  // namespace raygrade::serve
