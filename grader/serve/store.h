// What `raygrade serve` keeps: one interface over the database, with two backends, SQLite (one
// server) and PostgreSQL (several servers sharing one database). Every method is one
// transaction; a method returns only after its transaction is committed. Everything above this
// interface is the same code whichever backend holds the data.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raygrade::serve {

// The version of the schema this raygrade writes: both backends have one migration per version
// (a check in each says so), run in order at opening. A database of a higher version, made by
// a newer raygrade, is refused rather than used.
inline constexpr std::int64_t kSchemaVersion = 3;

// A platform the tool trusts: its issuer and the client_id it gave the tool, its endpoints and
// the deployments registered.
struct Registration {
  std::int64_t id = 0;
  std::string issuer;
  std::string client_id;
  std::string auth_url;
  std::string token_url;
  std::string jwks_url;
  std::vector<std::string> deployments;
};

// A login begun: the state and nonce sent to the platform, and the browser it was sent to.
struct LoginState {
  std::string state;
  std::string browser;  // the raygrade_state cookie of that browser
  std::string nonce;
  std::string issuer;
  std::string client_id;
  std::int64_t expires = 0;  // seconds since 1970 UTC
};

// A launch that passed every check, and the browser session it opened.
struct LaunchRecord {
  std::string launch_id;
  std::string session;  // the raygrade_session cookie
  std::string csrf;
  std::string issuer;
  std::string client_id;
  std::string deployment_id;
  std::string sub;
  std::string name;
  std::string roles;  // JSON array
  bool instructor = false;
  std::string message_type;
  std::string context_id;
  std::string resource_link_id;
  std::string assignment;  // the assignment's file name in the assignments folder
  std::string lineitem;
  std::string lineitems;
  std::string deep_link_return_url;
  std::string deep_link_data;
  std::int64_t expires = 0;
};

struct SubmissionRecord {
  std::int64_t id = 0;
  std::string launch_id;
  std::string issuer;
  std::string client_id;
  std::string sub;
  std::string context_id;
  std::string resource_link_id;
  std::string assignment;
  std::string answers;  // the submission as graded (JSON)
  std::string result;   // the graded submission, every detail (JSON)
  double score = 0;
  double max_score = 0;
  std::int64_t created = 0;
};

// A score to send to a platform's line item.
struct OutboxRow {
  std::int64_t id = 0;
  std::int64_t submission_id = 0;
  std::string issuer;
  std::string client_id;
  std::string lineitem;  // empty: found or made from lineitems and the resource link
  std::string lineitems;
  std::string resource_link_id;
  std::string label;
  std::string user_id;
  double score = 0;
  double max_score = 0;
  std::string timestamp;  // ISO 8601 with milliseconds, Z
  int attempts = 0;
  std::int64_t next_try_ms = 0;
  std::int64_t claimed_until_ms = 0;  // a sender holds it until then (0: nobody)
  bool delivered = false;
  std::string last_error;
};

// A member of a course as the platform's roster (Names and Role Provisioning Services 2.0) gives
// it: the platform's user_id (a launch's sub), and what the platform chose to share.
struct Member {
  std::string user_id;
  std::string name;
  std::string email;
  std::string roles;   // JSON array of the role URIs
  std::string status;  // Active, Inactive or Deleted
};

// A course's class list: where the platform serves it, and the members last read.
struct Roster {
  std::string memberships_url;  // the launches' context_memberships_url ("" none given)
  std::int64_t read_at = 0;     // seconds since 1970 UTC of the last read (0: never)
  std::vector<Member> members;  // in the platform's order
};

class Store {
 public:
  virtual ~Store() = default;

  // Adds the registration, or the deployment to the registration of the same issuer and client.
  virtual std::int64_t add_registration(const Registration& r) = 0;
  virtual std::optional<Registration> find_registration(const std::string& issuer,
                                                        const std::string& client_id) = 0;
  virtual std::vector<Registration> registrations(const std::string& issuer) = 0;

