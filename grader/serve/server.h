// `raygrade serve`: an LTI 1.3 tool over HTTP (docs/lti.md). The library part: it binds,
// serves and stops when told; the command prints and exits.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"

namespace raygrade::serve {

struct ServeOptions {
  std::string data_dir;  // the SQLite database and the tool's key, and scratch files
  // How browsers and platforms reach the tool; empty: http://HOST:PORT of the address bound.
  std::string public_url;
  std::string assignments_dir;         // the assignment files offered
  std::int64_t outbox_base_ms = 1000;  // the first retry of a score; doubled up to 30 s
  // Told one line per request answered (method, path, status, and why for a refusal) and per
  // score that could not be delivered; the caller decides where it goes.
  std::function<void(const std::string&)> log;
  // A PostgreSQL URL (postgresql://…): the database is there, shared with other servers,
  // rather than SQLite in data_dir.
  std::string database;
  std::int64_t outbox_lease_ms = 300000;  // kOutboxLeaseMs (outbox.h): how long a sender
                                          // holds the scores it claimed
};

class LtiServer {
 public:
  // Opens the database (making it and the tool's key at first start) and reads the
  // assignments. Throws Error when the database or the folder cannot be used.
  explicit LtiServer(ServeOptions options);
  ~LtiServer();
  LtiServer(const LtiServer&) = delete;
  LtiServer& operator=(const LtiServer&) = delete;

  // Binds host:port (0: a free port); the port bound. Throws Error when it cannot.
  int bind(const std::string& host, int port);
  // Serves until stop(), delivering scores from the outbox meanwhile.
  void run();
  // Makes run() return (from any thread); the outbox stops as run() returns.
  void stop();
  // The public URL, without a trailing slash (known once bound when none was given).
  const std::string& public_url() const;
  // Assignments left out of the folder, and why.
  const std::vector<Diagnostic>& warnings() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Stores a registration made by hand (`raygrade serve register`).
struct ManualRegistration {
  std::string issuer, client_id, deployment_id, auth_url, token_url, jwks_url;
};
// Stores it in `database` when given (a PostgreSQL URL), else in SQLite in `data_dir`.
void register_platform(const std::string& data_dir, const std::string& database,
                       const ManualRegistration& r);

}  // namespace raygrade::serve