  // The tool's signing key: kid and PKCS#8 PEM. set_tool_key keeps the first one stored.
  virtual std::optional<std::pair<std::string, std::string>> tool_key() = 0;
  virtual void set_tool_key(const std::string& kid, const std::string& pem) = 0;

  virtual void add_login_state(const LoginState& s) = 0;
  // A state not yet used whose time has not run out.
  virtual std::optional<LoginState> find_login_state(const std::string& state,
                                                     std::int64_t now) = 0;
  // Uses the state (once only) and stores the launch, in one transaction; false, storing
  // nothing, when the state was used already.
  virtual bool complete_launch(const std::string& state, const LaunchRecord& launch) = 0;
  virtual std::optional<LaunchRecord> find_launch(const std::string& launch_id) = 0;

  // Stores the submission and its score to send (when there is a line item), in one
  // transaction; the submission's id.
  virtual std::int64_t add_submission(const SubmissionRecord& s,
                                      const std::optional<OutboxRow>& score) = 0;
  // Every submission to the assignment in that resource link, oldest first.
  virtual std::vector<SubmissionRecord> submissions(const std::string& issuer,
                                                    const std::string& client_id,
                                                    const std::string& resource_link_id,
                                                    const std::string& assignment) = 0;

  // Claims up to `limit` scores not delivered whose next try is due and that no sender holds
  // (or whose sender's claim ran out), oldest first: each is held until now_ms + lease_ms, so
  // that no other process sends it meanwhile. A process killed while holding scores leaves
  // them to another once the lease has run out.
  virtual std::vector<OutboxRow> claim_scores(std::int64_t now_ms, std::int64_t lease_ms,
                                              int limit) = 0;
  // Gives back a claimed score not tried (the sender is stopping).
  virtual void release_claim(std::int64_t id) = 0;
  virtual void mark_delivered(std::int64_t id) = 0;
  virtual void retry_later(std::int64_t id, int attempts, std::int64_t next_try_ms,
                           const std::string& error) = 0;
  virtual std::vector<OutboxRow> outbox() = 0;
  virtual void add_score(const OutboxRow& score) = 0;

  // The line item found or made for a resource link.
  virtual std::optional<std::string> line_item(const std::string& issuer,
                                               const std::string& client_id,
                                               const std::string& resource_link_id) = 0;
  virtual void set_line_item(const std::string& issuer, const std::string& client_id,
                             const std::string& resource_link_id, const std::string& url) = 0;

  // A course (context) of a platform's client: where its roster is served, as the last launch
  // said; the members last read and when.
  virtual void set_memberships_url(const std::string& issuer, const std::string& client_id,
                                   const std::string& context_id, const std::string& url) = 0;
  virtual Roster roster(const std::string& issuer, const std::string& client_id,
                        const std::string& context_id) = 0;
  // Replaces the course's members with those read at `read_at`, in one transaction (a
  // user_id given twice is kept once, the first).
  virtual void set_members(const std::string& issuer, const std::string& client_id,
                           const std::string& context_id, const std::vector<Member>& members,
                           std::int64_t read_at) = 0;
};

// The SQLite database DIR/raygrade.sqlite (made when missing): WAL, synchronous=FULL, the schema
// brought to the current version at opening. Safe to use from several threads.
std::unique_ptr<Store> open_sqlite_store(const std::string& dir);

// The PostgreSQL database at `url` (postgresql://… or postgres://…, libpq's connection URI),
// brought to the current schema version at opening (one process at a time: an advisory lock).
// A small pool of connections; safe to use from several threads and several processes.
std::unique_ptr<Store> open_postgres_store(const std::string& url);

// True for a URL open_postgres_store takes.
bool is_postgres_url(const std::string& database);

// `database` when it is given (a PostgreSQL URL), else SQLite in `dir`. Throws Error for a
// database that is neither.
std::unique_ptr<Store> open_store(const std::string& database, const std::string& dir);

// The URL without its password, to be shown or logged.
std::string redacted_url(const std::string& url);

// Why a database of schema `version` (> kSchemaVersion) is refused, and what to do.
std::string newer_schema_message(std::int64_t version);

}  // namespace raygrade::serve
